/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "metalGasMixture.H"
#include "checkedInput.H"
#include "physicalLimits.H"
#include "interfaceDelta.H"
#include "fvc.H"

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

const Foam::scalar Foam::metalGasMixture::Tref = 298.15;

const Foam::scalar Foam::metalGasMixture::propertyTableStep = 5;


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::metalGasMixture::readBoussinesq
(
    const dictionary& phaseDict,
    const word& otherModel,
    const word& defaultModel,
    const word& referenceName,
    const word& referenceUnit,
    const scalar referenceMax,
    scalar& reference
) const
{
    const word model
    (
        phaseDict.lookupOrDefault<word>("densityModel", defaultModel)
    );
    if (model != "Boussinesq" && model != otherModel)
    {
        FatalIOErrorInFunction(phaseDict)
            << "Entry 'densityModel' must be Boussinesq or " << otherModel
            << ", not " << model << exit(FatalIOError);
    }

    Info<< "    " << phaseDict.dictName() << " density: " << model;
    if (model == "Boussinesq")
    {
        reference = ldna::getChecked<scalar>
        (
            phaseDict, referenceName, ldna::interval::open(0, referenceMax)
        );
        Info<< ", " << referenceName << " " << reference << " "
            << referenceUnit << " for mass and inertia";
    }
    Info<< endl;

    return model == "Boussinesq";
}


