/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "meltingRange.H"
#include "checkedInput.H"
#include "physicalLimits.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meltingRange::meltingRange(const dictionary& dict)
:
    Tsolidus_
    (
        ldna::getChecked<scalar>
        (
            dict, "solidus", ldna::interval::open(0, ldna::limits::temperature)
        )
    ),
    Tliquidus_(dict.get<scalar>("liquidus")),
    latentHeat_
    (
        ldna::getChecked<scalar>
        (
            dict, "latentHeat",
            ldna::interval::closed(0, ldna::limits::latentHeat)
        )
    )
{
    ldna::checkValue
    (
        dict, "liquidus", Tliquidus_,
        ldna::interval::open(Tsolidus_, ldna::limits::temperature),
        "above the solidus: the latent heat is released over the mushy range"
    );
}


// ************************************************************************* //
