/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalGasMixture.H"
#include "checkedInput.H"
#include "fieldIO.H"
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
        ldna::handedOn("liquidFraction", U.mesh()),
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
        ldna::handedOn(IOobject::groupName("rho", phase2Name()), U.mesh()),
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
