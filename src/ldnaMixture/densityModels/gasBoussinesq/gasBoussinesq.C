/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "gasBoussinesq.H"
#include "checkedInput.H"
#include "physicalLimits.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace gasDensityModels
{
    defineTypeNameAndDebug(Boussinesq, 0);
    addToRunTimeSelectionTable(gasDensityModel, Boussinesq, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasDensityModels::Boussinesq::Boussinesq(const dictionary& gasDict)
:
    referenceTemperature_
    (
        "referenceTemperature",
        dimTemperature,
        ldna::getChecked<scalar>
        (
            gasDict, "referenceTemperature",
            ldna::interval::open(0, ldna::limits::temperature)
        )
    )
{
    Info<< ", referenceTemperature " << referenceTemperature_.value()
        << " K for mass and inertia";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField>
Foam::gasDensityModels::Boussinesq::heatDensity
(
    const volScalarField& rho2,
    const volScalarField& T
) const
{
    return rho2*referenceTemperature_/T;
}


Foam::tmp<Foam::volScalarField>
Foam::gasDensityModels::Boussinesq::gravityDensity
(
    const volScalarField& alpha2,
    const volScalarField& p,
    const volScalarField& T,
    const volScalarField&,
    const scalar R
) const
{
    const dimensionedScalar gasConstant
    (
        "R", dimVelocity*dimVelocity/dimTemperature, R
    );
    return alpha2*p/(gasConstant*T);
}


// ************************************************************************* //
