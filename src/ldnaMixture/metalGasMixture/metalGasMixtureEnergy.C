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

Foam::scalar Foam::metalGasMixture::correctLiquidFraction
(
    const volScalarField& Tstar,
    const scalarField& m1,
    const scalarField& m2
)
{
    const volScalarField Cp1Field(Cp1());
    const volScalarField Cp2Field(Cp2());

    scalar maxChange = 0;

    forAll(T_, celli)
    {
        const scalar m = m1[celli];
        const scalar C = m*Cp1Field[celli] + m2[celli]*Cp2Field[celli];
        const scalar gl0 = liquidFraction_[celli];
        const scalar Tc = T_[celli];
        const meltingRange range(metals_->range(fillerFractionAt(celli)));
        const scalar L = range.latentHeat();

        // Local enthalpy as the energy equation linearised it about Tstar,
        // kept by the projection: C T' + m L F(T') = H
        const scalar H =
            C*Tc + m*L*gl0
          + range.latentSlope(liquidFraction_[celli], m)*(Tc - Tstar[celli]);

        scalar gl;
        scalar Tnew;
        range.equilibrate(H, C, m, Tnew, gl);

        // Weighted by the metal fraction: a cell with a trace of metal may
        // flip between solid and liquid without carrying latent heat
        maxChange = max(maxChange, alpha1()[celli]*mag(gl - gl0));
        liquidFraction_[celli] = gl;
        T_[celli] = Tnew;
    }

    T_.correctBoundaryConditions();

    // Boundary values at equilibrium with the boundary temperature: they
    // set the enthalpy of metal entering through a boundary
    volScalarField::Boundary& glb = liquidFraction_.boundaryFieldRef();
    forAll(glb, patchi)
    {
        const scalarField& Tp = T_.boundaryField()[patchi];
        if (glb[patchi].coupled())
        {
            continue;
        }
        forAll(Tp, facei)
        {
            const scalar c =
                fillerFraction_.valid()
              ? fillerFraction_->boundaryField()[patchi][facei]
              : scalar(1);
            glb[patchi][facei] =
                metals_->range(c).equilibriumLiquidFraction(Tp[facei]);
        }
    }
    liquidFraction_.correctBoundaryConditions();

    return returnReduce(maxChange, maxOp<scalar>());
}


void Foam::metalGasMixture::correctThermo()
{
    rho1Gravity_ = evaluate
    (
        "rho1",
        dimDensity,
        [&](scalar T, scalar gl, scalar c)
        {
            return metals_->density(T, gl, c);
        }
    );
    rho1_ = evaluate
    (
        "rho1",
        dimDensity,
        [&](scalar T, scalar gl, scalar c)
        {
            return metals_->massDensity(T, gl, c);
        }
    );
    if (fillerDensity_.valid())
    {
        *fillerDensity_ = evaluate
        (
            "rhoFiller",
            dimDensity,
            [&](scalar T, scalar gl, scalar)
            {
                return metals_->massDensity(T, gl, 1);
            }
        );
    }

    psi2_ = evaluate
    (
        "psi2",
        dimDensity/dimPressure,
        [&](scalar T, scalar, scalar)
        {
            return 1/(gas_->R()*gasDensity_->massTemperature(T));
        }
    );
    rho2_ = psi2_*p_;

    kappa_ = alpha1()*kappa1() + alpha2()*kappa2();

    const volScalarField mu1
    (
        evaluate
        (
            "mu1",
            mu_.dimensions(),
            [&](scalar T, scalar, scalar c)
            {
                return metals_->viscosity(T, c);
            }
        )
    );
    const volScalarField mu2
    (
        evaluate
        (
            "mu2",
            mu_.dimensions(),
            [&](scalar T, scalar, scalar) { return gas_->viscosity(T); }
        )
    );
    mu_ = alpha1()*mu1 + alpha2()*mu2;
}


void Foam::metalGasMixture::correctGasDensity(const volScalarField& dRho2)
{
    rho2_ += dRho2;
}


Foam::scalar Foam::metalGasMixture::metalMass() const
{
    return fvc::domainIntegrate(alpha1()*rho1_).value();
}


Foam::scalar Foam::metalGasMixture::totalEnthalpy() const
{
    return fvc::domainIntegrate(volumetricEnthalpy()).value();
}


// ************************************************************************* //
