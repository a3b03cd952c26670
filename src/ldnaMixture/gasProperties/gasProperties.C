/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "gasProperties.H"
#include "checkedInput.H"
#include "physicalLimits.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasProperties::gasProperties
(
    const dictionary& dict,
    const scalar Tmin,
    const scalar Tmax,
    const scalar Tref
)
:
    R_
    (
        ldna::getChecked<scalar>
        (
            dict, "R", ldna::interval::open(0, ldna::limits::gasConstant)
        )
    ),
    Tref_(Tref),
    Cp_
    (
        temperatureTable::New
        (
            dict, "Cp", Tmin, Tmax, ldna::limits::specificHeat, true
        )
    ),
    kappa_
    (
        temperatureTable::New
        (
            dict, "kappa", Tmin, Tmax, ldna::limits::conductivity
        )
    ),
    mu_
    (
        temperatureTable::New(dict, "mu", Tmin, Tmax, ldna::limits::viscosity)
    )
{}


// ************************************************************************* //
