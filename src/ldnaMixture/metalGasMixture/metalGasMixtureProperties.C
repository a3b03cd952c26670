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

Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::sigma() const
{
    return sigmaModel_->sigma();
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::h1() const
{
    return evaluate
    (
        "h1",
        dimEnergy/dimMass,
        [&](scalar T, scalar gl, scalar c)
        {
            return
                metals_->sensibleEnthalpy(T, c)
              + gl*metals_->range(c).latentHeat();
        }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::h2() const
{
    return evaluate
    (
        "h2",
        dimEnergy/dimMass,
        [&](scalar T, scalar, scalar) { return gas_->sensibleEnthalpy(T); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::kappa1() const
{
    return evaluate
    (
        "kappa1",
        kappa_.dimensions(),
        [&](scalar T, scalar gl, scalar c)
        {
            return metals_->conductivity(T, gl, c);
        }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::kappa2() const
{
    return evaluate
    (
        "kappa2",
        kappa_.dimensions(),
        [&](scalar T, scalar, scalar) { return gas_->conductivity(T); }
    );
}


Foam::tmp<Foam::surfaceScalarField> Foam::metalGasMixture::kappaf() const
{
    const volScalarField metal(max(min(alpha1(), scalar(1)), scalar(0)));
    const volScalarField metalHeat(metal*rho1_*Cp1());
    return layeredConductivity::faceConductivity
    (
        metal,
        metalHeat/(metalHeat + (1 - metal)*rho2Heat()*Cp2()),
        kappa1(),
        kappa2(),
        kappa_
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::Cp1() const
{
    return evaluate
    (
        "Cp1",
        dimEnergy/dimMass/dimTemperature,
        [&](scalar T, scalar, scalar c) { return metals_->Cp(T, c); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::Cp2() const
{
    return evaluate
    (
        "Cp2",
        dimEnergy/dimMass/dimTemperature,
        [&](scalar T, scalar, scalar) { return gas_->Cp(T); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rho2Heat() const
{
    return gasDensity_->heatDensity(rho2_, T_);
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rho() const
{
    return alpha1()*rho1_ + alpha2()*rho2_;
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rhoGravity() const
{
    return
        alpha1()*rho1Gravity_
      + gasDensity_->gravityDensity(alpha2(), p_, T_, rho2_, gas_->R());
}


Foam::tmp<Foam::volScalarField>
Foam::metalGasMixture::volumetricEnthalpy() const
{
    return alpha1()*rho1_*h1() + alpha2()*rho2Heat()*h2();
}


Foam::tmp<Foam::volScalarField>
Foam::metalGasMixture::metalMassDensity() const
{
    return alpha1()*rho1_;
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::heatCapacity
(
    const scalarField& m1,
    const scalarField& m2,
    const scalarField& m1Latent
) const
{
    tmp<volScalarField> tC(Cp1());
    volScalarField& C = tC.ref();
    C.rename("rhoCp");
    C.dimensions().reset(dimEnergy/dimVolume/dimTemperature);

    const volScalarField Cp2Field(Cp2());
    forAll(C, celli)
    {
        C[celli] =
            m1[celli]*C[celli] + m2[celli]*Cp2Field[celli]
          + metals_->range(fillerFractionAt(celli))
           .latentSlope(liquidFraction_[celli], m1Latent[celli]);
    }
    C.boundaryFieldRef() = Zero;

    return tC;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::metalGasMixture::liquidMetalFaceFraction() const
{
    // The face's liquid fraction is the metal's (weighted by the metal on
    // each side): the temperature of a gas cell with a trace of metal is
    // not the metal's, and its liquid fraction must not decide the force
    const volScalarField metal(max(min(alpha1(), scalar(1)), scalar(0)));
    return
        fvc::interpolate(metal*max(min(liquidFraction_, scalar(1)), scalar(0)))
       /max(fvc::interpolate(metal), dimensionedScalar("small", dimless, SMALL));
}


Foam::tmp<Foam::surfaceScalarField>
Foam::metalGasMixture::surfaceTensionForce() const
{
    // Capillary force on liquid metal only: a solid surface does not flow,
    // and the force on its frozen shape would fight the porosity sink
    tmp<surfaceScalarField> tforce
    (
        liquidMetalFaceFraction()
       *(
            !curvature_.smoothed()
          ? interfaceProperties::surfaceTensionForce()
          : fvc::interpolate(sigma())*curvature_.faceCurvature()
           *fvc::snGrad(alpha1())
        )
    );

    const fvMesh& mesh = alpha1().mesh();
    if (mesh.foundObject<volScalarField>(interfacePressureName))
    {
        const volScalarField& pInterface =
            mesh.lookupObject<volScalarField>(interfacePressureName);
        tforce.ref() += fvc::interpolate(pInterface)*fvc::snGrad(alpha1());
    }

    return tforce;
}


void Foam::metalGasMixture::correctNormal()
{
    interfaceProperties::correct();
}


void Foam::metalGasMixture::correct()
{
    // Always: besides its curvature it updates nHatf, the interface normal
    // flux of the alpha equation's interface compression
    interfaceProperties::correct();

    if (curvature_.smoothed())
    {
        curvature_.correct();
    }
}


// ************************************************************************* //
