/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "evaporation.H"
#include "metalGasMixture.H"
#include "interfaceDelta.H"
#include "cellSource.H"
#include "fvMatrices.H"
#include "physicoChemicalConstants.H"
#include "mathematicalConstants.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(evaporation, 0);
    addToRunTimeSelectionTable(option, evaporation, dictionary);
}

const Foam::Enum<Foam::fv::evaporation::evaporationModel>
Foam::fv::evaporation::evaporationModelNames
({
    { evaporationModel::paper, "paper" },
    { evaporationModel::hertzKnudsen, "hertzKnudsen" },
});
}

namespace
{

// Standard atmosphere [Pa]: the boiling point is quoted at it
const Foam::scalar standardPressure = 101325;

// Recoil pressure over saturation pressure for evaporation into vacuum
// (Anisimov, Sov. Phys. JETP 27 (1968) 182)
const Foam::scalar recoilFactor = 0.54;

}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::evaporation::readCoeffs()
{
    ldna::checkKeys
    (
        coeffs_,
        {
            "type", "active", "model", "boilingTemperature", "latentHeat",
            "molarMass", "boilingPressure", "recondensation",
            "recoilPressure", "alpha", "T", "log"
        }
    );

    model_ = ldna::getChoice(coeffs_, "model", evaporationModelNames);

    using ldna::interval;

    const metalGasMixture& mixture =
        mesh_.lookupObject<metalGasMixture>("thermophysicalProperties");

    // The boiling point lies above the melting range of the metal
    boilingTemperature_ = coeffs_.get<scalar>("boilingTemperature");
    ldna::checkValue
    (
        coeffs_, "boilingTemperature", boilingTemperature_,
        interval::open(mixture.metal().Tliquidus(), ldna::limits::temperature),
        "above the metal's liquidus"
    );
    latentHeat_ = ldna::getChecked<scalar>
    (
        coeffs_, "latentHeat", interval::openClosed(0, ldna::limits::latentHeat)
    );

    const bool hk = (model_ == evaporationModel::hertzKnudsen);
    // Molar masses [kg/mol]: oganesson, the heaviest element, 0.294 kg/mol
    const scalar maxMolarMass = 1;
    molarMass_ = hk
      ? ldna::getChecked<scalar>
        (
            coeffs_, "molarMass", interval::openClosed(0, maxMolarMass)
        )
      : 0;
    boilingPressure_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "boilingPressure",
        interval::openClosed(0, ldna::limits::pressure), standardPressure
    );
    recondensation_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "recondensation", interval::closedOpen(0, 1), 0
    );
    recoilPressure_ = coeffs_.lookupOrDefault<bool>("recoilPressure", false);

    if (recoilPressure_ && !hk)
    {
        FatalIOErrorInFunction(coeffs_)
            << "recoilPressure needs model hertzKnudsen (the paper model has "
            << "no saturation pressure)" << exit(FatalIOError);
    }

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    fieldNames_.setSize(nSourceFields);
    fieldNames_[alphaFieldi] = alphaName_;
    fieldNames_[TFieldi] = TName_;
    applied_.setSize(fieldNames_.size(), false);

    if (recoilPressure_ && !recoilPressureField_.valid())
    {
        recoilPressureField_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    metalGasMixture::interfacePressureName,
                    mesh_.time().timeName(),
                    mesh_
                ),
                mesh_,
                dimensionedScalar(dimPressure, Zero)
            )
        );
    }
    else if (!recoilPressure_)
    {
        recoilPressureField_.clear();
    }

    updatedTimeIndex_ = -1;
}


Foam::scalar Foam::fv::evaporation::saturationPressure(const scalar T) const
{
    const scalar R = constant::physicoChemical::R.value();
    return
        boilingPressure_
       *exp(latentHeat_*molarMass_/R*(1/boilingTemperature_ - 1/T));
}


