/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "variableDensity.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace metalDensityModels
{
    defineTypeNameAndDebug(variable, 0);
    addToRunTimeSelectionTable(metalDensityModel, variable, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::metalDensityModels::variable::correct
(
    const volScalarField& rhoGravity,
    volScalarField& rho1
) const
{
    rho1 = rhoGravity;
}


// ************************************************************************* //
