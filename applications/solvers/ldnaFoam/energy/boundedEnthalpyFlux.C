/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "boundedEnthalpyFlux.H"
#include "convectionScheme.H"
#include "surfaceInterpolate.H"
#include "fvcSurfaceIntegrate.H"
#include "localMax.H"
#include "localMin.H"
#include "upwind.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * * //

namespace
{

// Explicit TVD schemes whose limiter reaches 2 (vanLeer, MUSCL) are bounded
// up to a Courant number of 1/2 (Sweby, SIAM J. Numer. Anal. 21 (1984) 995)
const Foam::scalar maxCorrectionCourant = 0.5;

// Cells at least this much metal are the pool and the substrate, where
// upwind's diffusion competes with conduction.  Thinner metal is the
// interface band, one or two cells wide, which drains and fills from step
// to step: there a face enthalpy other than the draining cell's own leaves
// the cell's remaining heat on its remaining trace of metal (a cell of
// metal fraction 1e-3 under the laser at five times its power went to
// 3649 K, 400 K above its upwind value), so those faces stay upwind
const Foam::scalar bulkMetalFraction = 0.5;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boundedEnthalpyFlux::boundedEnthalpyFlux
(
    const metalGasMixture& mixture,
    const volScalarField& alpha1,
    const surfaceScalarField& rhoPhi1,
    const surfaceScalarField& rhoPhi2,
    const scalarField& metalEnthalpyMass,
    const scalarField& gasEnthalpyMass
)
:
    mesh_(alpha1.mesh()),
    Cp1_(mixture.Cp1()),
    Cp2_(mixture.Cp2()),
    correctionWeight_
    (
        IOobject("correctionWeight", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless, Zero)
    )
{
    volScalarField heatCourant
    (
        IOobject("heatCourant", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
    heatCourant.primitiveFieldRef() =
        0.5*mesh_.time().deltaTValue()
       *fvc::surfaceSum
        (
            mag(rhoPhi1)*fvc::interpolate(Cp1_)
          + mag(rhoPhi2)*fvc::interpolate(Cp2_)
        )().primitiveField()
       /mesh_.V()
       /(
            metalEnthalpyMass*Cp1_.primitiveField()
          + gasEnthalpyMass*Cp2_.primitiveField()
        );
    heatCourant.correctBoundaryConditions();

    // All of the correction where both cells allow it, less where either
    // does not, none outside the bulk metal
    correctionWeight_ =
        pos0(localMin<scalar>(mesh_).interpolate(alpha1) - bulkMetalFraction)
       *min
        (
            scalar(1),
            maxCorrectionCourant
           /max
            (
                localMax<scalar>(mesh_).interpolate(heatCourant),
                dimensionedScalar
                (
                    "maxCorrectionCourant", dimless, maxCorrectionCourant
                )
            )
        );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField> Foam::boundedEnthalpyFlux::flux
(
    const surfaceScalarField& massFlux,
    const volScalarField& h,
    const word& schemeName
) const
{
    const surfaceScalarField hUpwind
    (
        upwind<scalar>(mesh_, massFlux).interpolate(h)
    );
    const surfaceScalarField hScheme
    (
        fv::convectionScheme<scalar>::New
        (
            mesh_,
            massFlux,
            mesh_.divScheme(schemeName)
        )().interpolate(massFlux, h)
    );
    return tmp<surfaceScalarField>
    (
        new surfaceScalarField
        (
            "enthalpyFlux",
            massFlux*(hUpwind + correctionWeight_*(hScheme - hUpwind))
        )
    );
}

// ************************************************************************* //
