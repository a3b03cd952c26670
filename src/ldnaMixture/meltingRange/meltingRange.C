/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meltingRange::equilibrate
(
    const scalar H,
    const scalar C,
    const scalar m,
    scalar& T,
    scalar& gl
) const
{
    const scalar Ts = Tsolidus_;
    const scalar Tl = Tliquidus_;
    const scalar dTm = Tl - Ts;
    const scalar L = latentHeat_;

    if (H <= C*Ts)
    {
        gl = 0;
        T = H/C;
    }
    else if (H >= C*Tl + m*L)
    {
        gl = 1;
        T = (H - m*L)/C;
    }
    else
    {
        T = (H + m*L*Ts/dTm)/(C + m*L/dTm);
        gl = (T - Ts)/dTm;
    }
}


// ************************************************************************* //
