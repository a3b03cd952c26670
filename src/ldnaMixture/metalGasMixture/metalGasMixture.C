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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(metalGasMixture, 0);
}

const Foam::scalar Foam::metalGasMixture::propertyCheckTmin = 200;
const Foam::scalar Foam::metalGasMixture::propertyCheckTmax = 3200;
const Foam::word Foam::metalGasMixture::interfacePressureName
(
    "interfacePressure"
);

const Foam::word Foam::metalGasMixture::substrateName("substrate");

const Foam::word Foam::metalGasMixture::fillerFractionName("fillerFraction");

const Foam::scalar Foam::metalGasMixture::Tref = 298.15;

const Foam::scalar Foam::metalGasMixture::propertyTableStep = 5;


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::metalGasMixture::readCoeffs()
{
    using ldna::interval;
    namespace limits = ldna::limits;

    ldna::checkKeys
    (
        *this,
        {
            "phases", "pMin", "curvatureSmoothing", "sigma", phase1Name(),
            substrateName, "gas"
        }
    );

    pMin_ = dimensionedScalar
    (
        "pMin", dimPressure,
        ldna::getChecked<scalar>
        (
            *this, "pMin", interval::openClosed(0, limits::pressure)
        )
    );

    curvature_.read(*this);

    const wordList metalKeys
    {
        "densityModel", "referenceDensity", "solidus", "liquidus",
        "latentHeat", "rho", "Cp", "kappa", "mu"
    };
    const dictionary& metal = subDict(phase1Name());
    ldna::checkKeys(metal, metalKeys);
    const dictionary* substrate = findDict(substrateName);
    if (substrate)
    {
        ldna::checkKeys(*substrate, metalKeys);
    }

    metals_.reset
    (
        new metalComposition
        (
            metal, substrate, propertyCheckTmin, propertyCheckTmax, Tref
        )
    );

    // Written whenever the properties are read, so that a dictionary
    // changed during the run gets its table too (the newest file is the
    // one in force)
    metals_->writeTables
    (
        db(), typeName, propertyCheckTmin, limits::temperature,
        propertyTableStep
    );

    const dictionary& gas = subDict(phase2Name());
    ldna::checkKeys
    (
        gas,
        {"R", "densityModel", "referenceTemperature", "Cp", "kappa", "mu"}
    );

    gas_.reset
    (
        new gasProperties(gas, propertyCheckTmin, propertyCheckTmax, Tref)
    );
    gasDensity_ = gasDensityModel::New(gas);
}


