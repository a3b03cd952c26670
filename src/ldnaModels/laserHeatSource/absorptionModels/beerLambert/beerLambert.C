/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "beerLambert.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace laserAbsorptionModels
{
    defineTypeNameAndDebug(beerLambert, 0);
    addToRunTimeSelectionTable(laserAbsorptionModel, beerLambert, dictionary);
}
}


namespace
{

// Attenuation of the paper: Tr = exp(-4) over l = 1 mm (eq. 10-11)
const Foam::scalar defaultTransmittance = Foam::exp(-4.0);
const Foam::scalar defaultPathLength = 1e-3;
const Foam::scalar maxPathLength = 1;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserAbsorptionModels::beerLambert::beerLambert
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    pixelAbsorptionModel(typeName, dict, mesh),
    mu_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserAbsorptionModels::beerLambert::read(const dictionary& dict)
{
    using ldna::interval;

    laserAbsorptionModel::read(dict);
    ldna::checkKeys(coeffs_, {"transmittance", "pathLength", "nRaysAcross"});

    const scalar transmittance = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "transmittance", interval::open(0, 1), defaultTransmittance
    );
    const scalar pathLength = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "pathLength", interval::openClosed(0, maxPathLength),
        defaultPathLength
    );
    mu_ = -Foam::log(transmittance)/pathLength;
    ldna::checkValue
    (
        coeffs_, "transmittance", mu_, interval::open(0, GREAT),
        "the attenuation coefficient -ln(Tr)/l it gives"
    );

    readRaysAcross();

    Info<< "    attenuation coefficient " << mu_ << " 1/m" << endl;
}


void Foam::laserAbsorptionModels::beerLambert::cross
(
    laserRay& ray,
    laserRay::trackingData& td,
    const label celli,
    const scalar ds
) const
{
    const scalar opticalDepth = mu_*max(td.alpha[celli], scalar(0))*ds;
    if (!(opticalDepth > 0) || !(ray.power() > 0))
    {
        return;
    }

    const scalar lost = ray.power()*(1 - exp(-opticalDepth));
    const scalar a =
        absorptivity(td, celli, ray.direction(), ray.surfaceNormal(td, celli));
    ray.absorb(td, celli, a*lost);
    ray.reflectOut(td, (1 - a)*lost);
}


// ************************************************************************* //