void Foam::fv::evaporation::update()
{
    if (updatedTimeIndex_ == mesh_.time().timeIndex())
    {
        return;
    }
    updatedTimeIndex_ = mesh_.time().timeIndex();

    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);
    const metalGasMixture& mixture =
        mesh_.lookupObject<metalGasMixture>("thermophysicalProperties");
    const scalarField& rho1 = mixture.rho1().primitiveField();
    const scalar rDeltaT = 1/mesh_.time().deltaTValue();

    massRate_.setSize(mesh_.nCells());
    massRate_ = 0;
    heatSink_.setSize(mesh_.nCells());
    heatSink_ = 0;
    vector recoilForce(Zero);

    if (model_ == evaporationModel::paper)
    {
        // Eq. 38 with the sensible enthalpy for cp (T - T_b), so that it
        // also holds for a temperature-dependent cp.  The vapour leaves at
        // T_b: the solver removes the metal with h1(T), so the sink here is
        // L_b less the superheat h1(T) - h1(T_b) the vapour does not carry,
        // and the metal that stays is left at T_b
        const scalar hBoiling =
            mixture.metal().sensibleEnthalpy(boilingTemperature_);
        forAll(massRate_, celli)
        {
            if (T[celli] > boilingTemperature_ && alpha[celli] > 0)
            {
                const scalar superheat =
                    mixture.metal().sensibleEnthalpy(T[celli]) - hBoiling;
                const scalar we = min(superheat/latentHeat_, scalar(1));
                massRate_[celli] = we*alpha[celli]*rho1[celli]*rDeltaT;
                heatSink_[celli] = massRate_[celli]*(latentHeat_ - superheat);
            }
        }
    }
    else
    {
        const scalar R = constant::physicoChemical::R.value();
        const volVectorField gradAlpha(fvc::grad(alpha));
        const volScalarField delta(metalSurfaceDelta(alpha, gradAlpha));
        const volVectorField deltaNormal
        (
            metalSurfaceDeltaNormal(alpha, gradAlpha)
        );
        forAll(massRate_, celli)
        {
            if (delta[celli] > 0)
            {
                const scalar Tc = T[celli];
                const scalar pSat = saturationPressure(Tc);
                const scalar flux =
                    (1 - recondensation_)*pSat
                   *sqrt(molarMass_/(constant::mathematical::twoPi*R*Tc));

                // A cell cannot lose more metal than it holds
                massRate_[celli] = min
                (
                    flux*delta[celli],
                    max(alpha[celli], scalar(0))*rho1[celli]*rDeltaT
                );

                heatSink_[celli] = massRate_[celli]*latentHeat_;

                // Into the metal: along grad(alpha); the log's cell sum of
                // the force the face form p_r snGrad(alpha) applies
                recoilForce +=
                    recoilFactor*pSat*deltaNormal[celli]*mesh_.V()[celli];
            }
        }

        if (recoilPressure_)
        {
            // In every cell: the face force p_r snGrad(alpha) picks the
            // interface
            volScalarField& pRecoil = recoilPressureField_.ref();
            forAll(pRecoil, celli)
            {
                pRecoil[celli] = recoilFactor*saturationPressure(T[celli]);
            }

            // Processor faces interpolate with the neighbour's value
            pRecoil.correctBoundaryConditions();
        }
    }

    const scalar massRate = gSum(massRate_*mesh_.V());
    evaporatedMass_ += massRate*mesh_.time().deltaTValue();
    const scalar heatSink = gSum(heatSink_*mesh_.V());
    reduce(recoilForce, sumOp<vector>());

    if (log_)
    {
        Info<< type() << ' ' << name_ << ": mass rate = " << massRate
            << " kg/s, evaporated mass = " << evaporatedMass_
            << " kg, latent heat = " << massRate*latentHeat_
            << " W, heat sink = " << heatSink << " W";
        if (recoilPressure_)
        {
            Info<< ", recoil force = " << recoilForce << " N";
        }
        Info<< endl;
    }

    rateFile_.writeRow
    ({
        massRate, evaporatedMass_, massRate*latentHeat_, heatSink,
        recoilForce.x(), recoilForce.y(), recoilForce.z()
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::evaporation::evaporation
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    model_(evaporationModel::paper),
    boilingTemperature_(0),
    latentHeat_(0),
    molarMass_(0),
    boilingPressure_(standardPressure),
    recondensation_(0),
    recoilPressure_(false),
    log_(true),
    updatedTimeIndex_(-1),
    evaporatedMass_(0),
    rateFile_(mesh, name, "evaporation")
{
    readCoeffs();

    rateFile_.writeHeader
    (
        "Evaporated mass rate [kg/s], evaporated mass since the start of the"
        " run [kg], latent heat [W], heat sink [W], recoil force [N]",
        {
            "massRate", "evaporatedMass", "latentHeat", "heatSink",
            "recoilForce_x", "recoilForce_y", "recoilForce_z"
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::evaporation::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    update();

    if (fieldi == alphaFieldi)
    {
        // Metal mass [kg/m3/s]
        eqn -= cellSource(eqn, name_ + ":massSink", massRate_);
    }
    else if (fieldi == TFieldi)
    {
        // Latent heat [W/m3]
        eqn -= cellSource(eqn, name_ + ":heatSink", heatSink_);
    }
}


bool Foam::fv::evaporation::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
