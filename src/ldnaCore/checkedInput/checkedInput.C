/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "checkedInput.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * * * IOstream Operators * * * * * * * * * * * //

Foam::Ostream& Foam::ldna::operator<<(Ostream& os, const interval& range)
{
    os  << (range.lowClosed_ ? "[" : "(") << range.low_ << ", "
        << range.high_ << (range.highClosed_ ? "]" : ")");
    return os;
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::ldna::checkValue
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const interval& range,
    const string& what
)
{
    if (!range.contains(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name()
            << (what.empty() ? "" : " (") << what.c_str()
            << (what.empty() ? "" : ")")
            << " is " << value << ": it must lie in " << range
            << exit(FatalIOError);
    }
}


Foam::vector Foam::ldna::getDirection
(
    const dictionary& dict,
    const word& key,
    const vector* deflt
)
{
    const vector v =
        (deflt && !dict.found(key)) ? *deflt : dict.get<vector>(key);

    // Components up to this size keep |v|^2 finite.  Each is checked:
    // a maximum over the components would pass a NaN next to a number
    const scalar largestComponent = 1e100;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        checkValue
        (
            dict, key, mag(v[i]), interval::closedOpen(0, largestComponent),
            "the magnitude of component " + Foam::name(i) + " of a direction"
        );
    }
    checkValue
    (
        dict, key, mag(v), interval::open(VSMALL, GREAT),
        "its length: a non-zero direction"
    );
    return v/mag(v);
}


Foam::label Foam::ldna::editDistance(const word& a, const word& b)
{
    labelList previous(b.size() + 1);
    labelList current(b.size() + 1);
    forAll(previous, j)
    {
        previous[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const label substitution =
                previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] =
                min(min(previous[j] + 1, current[j - 1] + 1), substitution);
        }
        previous = current;
    }
    return previous[b.size()];
}


void Foam::ldna::badChoice
(
    const dictionary& dict,
    const word& key,
    const word& value,
    const wordList& allowed
)
{
    FatalIOErrorInFunction(dict)
        << "Entry '" << key << "' in " << dict.name() << " is " << value
        << ": it must be one of (";
    forAll(allowed, i)
    {
        FatalIOError << (i ? " " : "") << allowed[i];
    }
    FatalIOError << ")" << exit(FatalIOError);
}


void Foam::ldna::checkKeys(const dictionary& dict, const wordList& known)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (key.empty() || key[0] == '#' || known.found(key))
        {
            continue;
        }

        label nearest = -1;
        label distance = labelMax;
        forAll(known, i)
        {
            const label d = editDistance(key, known[i]);
            if (d < distance)
            {
                distance = d;
                nearest = i;
            }
        }

        FatalIOErrorInFunction(dict)
            << "Unknown entry '" << key << "' in " << dict.name();
        if (nearest >= 0)
        {
            FatalIOError << ": did you mean '" << known[nearest] << "'?";
        }
        FatalIOError
            << nl << "Known entries: " << flatOutput(known)
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