void Foam::metalGasMixture::readCoeffs()
{
    using ldna::interval;
    namespace limits = ldna::limits;

    ldna::checkKeys
    (
        *this,
        {"phases", "pMin", "curvatureSmoothing", "sigma", "metal", "gas"}
    );

    pMin_ = dimensionedScalar
    (
        "pMin", dimPressure,
        ldna::getChecked<scalar>
        (
            *this, "pMin", interval::openClosed(0, limits::pressure)
        )
    );

    // More passes smooth the curvature over more than the interface's
    // neighbourhood
    const label maxCurvatureSmoothing = 100;
    curvatureSmoothing_ = ldna::getCheckedOrDefault<label>
    (
        *this, "curvatureSmoothing",
        interval::closed(0, maxCurvatureSmoothing), 2
    );

    const dictionary& metal = subDict(phase1Name());
    ldna::checkKeys
    (
        metal,
        {
            "densityModel", "referenceDensity", "solidus", "liquidus",
            "latentHeat", "rho", "Cp", "kappa", "mu"
        }
    );

    Boussinesq_ = readBoussinesq
    (
        metal, "variable", "Boussinesq", "referenceDensity", "kg/m3",
        limits::density, referenceDensity_
    );
    metal_.reset
    (
        new metalProperties(metal, propertyCheckTmin, propertyCheckTmax, Tref)
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
    gasBoussinesq_ = readBoussinesq
    (
        gas, "idealGas", "idealGas", "referenceTemperature", "K",
        limits::temperature, gasReferenceTemperature_
    );
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
        rc[celli] = f(Tc[celli], glc[celli]);
    }

    volScalarField::Boundary& rb = result.boundaryFieldRef();
    forAll(rb, patchi)
    {
        const scalarField& Tp = T_.boundaryField()[patchi];
        const scalarField& glp = liquidFraction_.boundaryField()[patchi];
        fvPatchScalarField& rp = rb[patchi];
        forAll(rp, facei)
        {
            rp[facei] = f(Tp[facei], glp[facei]);
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
    curvatureSmoothing_(0),
    curvature_
    (
        IOobject
        (
            "curvature",
            U.time().timeName(),
            U.mesh()
        ),
        U.mesh(),
        dimensionedScalar(dimless/dimLength, Zero)
    ),
    curvaturef_
    (
        IOobject("curvaturef", U.time().timeName(), U.mesh()),
        U.mesh(),
        dimensionedScalar(dimless/dimLength, Zero)
    ),
    Boussinesq_(true),
    referenceDensity_(0),
    gasBoussinesq_(false),
    gasReferenceTemperature_(0)
{
    readCoeffs();
    metal_->writeTable
    (
        U.db(), typeName, propertyCheckTmin, ldna::limits::temperature,
        propertyTableStep
    );
    correct();

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
                metal_->equilibriumLiquidFraction(T_[celli]);
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
    const scalar L = metal_->latentHeat();
    return evaluate
    (
        "h1",
        dimEnergy/dimMass,
        [&](scalar T, scalar gl) { return metal_->sensibleEnthalpy(T) + gl*L; }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::h2() const
{
    return evaluate
    (
        "h2",
        dimEnergy/dimMass,
        [&](scalar T, scalar) { return gas_->sensibleEnthalpy(T); }
    );
}


namespace
{

// Thermal resistance times area [m2 K/W] between the centre of the heat
// capacity of a cell and its face at distance d, the cell's metal fraction
// alpha lying as a layer against the face (thickness 2 alpha d) and its gas
// behind it; metalHeatShare is the metal's share of the cell's heat
// capacity.  Pure gas and pure metal give d/kappa
Foam::scalar layeredHalfResistance
(
    const Foam::scalar d,
    const Foam::scalar alpha,
    const Foam::scalar metalHeatShare,
    const Foam::scalar kappaMetal,
    const Foam::scalar kappaGas
)
{
    const Foam::scalar centre = d*(1 + alpha - metalHeatShare);
    const Foam::scalar metalLayer = 2*alpha*d;
    if (centre <= metalLayer)
    {
        return centre/kappaMetal;
    }
    return metalLayer/kappaMetal + (centre - metalLayer)/kappaGas;
}


// One cell of a face: its distance to the face, metal fraction, metal's
// share of its heat capacity, phase and volume-mean conductivities
struct faceCell
{
    Foam::scalar d, alpha, metalHeatShare, kappaMetal, kappaGas, kappa;
};

Foam::scalar seriesConductivity(const faceCell& lean, const faceCell& rich)
{
    return
        (lean.d + rich.d)
       /(
            layeredHalfResistance
            (
                lean.d, lean.alpha, lean.metalHeatShare,
                lean.kappaMetal, lean.kappaGas
            )
          + rich.d/rich.kappa
        );
}


// Symmetric in a and b, so that both sides of a processor face agree
Foam::scalar layeredFaceConductivity(const faceCell& a, const faceCell& b)
{
    if (a.alpha < b.alpha)
    {
        return seriesConductivity(a, b);
    }
    if (b.alpha < a.alpha)
    {
        return seriesConductivity(b, a);
    }
    return 0.5*(seriesConductivity(a, b) + seriesConductivity(b, a));
}

} // End anonymous namespace


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::kappa1() const
{
    return evaluate
    (
        "kappa1",
        kappa_.dimensions(),
        [&](scalar T, scalar gl) { return metal_->conductivity(T, gl); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::kappa2() const
{
    return evaluate
    (
        "kappa2",
        kappa_.dimensions(),
        [&](scalar T, scalar) { return gas_->conductivity(T); }
    );
}


Foam::tmp<Foam::surfaceScalarField> Foam::metalGasMixture::kappaf() const
{
    const fvMesh& mesh = alpha1().mesh();

    const volScalarField metal(max(min(alpha1(), scalar(1)), scalar(0)));
    const volScalarField kappaMetal(kappa1());
    const volScalarField kappaGas(kappa2());
    const volScalarField metalHeat(metal*rho1_*Cp1());
    const volScalarField metalHeatShare
    (
        metalHeat/(metalHeat + (1 - metal)*rho2Heat()*Cp2())
    );

    const auto cellOf = [&](const label celli, const scalar d)
    {
        return faceCell
        {
            d, metal[celli], metalHeatShare[celli],
            kappaMetal[celli], kappaGas[celli], kappa_[celli]
        };
    };

    tmp<surfaceScalarField> tkappaf
    (
        new surfaceScalarField
        (
            IOobject("kappaf", mesh.time().timeName(), mesh),
            mesh,
            kappa_.dimensions()
        )
    );
    surfaceScalarField& kf = tkappaf.ref();

    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    const vectorField& C = mesh.C();
    const vectorField& Cf = mesh.Cf();
    const vectorField& Sf = mesh.Sf();
    const scalarField& magSf = mesh.magSf();

    forAll(owner, facei)
    {
        const vector n(Sf[facei]/magSf[facei]);
        kf[facei] = layeredFaceConductivity
        (
            cellOf(owner[facei], mag(n & (Cf[facei] - C[owner[facei]]))),
            cellOf(neighbour[facei], mag(n & (C[neighbour[facei]] - Cf[facei])))
        );
    }

    forAll(kf.boundaryField(), patchi)
    {
        fvsPatchScalarField& kfp = kf.boundaryFieldRef()[patchi];
        const fvPatch& patch = mesh.boundary()[patchi];
        if (!patch.coupled())
        {
            kfp = kappa_.boundaryField()[patchi];
            continue;
        }
        const labelUList& faceCells = patch.faceCells();
        const vectorField nf(patch.nf());
        const vectorField ownerDelta(patch.Cf() - patch.Cn());
        const vectorField delta(patch.delta());
        const scalarField nbrMetal(metal.boundaryField()[patchi].patchNeighbourField());
        const scalarField nbrShare
        (
            metalHeatShare.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa1
        (
            kappaMetal.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa2
        (
            kappaGas.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa(kappa_.boundaryField()[patchi].patchNeighbourField());
        forAll(kfp, i)
        {
            const scalar dOwner = mag(nf[i] & ownerDelta[i]);
            kfp[i] = layeredFaceConductivity
            (
                cellOf(faceCells[i], dOwner),
                faceCell
                {
                    max(mag(nf[i] & delta[i]) - dOwner, SMALL),
                    nbrMetal[i], nbrShare[i],
                    nbrKappa1[i], nbrKappa2[i], nbrKappa[i]
                }
            );
        }
    }

    return tkappaf;
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::Cp1() const
{
    return evaluate
    (
        "Cp1",
        dimEnergy/dimMass/dimTemperature,
        [&](scalar T, scalar) { return metal_->Cp(T); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::Cp2() const
{
    return evaluate
    (
        "Cp2",
        dimEnergy/dimMass/dimTemperature,
        [&](scalar T, scalar) { return gas_->Cp(T); }
    );
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rho2Heat() const
{
    if (gasBoussinesq_)
    {
        const dimensionedScalar Tref
        (
            "referenceTemperature",
            dimTemperature,
            gasReferenceTemperature_
        );
        return rho2_*Tref/T_;
    }
    return tmp<volScalarField>::New("rho2Heat", rho2_);
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rho() const
{
    return alpha1()*rho1_ + alpha2()*rho2_;
}


Foam::tmp<Foam::volScalarField> Foam::metalGasMixture::rhoGravity() const
{
    if (gasBoussinesq_)
    {
        const dimensionedScalar R
        (
            "R",
            dimVelocity*dimVelocity/dimTemperature,
            gas_->R()
        );
        return alpha1()*rho1Gravity_ + alpha2()*p_/(R*T_);
    }
    return alpha1()*rho1Gravity_ + alpha2()*rho2_;
}


Foam::tmp<Foam::volScalarField>
Foam::metalGasMixture::volumetricEnthalpy() const
{
    return alpha1()*rho1_*h1() + alpha2()*rho2Heat()*h2();
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
          + metal_->latentSlope(liquidFraction_[celli], m1Latent[celli]);
    }
    C.boundaryFieldRef() = Zero;

    return tC;
}


void Foam::metalGasMixture::correctCurvature()
{
    const fvMesh& mesh = alpha1().mesh();

    volScalarField alphaSmooth("alphaSmooth", alpha1());
    for (label pass = 0; pass < curvatureSmoothing_; ++pass)
    {
        alphaSmooth = fvc::average(fvc::interpolate(alphaSmooth));

        // The boundary values follow alpha1's conditions (zeroGradient at
        // walls); left at the unsmoothed values, they bent the smoothed
        // interface where it meets a wall
        alphaSmooth.correctBoundaryConditions();
    }

    // Unit normals in the cells of the (smoothed) interface band only
    const volVectorField gradAlpha(fvc::grad(alphaSmooth, "nHat"));
    volVectorField nHat
    (
        IOobject("nHat", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimless, Zero)
    );
    nHat.primitiveFieldRef() = metalInterfaceNormal(gradAlpha);

    // Processor and symmetry faces take their neighbour's (mirrored) normal;
    // on walls and open patches nHat stays zero: no capillary flux through
    // them (the 90 degree contact angle of a zeroGradient alpha)
    nHat.correctBoundaryConditions();
    curvature_ = -fvc::div(fvc::interpolate(nHat) & mesh.Sf());

    // Face curvature: the cell curvatures weighted by |grad alpha| of the
    // smoothed field, so that
    // a face of the sharp interface takes the curvature of the cells the
    // interface passes through, not that of the band's edge cells, where
    // the normals fade out and -div(nHat) is an artefact of the fading
    const volScalarField weight(mag(gradAlpha));
    curvaturef_ =
        fvc::interpolate(weight*curvature_)
       /(fvc::interpolate(weight) + dimensionedScalar("small", weight.dimensions(), VSMALL));
}


Foam::tmp<Foam::surfaceScalarField>
Foam::metalGasMixture::surfaceTensionForce() const
{
    // Capillary force on liquid metal only: a solid surface does not flow,
    // and the force on its frozen shape would fight the porosity sink.  The
    // face's liquid fraction is the metal's (weighted by the metal on each
    // side): the temperature of a gas cell with a trace of metal is not the
    // metal's, and its liquid fraction must not decide the force
    const volScalarField metal(max(min(alpha1(), scalar(1)), scalar(0)));
    const surfaceScalarField liquidMetalFraction
    (
        fvc::interpolate(metal*max(min(liquidFraction_, scalar(1)), scalar(0)))
       /max(fvc::interpolate(metal), dimensionedScalar("small", dimless, SMALL))
    );
    tmp<surfaceScalarField> tforce
    (
        liquidMetalFraction
       *(
            curvatureSmoothing_ == 0
          ? interfaceProperties::surfaceTensionForce()
          : fvc::interpolate(sigma())*curvaturef_*fvc::snGrad(alpha1())
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

    if (curvatureSmoothing_ > 0)
    {
        correctCurvature();
    }
}


Foam::scalar Foam::metalGasMixture::correctLiquidFraction
(
    const volScalarField& Tstar,
    const scalarField& m1,
    const scalarField& m2
)
{
    const scalar Ts = metal_->Tsolidus();
    const scalar Tl = metal_->Tliquidus();
    const scalar dTm = Tl - Ts;
    const scalar L = metal_->latentHeat();

    const volScalarField Cp1Field(Cp1());
    const volScalarField Cp2Field(Cp2());

    scalar maxChange = 0;

    forAll(T_, celli)
    {
        const scalar m = m1[celli];
        const scalar C = m*Cp1Field[celli] + m2[celli]*Cp2Field[celli];
        const scalar gl0 = liquidFraction_[celli];
        const scalar Tc = T_[celli];

        // Local enthalpy as the energy equation linearised it about Tstar,
        // kept by the projection: C T' + m L F(T') = H
        const scalar H =
            C*Tc + m*L*gl0
          + metal_->latentSlope(liquidFraction_[celli], m)*(Tc - Tstar[celli]);

        scalar gl;
        scalar Tnew;
        if (H <= C*Ts)
        {
            gl = 0;
            Tnew = H/C;
        }
        else if (H >= C*Tl + m*L)
        {
            gl = 1;
            Tnew = (H - m*L)/C;
        }
        else
        {
            Tnew = (H + m*L*Ts/dTm)/(C + m*L/dTm);
            gl = (Tnew - Ts)/dTm;
        }

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
            glb[patchi][facei] = metal_->equilibriumLiquidFraction(Tp[facei]);
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
        [&](scalar T, scalar gl) { return metal_->density(T, gl); }
    );
    if (Boussinesq_)
    {
        rho1_ =
            dimensionedScalar("referenceDensity", dimDensity, referenceDensity_);
    }
    else
    {
        rho1_ = rho1Gravity_;
    }

    psi2_ = evaluate
    (
        "psi2",
        dimDensity/dimPressure,
        [&](scalar T, scalar)
        {
            return
                1/(gas_->R()*(gasBoussinesq_ ? gasReferenceTemperature_ : T));
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
            [&](scalar T, scalar)
            {
                return metal_->viscosity(T);
            }
        )
    );
    const volScalarField mu2
    (
        evaluate
        (
            "mu2",
            mu_.dimensions(),
            [&](scalar T, scalar) { return gas_->viscosity(T); }
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
