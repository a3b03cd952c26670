/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "pixelAbsorptionModel.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace
{

// Pixels across the beam diameter: 64 over 4 beam radii resolve the
// Gaussian on cells down to a sixteenth of the radius
const Foam::label defaultRaysAcross = 64;
const Foam::label maxRaysAcross = 1024;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserAbsorptionModels::pixelAbsorptionModel::pixelAbsorptionModel
(
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    laserAbsorptionModel(modelType, dict, mesh),
    nRaysAcross_(defaultRaysAcross)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::laserAbsorptionModels::pixelAbsorptionModel::readRaysAcross()
{
    nRaysAcross_ = ldna::getCheckedOrDefault<label>
    (
        coeffs_, "nRaysAcross", ldna::interval::closed(2, maxRaysAcross),
        defaultRaysAcross
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserAbsorptionModels::pixelAbsorptionModel::rays
(
    const laserBeam& beam,
    const label,
    DynamicList<vector2D>& across,
    DynamicList<scalar>& shares
) const
{
    beam.pixels(nRaysAcross_, across, shares);
}


// ************************************************************************* //
