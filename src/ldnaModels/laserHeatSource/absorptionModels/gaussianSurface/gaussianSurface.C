/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "gaussianSurface.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace laserAbsorptionModels
{
    defineTypeNameAndDebug(gaussianSurface, 0);
    addToRunTimeSelectionTable
    (
        laserAbsorptionModel,
        gaussianSurface,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserAbsorptionModels::gaussianSurface::gaussianSurface
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    pixelAbsorptionModel(modelType, dict, mesh)
{}


Foam::laserAbsorptionModels::gaussianSurface::gaussianSurface
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    gaussianSurface(typeName, dict, mesh)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserAbsorptionModels::gaussianSurface::read
(
    const dictionary& dict
)
{
    laserAbsorptionModel::read(dict);
    ldna::checkKeys(coeffs_, {"nRaysAcross"});
    readRaysAcross();
}


Foam::scalar
Foam::laserAbsorptionModels::gaussianSurface::interactionDistance
(
    const laserRay& ray,
    const laserRay::trackingData& td,
    const label celli
) const
{
    return
        td.alpha[celli] >= surfaceFraction && !ray.justReflected(celli)
      ? 0
      : GREAT;
}


Foam::vector Foam::laserAbsorptionModels::gaussianSurface::absorbAtSurface
(
    laserRay& ray,
    laserRay::trackingData& td,
    const label celli
) const
{
    const vector n = ray.surfaceNormal(td, celli);
    const scalar a = absorptivity(td, celli, ray.direction(), n);
    ray.absorb(td, celli, a*ray.power());
    return n;
}


void Foam::laserAbsorptionModels::gaussianSurface::interact
(
    laserRay& ray,
    laserRay::trackingData& td,
    const label celli
) const
{
    absorbAtSurface(ray, td, celli);
    ray.stop(td, true);
}


// ************************************************************************* //
