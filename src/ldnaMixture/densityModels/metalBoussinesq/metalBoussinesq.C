/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalBoussinesq.H"
#include "checkedInput.H"
#include "physicalLimits.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace metalDensityModels
{
    defineTypeNameAndDebug(Boussinesq, 0);
    addToRunTimeSelectionTable(metalDensityModel, Boussinesq, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalDensityModels::Boussinesq::Boussinesq(const dictionary& metalDict)
:
    referenceDensity_
    (
        "referenceDensity",
        dimDensity,
        ldna::getChecked<scalar>
        (
            metalDict, "referenceDensity",
            ldna::interval::open(0, ldna::limits::density)
        )
    )
{
    Info<< ", referenceDensity " << referenceDensity_.value()
        << " kg/m3 for mass and inertia";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::metalDensityModels::Boussinesq::massDensity
(
    const scalar
) const
{
    return referenceDensity_.value();
}


// ************************************************************************* //
