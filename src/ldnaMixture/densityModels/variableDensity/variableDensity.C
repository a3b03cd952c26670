/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
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

Foam::scalar Foam::metalDensityModels::variable::massDensity
(
    const scalar rhoGravity
) const
{
    return rhoGravity;
}


// ************************************************************************* //
