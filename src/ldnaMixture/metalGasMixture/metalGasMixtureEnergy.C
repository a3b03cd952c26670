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


void Foam::metalGasMixture::correctDensities()
{
    // The metal's three densities from one look-up of each metal's rho(T, gl)
    // per cell and boundary face
    scalarField& rhoGravityc = rho1Gravity_.primitiveFieldRef();
    scalarField& rhoc = rho1_.primitiveFieldRef();
    const scalarField& Tc = T_.primitiveField();
    const scalarField& glc = liquidFraction_.primitiveField();
    scalar fillerMass = 0;
    forAll(Tc, celli)
    {
        metals_->densities
        (
            Tc[celli], glc[celli], fillerFractionAt(celli),
            rhoGravityc[celli], rhoc[celli], fillerMass
        );
        if (fillerDensity_.valid())
        {
            fillerDensity_->primitiveFieldRef()[celli] = fillerMass;
        }
    }
    forAll(T_.boundaryField(), patchi)
    {
        const scalarField& Tp = T_.boundaryField()[patchi];
        const scalarField& glp = liquidFraction_.boundaryField()[patchi];
        scalarField& rhoGravityp = rho1Gravity_.boundaryFieldRef()[patchi];
        scalarField& rhop = rho1_.boundaryFieldRef()[patchi];
        forAll(Tp, facei)
        {
            metals_->densities
            (
                Tp[facei], glp[facei],
                fillerFraction_.valid()
              ? fillerFraction_->boundaryField()[patchi][facei]
              : scalar(1),
                rhoGravityp[facei], rhop[facei], fillerMass
            );
            if (fillerDensity_.valid())
            {
                fillerDensity_->boundaryFieldRef()[patchi][facei] = fillerMass;
            }
        }
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
}


void Foam::metalGasMixture::correctTransport()
{
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


void Foam::metalGasMixture::correctThermo()
{
    correctDensities();
    correctTransport();
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