template<class CellFunction>
Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::evaluate
(
    const word& name,
    const dimensionSet& dims,
    const CellFunction& f
) const
{
    tmp<volScalarField> tresult
    (
        new volScalarField
        (
            IOobject
            (
                name,
                T_.time().timeName(),
                T_.mesh(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            T_.mesh(),
            dimensionedScalar(dims, Zero)
        )
    );
    volScalarField& result = tresult.ref();

    const scalarField& Tc = T_.primitiveField();
    const scalarField& glc = liquidFraction_.primitiveField();
    scalarField& rc = result.primitiveFieldRef();
    forAll(rc, celli)
    {
        rc[celli] = f(Tc[celli], glc[celli], fillerFractionAt(celli));
    }

    volScalarField::Boundary& rb = result.boundaryFieldRef();
    forAll(rb, patchi)
    {
        const scalarField& Tp = T_.boundaryField()[patchi];
        const scalarField& glp = liquidFraction_.boundaryField()[patchi];
        fvPatchScalarField& rp = rb[patchi];
        forAll(rp, facei)
        {
            rp[facei] =
                f
                (
                    Tp[facei], glp[facei],
                    fillerFraction_.valid()
                  ? fillerFraction_->boundaryField()[patchi][facei]
                  : scalar(1)
                );
        }
    }

    return tresult;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalGasMixture::metalGasMixture
(
    const volVectorField& U,
    const surfaceScalarField& phi
)
:
    IOdictionary
    (
        IOobject
        (
            "thermophysicalProperties",
            U.time().constant(),
            U.db(),
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    twoPhaseMixture(U.mesh(), *this),
    interfaceProperties(alpha1(), U, *this),
    p_
    (
        IOobject
        (
            "p",
            U.time().timeName(),
            U.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        U.mesh()
    ),
    T_
    (
        IOobject
        (
            "T",
            U.time().timeName(),
            U.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        U.mesh()
    ),
    liquidFraction_
    (
        IOobject
        (
            "liquidFraction",
            U.time().timeName(),
            U.mesh(),
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        U.mesh(),
        dimensionedScalar(dimless, Zero)
    ),
    rho1_
    (
        IOobject
        (
            IOobject::groupName("rho", phase1Name()),
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimDensity, Zero)
    ),
    rho1Gravity_
    (
        IOobject
        (
            IOobject::groupName("rhoGravity", phase1Name()),
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimDensity, Zero)
    ),
    rho2_
    (
        IOobject
        (
            IOobject::groupName("rho", phase2Name()),
            U.time().timeName(),
            U.mesh(),
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        U.mesh(),
        dimensionedScalar(dimDensity, Zero)
    ),
    restartedGasDensity_(false),
    psi2_
    (
        IOobject
        (
            IOobject::groupName("psi", phase2Name()),
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimDensity/dimPressure, Zero)
    ),
    kappa_
    (
        IOobject
        (
            "kappa",
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimPower/dimLength/dimTemperature, Zero)
    ),
    mu_
    (
        IOobject
        (
            "mu",
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimDynamicViscosity, Zero)
    ),
    pMin_("pMin", dimPressure, Zero),
    sigmaModel_(surfaceTensionModel::New(*this, U.mesh())),
    curvature_(alpha1()),
    metals_(),
    fillerFraction_(),
    fillerDensity_(),
    gas_(),
    gasDensity_()
{
    readCoeffs();
    correct();

    if (metals_->twoMetals())
    {
        fillerFraction_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    fillerFractionName,
                    U.time().timeName(),
                    U.mesh(),
                    IOobject::MUST_READ,
                    IOobject::AUTO_WRITE
                ),
                U.mesh()
            )
        );
        // A field mapped volume-weighted from another mesh (Allrun
        // -start-from) may exceed [0, 1] by the round-off of its weights:
        // such values are clipped, anything further out is an error
        const scalar mappingRoundOff = 1e-12;
        scalarField& c = fillerFraction_->primitiveFieldRef();
        label clipped = 0;
        forAll(c, celli)
        {
            if
            (
                (c[celli] < 0 && c[celli] >= -mappingRoundOff)
             || (c[celli] > 1 && c[celli] <= 1 + mappingRoundOff)
            )
            {
                c[celli] = min(max(c[celli], scalar(0)), scalar(1));
                ++clipped;
            }
            if (!(c[celli] >= 0 && c[celli] <= 1))
            {
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__,
                    fillerFraction_->objectPath(), -1, -1
                )   << "Field " << fillerFractionName << ": value "
                    << c[celli] << " in cell " << celli << " must lie in"
                    << " [0, 1] (the filler's share of the metal's volume)"
                    << exit(FatalIOError);
            }
        }
        reduce(clipped, sumOp<label>());
        if (clipped)
        {
            Info<< "Field " << fillerFractionName << ": " << clipped
                << " values within " << mappingRoundOff << " of [0, 1] set to"
                << " its bounds (a mapped field's round-off)" << endl;
        }
        fillerFraction_->oldTime();

        fillerDensity_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "rhoFiller",
                    U.time().timeName(),
                    U.mesh()
                ),
                U.mesh(),
                dimensionedScalar(dimDensity, Zero)
            )
        );
    }

    if (min(T_).value() <= 0)
    {
        FatalErrorInFunction
            << "Field T must be > 0 K everywhere; its minimum is "
            << min(T_).value() << exit(FatalError);
    }

    // Without a stored liquid fraction start from equilibrium
    if
    (
        !liquidFraction_.typeHeaderOk<volScalarField>(true)
    )
    {
        forAll(liquidFraction_, celli)
        {
            liquidFraction_[celli] =
                metals_->range(fillerFractionAt(celli))
               .equilibriumLiquidFraction(T_[celli]);
        }
    }

    // The gas density of a written time is the pressure solution's
    // incremental update of psi2 p (correctGasDensity), not psi2 p itself:
    // a restart takes it as written so that it continues where the run was
    // stopped
    restartedGasDensity_ = rho2_.typeHeaderOk<volScalarField>(true);
    tmp<volScalarField> rho2Written;
    if (restartedGasDensity_)
    {
        rho2Written = new volScalarField("rho2Written", rho2_);
    }

    correctThermo();

    if (restartedGasDensity_)
    {
        rho2_ = rho2Written();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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


bool Foam::metalGasMixture::read()
{
    if (regIOobject::read())
    {
        readCoeffs();
        return interfaceProperties::read() && sigmaModel_->readDict(*this);
    }
    return false;
}


// ************************************************************************* //
