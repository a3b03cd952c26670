/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "temperatureTable.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::scalar Foam::temperatureTable::maxRelativeError = 1e-9;

const Foam::scalar Foam::temperatureTable::initialSpacing = 1;

const Foam::label Foam::temperatureTable::maxPoints = 1 << 20;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::temperatureTable::temperatureTable
(
    autoPtr<Function1<scalar>>&& f,
    const scalar Tlow,
    const scalar Thigh,
    const bool withIntegral
)
:
    function_(std::move(f)),
    Tlow_(Tlow),
    Thigh_(Thigh),
    dT_(0),
    rdT_(0)
{
    const Function1<scalar>& fn = *function_;
    const scalar range = Thigh - Tlow;
    if (!(range > 0))
    {
        return;
    }

    label nIntervals = max(label(1), label(std::ceil(range/initialSpacing)));
    while (nIntervals < maxPoints)
    {
        const scalar dT = range/nIntervals;
        scalarList values(nIntervals + 1);
        scalar magMax = 0;
        forAll(values, i)
        {
            values[i] = fn.value(Tlow + i*dT);
            magMax = max(magMax, mag(values[i]));
        }

        scalar maxError = 0;
        for (label i = 0; i < nIntervals; ++i)
        {
            const scalar midpoint = fn.value(Tlow + (i + 0.5)*dT);
            maxError =
                max(maxError, mag(midpoint - 0.5*(values[i] + values[i + 1])));
        }

        if (maxError <= maxRelativeError*magMax)
        {
            dT_ = dT;
            rdT_ = 1/dT;
            if (withIntegral)
            {
                integrals_.setSize(values.size());
                forAll(integrals_, i)
                {
                    integrals_[i] = fn.integrate(Tlow, Tlow + i*dT);
                }
            }
            values_.transfer(values);
            return;
        }
        nIntervals *= 2;
    }
    // Not representable within the tolerance: evaluated directly
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::temperatureTable> Foam::temperatureTable::New
(
    const dictionary& dict,
    const word& entryName,
    const scalar Tlow,
    const scalar Thigh,
    const scalar maxValue,
    const bool withIntegral
)
{
    autoPtr<Function1<scalar>> f(Function1<scalar>::New(entryName, dict));

    // Sample the range finely enough to catch a sign change of a
    // low-order polynomial or a table entry
    const label nSamples = 200;
    for (label i = 0; i <= nSamples; ++i)
    {
        const scalar T = Tlow + (Thigh - Tlow)*i/nSamples;
        ldna::checkValue
        (
            dict, entryName, f->value(T),
            ldna::interval::open(0, maxValue),
            "at T = " + Foam::name(T) + " K of [" + Foam::name(Tlow) + ", "
          + Foam::name(Thigh) + "] K"
        );
    }

    return autoPtr<temperatureTable>::New
    (
        std::move(f), Tlow, Thigh, withIntegral
    );
}


// ************************************************************************* //
