/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "idealGas.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gasDensityModels
{
    defineTypeNameAndDebug(idealGas, 0);
    addToRunTimeSelectionTable(gasDensityModel, idealGas, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField>
Foam::gasDensityModels::idealGas::heatDensity
(
    const volScalarField& rho2,
    const volScalarField&
) const
{
    return tmp<volScalarField>::New("rho2Heat", rho2);
}


Foam::tmp<Foam::volScalarField>
Foam::gasDensityModels::idealGas::gravityDensity
(
    const volScalarField& alpha2,
    const volScalarField&,
    const volScalarField&,
    const volScalarField& rho2,
    const scalar
) const
{
    return alpha2*rho2;
}


// ************************************************************************* //
