/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "interfaceHeatLoss.H"
#include "fvMatrices.H"
#include "interfaceDelta.H"
#include "fvmSup.H"
#include "physicoChemicalConstants.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(interfaceHeatLoss, 0);
    addToRunTimeSelectionTable(option, interfaceHeatLoss, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::interfaceHeatLoss::readCoeffs()
{
    using ldna::interval;

    ldna::checkKeys
    (
        coeffs_,
        {
            "type", "active", "radiation", "emissivity", "convection",
            "heatTransferCoeff", "ambientTemperature", "alpha", "T", "log"
        }
    );

    radiation_ = coeffs_.lookupOrDefault<bool>("radiation", true);
    convection_ = coeffs_.lookupOrDefault<bool>("convection", true);

    emissivity_ = radiation_
      ? ldna::getChecked<scalar>(coeffs_, "emissivity", interval::closed(0, 1))
      : 0;
    heatTransferCoeff_ = convection_
      ? ldna::getChecked<scalar>
        (
            coeffs_, "heatTransferCoeff",
            interval::closed(0, ldna::limits::heatTransferCoeff)
        )
      : 0;
    ambientTemperature_ = ldna::getChecked<scalar>
    (
        coeffs_, "ambientTemperature",
        interval::open(0, ldna::limits::temperature)
    );

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    fieldNames_.setSize(1, TName_);
    applied_.setSize(1, false);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::interfaceHeatLoss::interfaceHeatLoss
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    radiation_(true),
    emissivity_(0),
    convection_(true),
    heatTransferCoeff_(0),
    ambientTemperature_(0),
    log_(true),
    loggedTimeIndex_(-1),
    lossFile_(mesh, name, "losses"),
    deltaEventNo_(-1)
{
    readCoeffs();

    lossFile_.writeHeader
    (
        "Power lost by the metal surface at the first energy iteration"
        " of the step [W]",
        {"radiated", "convected"}
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::interfaceHeatLoss::addSup
(
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);
    if (alpha.eventNo() != deltaEventNo_ || delta_.size() != mesh_.nCells())
    {
        // alpha changes once per outer corrector, not between the energy
        // iterations that call this
        delta_ = metalSurfaceDelta(alpha)().primitiveField();
        deltaEventNo_ = alpha.eventNo();
    }
    const scalarField& delta = delta_;
    const scalarField& Tc = T.primitiveField();

    const scalar sigmaSB = constant::physicoChemical::sigma.value();
    const scalar T0 = ambientTemperature_;
    const scalar T04 = pow4(T0);

    // Loss q(T) about the current iterate T*: q(T*) + q'(T*) (T - T*), the
    // slope part implicit
    const dimensionSet sourceDims(eqn.dimensions()/dimVolume);
    DimensionedField<scalar, volMesh> explicitPart
    (
        IOobject(name_ + ":explicit", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(sourceDims, Zero)
    );
    DimensionedField<scalar, volMesh> slope
    (
        IOobject(name_ + ":slope", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(sourceDims/dimTemperature, Zero)
    );

    scalar radiated = 0;
    scalar convected = 0;
    const scalarField& V = mesh_.V();
    forAll(Tc, celli)
    {
        const scalar Ts = Tc[celli];
        const scalar qRad = emissivity_*sigmaSB*(pow4(Ts) - T04);
        const scalar qConv = heatTransferCoeff_*(Ts - T0);
        const scalar dq = 4*emissivity_*sigmaSB*pow3(Ts) + heatTransferCoeff_;

        slope[celli] = delta[celli]*dq;
        explicitPart[celli] = delta[celli]*(qRad + qConv - dq*Ts);

        radiated += qRad*delta[celli]*V[celli];
        convected += qConv*delta[celli]*V[celli];
    }

    eqn -= explicitPart;
    eqn -= fvm::Sp(slope, T);

    // At the first energy iteration of each step
    if (loggedTimeIndex_ != mesh_.time().timeIndex())
    {
        loggedTimeIndex_ = mesh_.time().timeIndex();
        reduce(radiated, sumOp<scalar>());
        reduce(convected, sumOp<scalar>());
        if (log_)
        {
            Info<< type() << ' ' << name_ << ": radiated = " << radiated
                << " W, convected = " << convected << " W" << endl;
        }
        lossFile_.writeRow({radiated, convected});
    }
}


void Foam::fv::interfaceHeatLoss::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::interfaceHeatLoss::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
