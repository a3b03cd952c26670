/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "laserAbsorptionModel.H"
#include "checkedInput.H"
#include <complex>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(laserAbsorptionModel, 0);
    defineRunTimeSelectionTable(laserAbsorptionModel, dictionary);
}

// Half metal: the cell holds the metal surface (the alpha = 0.5 contour)
const Foam::scalar Foam::laserAbsorptionModel::surfaceFraction = 0.5;

const Foam::wordList Foam::laserAbsorptionModel::keys
({
    "absorptionModel", "absorptivity", "fresnel",
    "gaussianSurfaceCoeffs", "beerLambertCoeffs", "monteCarloCoeffs"
});


namespace
{

// Largest refractive index and extinction coefficient accepted (metals in
// the infrared reach a few tens)
const Foam::scalar maxRefractiveIndex = 100;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserAbsorptionModel::laserAbsorptionModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    dict_(dict),
    coeffs_(dict.subOrEmptyDict(modelType + "Coeffs")),
    fresnel_(false),
    nRefraction_(1),
    kExtinction_(0)
{
    laserAbsorptionModel::read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserAbsorptionModel::read(const dictionary& dict)
{
    using ldna::interval;

    dict_ = dict;
    coeffs_ = dict.subOrEmptyDict(dict.get<word>("absorptionModel") + "Coeffs");

    fresnel_ = dict.found("fresnel");
    if (fresnel_)
    {
        const dictionary& fresnelDict = dict.subDict("fresnel");
        ldna::checkKeys(fresnelDict, {"n", "k"});
        nRefraction_ = ldna::getChecked<scalar>
        (
            fresnelDict, "n", interval::openClosed(0, maxRefractiveIndex)
        );
        kExtinction_ = ldna::getChecked<scalar>
        (
            fresnelDict, "k", interval::closed(0, maxRefractiveIndex)
        );
    }

    absorptivity_.clear();
    if (!fresnel_)
    {
        absorptivity_ = Function1<scalar>::New("absorptivity", dict);
    }
    else if (dict.found("absorptivity"))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'absorptivity' and 'fresnel' in " << dict.name()
            << ": give one of them" << exit(FatalIOError);
    }
}


Foam::scalar Foam::laserAbsorptionModel::fresnelAbsorptivity
(
    const scalar cosTheta,
    const scalar n,
    const scalar k
)
{
    typedef std::complex<scalar> complexScalar;

    const scalar c = min(max(cosTheta, scalar(0)), scalar(1));
    const complexScalar N2 = complexScalar(n, k)*complexScalar(n, k);
    const complexScalar root = std::sqrt(N2 - complexScalar(1 - c*c, 0));

    const scalar rs = std::norm((c - root)/(c + root));
    const scalar rp = std::norm((N2*c - root)/(N2*c + root));

    return 1 - 0.5*(rs + rp);
}


Foam::scalar Foam::laserAbsorptionModel::absorptivity
(
    const laserRay::trackingData& td,
    const label celli,
    const vector& d,
    const vector& n
) const
{
    if (fresnel_)
    {
        return fresnelAbsorptivity(mag(d & n), nRefraction_, kExtinction_);
    }

    const scalar a = absorptivity_->value(td.T[celli]);
    // The message is built only for a value out of range: this runs at every
    // cell a ray crosses in metal, and formatting the temperature each time
    // cost more than the ray's absorption
    const ldna::interval allowed(ldna::interval::closed(0, 1));
    if (!allowed.contains(a))
    {
        ldna::checkValue
        (
            dict_, "absorptivity", a, allowed,
            "at T = " + Foam::name(td.T[celli]) + " K"
        );
    }
    return a;
}


// ************************************************************************* //
