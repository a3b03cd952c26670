/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalGasMixture.H"
#include "checkedInput.H"
#include "physicalLimits.H"
#include "layeredConductivity.H"
#include "fvc.H"
#include "upwind.H"
#include "gaussConvectionScheme.H"
#include "fvm.H"
#include "fvMatrices.H"


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

const Foam::volScalarField& Foam::metalGasMixture::fillerFraction() const
{
    if (!fillerFraction_.valid())
    {
        FatalErrorInFunction
            << "The filler fraction exists with two metals only (dictionary "
            << substrateName << " in " << objectPath() << ")"
            << exit(FatalError);
    }
    return *fillerFraction_;
}


Foam::volScalarField& Foam::metalGasMixture::fillerFraction()
{
    return const_cast<volScalarField&>
    (
        static_cast<const metalGasMixture&>(*this).fillerFraction()
    );
}


Foam::scalar Foam::metalGasMixture::fillerVolume() const
{
    if (!fillerFraction_.valid())
    {
        return 0;
    }
    return gSum
    (
        (alpha1().primitiveField()*fillerFraction_->primitiveField())
       *alpha1().mesh().V().field()
    );
}


Foam::scalar Foam::metalGasMixture::transportFiller
(
    const surfaceScalarField& alphaPhi1,
    const volScalarField::Internal& fillerSource
)
{
    if (!fillerFraction_.valid())
    {
        return 0;
    }

    const fvMesh& mesh = alpha1().mesh();
    const dimensionedScalar rDeltaT(1/mesh.time().deltaT());
    volScalarField& c = *fillerFraction_;
    const volScalarField& alpha10 = alpha1().oldTime();

    // Every change of the cell's metal that neither the flux nor the
    // sources make keeps its composition (the dilatation terms, a sink)
    const volScalarField::Internal rest
    (
        "fillerRest",
        rDeltaT*(alpha1()() - alpha10())
      + fvc::div(alphaPhi1)()()
      - fillerSource
    );

    // Implicit upwind, as the metal fraction's predictor: the filler volume
    // alpha1 c changes by the metal flux times the donor's c (the inflow
    // boundary's where metal enters), the sources add filler and the rest
    // acts at the new c.  Its diagonal, alpha10/dt + inflow + source, holds
    // every row's off-diagonals (the inflow): c stays within its old values,
    // its neighbours' and the sources' 1.  A weight of 1e-12 of a full cell
    // towards the old value keeps empty cells (no metal, no inflow) defined
    const scalar emptyWeight = 1e-12;
    fv::gaussConvectionScheme<scalar> upwindConvection
    (
        mesh,
        alphaPhi1,
        tmp<surfaceInterpolationScheme<scalar>>
        (
            new upwind<scalar>(mesh, alphaPhi1)
        )
    );
    fvScalarMatrix fillerEqn
    (
        fvm::Sp(rDeltaT*(alpha1()() + emptyWeight), c)
      - rDeltaT*(alpha10() + emptyWeight)*c.oldTime()()
      + upwindConvection.fvmDiv(alphaPhi1, c)
      - fvm::Sp(rest, c)
     ==
        fillerSource
    );
    fillerEqn.solve();

    // Outside [0, 1] only by the solver's residual: clipped, and the filler
    // volume that adds reported
    const scalarField& a = alpha1().primitiveField();
    const scalarField& V = mesh.V().field();
    scalarField& cc = c.primitiveFieldRef();
    scalar clipped = 0;
    forAll(cc, celli)
    {
        const scalar cNew = min(max(cc[celli], scalar(0)), scalar(1));
        clipped += (cNew - cc[celli])*a[celli]*V[celli];
        cc[celli] = cNew;
    }
    c.correctBoundaryConditions();

    return returnReduce(clipped, sumOp<scalar>());
}


Foam::scalar Foam::metalGasMixture::addFiller
(
    const label celli,
    const scalar dAlpha,
    const scalar h,
    const scalar Tin
)
{
    volScalarField& alpha = alpha1();
    const scalar a = alpha[celli];
    const scalar aNew = a + dAlpha;
    const scalar T0 = T_[celli];
    const scalar gl0 = liquidFraction_[celli];
    const scalar c0 = fillerFractionAt(celli);
    const scalar r1 = rho1_[celli];
    const scalar r2 = rho2_[celli];

    // The filler's density at the cell's state (with one metal, rho1)
    const scalar rFiller = metals_->massDensity(T0, gl0, 1);

    // Filler fraction and metal density after the addition
    scalar c = c0;
    scalar r1New = r1;
    if (fillerFraction_.valid())
    {
        c = (a*c0 + dAlpha)/aNew;
        r1New = (a*r1 + dAlpha*rFiller)/aNew;
    }
    const meltingRange range0(metals_->range(c0));
    const meltingRange range(metals_->range(c));

    const scalar E =
        a*r1*(metals_->sensibleEnthalpy(T0, c0) + gl0*range0.latentHeat())
      + (1 - a - dAlpha)*r2*gas_->sensibleEnthalpy(T0)
      + dAlpha*rFiller*h;

    // The temperature of that enthalpy (monotonic in T), by bisection
    // between the cell's and the added metal's temperatures
    auto enthalpyAt = [&](const scalar Tc)
    {
        return
            aNew*r1New
           *(
                metals_->sensibleEnthalpy(Tc, c)
              + range.equilibriumLiquidFraction(Tc)*range.latentHeat()
            )
          + (1 - aNew)*r2*gas_->sensibleEnthalpy(Tc);
    };
    scalar Tlow = min(T0, Tin) - 1;
    scalar Thigh = max(T0, Tin) + 1;
    while (enthalpyAt(Tlow) > E && Tlow > 1)
    {
        Tlow *= 0.5;
    }
    while (enthalpyAt(Thigh) < E && Thigh < ldna::limits::temperature)
    {
        Thigh *= 2;
    }
    const label bisections = 60;
    for (label iter = 0; iter < bisections; ++iter)
    {
        const scalar Tmid = 0.5*(Tlow + Thigh);
        (enthalpyAt(Tmid) < E ? Tlow : Thigh) = Tmid;
    }
    T_[celli] = 0.5*(Tlow + Thigh);
    liquidFraction_[celli] = range.equilibriumLiquidFraction(T_[celli]);
    alpha[celli] = aNew;
    if (fillerFraction_.valid())
    {
        fillerFraction_()[celli] = c;
    }

    return rFiller;
}


// ************************************************************************* //
