/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "dropletSource.H"
#include "metalGasMixture.H"
#include "boundBox.H"
#include "unitConversion.H"
#include "checkedInput.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::dropletSource::readCoeffs()
{
    ldna::checkKeys
    (
        coeffs_,
        {
            "type", "active", "mode", "wireDensity", "position",
            "wireSpacing", "speed", "transverseAngle", "parallelityFrequency",
            "maxLongitudinalAngle", "switchPhase", "switchThreshold",
            "irregularityTime", "irregularDiameterFactor",
            "irregularSpacingIncrease", "wires", "alpha", "U", "T", "log"
        }
    );

    readTiming();
    readIrregularity();
    readMode();
    readWires();
}


void Foam::fv::dropletSource::readTiming()
{
    using ldna::interval;
    namespace limits = ldna::limits;

    speed_ = ldna::getChecked<scalar>
    (
        coeffs_, "speed", interval::closedOpen(0, limits::speed)
    );
    parallelityFrequency_ = ldna::getChecked<scalar>
    (
        coeffs_, "parallelityFrequency",
        interval::openClosed(0, limits::frequency)
    );
    transverseAngle_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "transverseAngle", interval::open(-90, 90), 0
    );

    // eq. 33: alpha between 0 and 10 degrees
    const scalar alphaMax = 10;
    maxLongitudinalAngle_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "maxLongitudinalAngle", interval::closedOpen(0, 90), alphaMax
    );

    // eq. 18: on while sin(2 pi nu t + arcsin 0.9) > 0.8
    const scalar phase = radToDeg(asin(0.9));
    switchPhase_ = degToRad
    (
        ldna::getCheckedOrDefault<scalar>
        (
            coeffs_, "switchPhase", interval::closed(-360, 360), phase
        )
    );
    const scalar threshold = 0.8;
    switchThreshold_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "switchThreshold", interval::open(-1, 1), threshold
    );
}


void Foam::fv::dropletSource::readIrregularity()
{
    using ldna::interval;
    namespace limits = ldna::limits;

    irregularityTime_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "irregularityTime", interval::closedOpen(0, GREAT), 0
    );
    // A droplet of up to ten times the regular diameter, 1 000 times the
    // mass: beyond that it is no droplet of the wire
    const scalar maxDiameterFactor = 10;
    const scalar diameterFactor = 2;
    irregularDiameterFactor_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "irregularDiameterFactor",
        interval::openClosed(0, maxDiameterFactor), diameterFactor
    );
    // The paper adds 0.5 in the units of d_d, which its figures give in mm
    const scalar spacingIncrease = 0.5e-3;
    irregularSpacingIncrease_ = ldna::getCheckedOrDefault<scalar>
    (
        coeffs_, "irregularSpacingIncrease",
        interval::closedOpen(0, limits::length), spacingIncrease
    );
}


void Foam::fv::dropletSource::readMode()
{
    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    UName_ = coeffs_.lookupOrDefault<word>("U", "U");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    transfer_ = dropletTransferModel::New(*this, mesh_);
    fieldNames_ = transfer_->fieldNames(alphaName_, UName_, TName_);
    applied_.setSize(fieldNames_.size(), false);
}


void Foam::fv::dropletSource::readWires()
{
    using ldna::interval;
    namespace limits = ldna::limits;

    wireDefaults defaults;
    defaults.wireDensity = ldna::getChecked<scalar>
    (
        coeffs_, "wireDensity", interval::openClosed(0, limits::density)
    );
    defaults.position = coeffs_.get<vector>("position");
    defaults.spacing = ldna::getChecked<scalar>
    (
        coeffs_, "wireSpacing", interval::closedOpen(0, limits::length)
    );
    defaults.domainSize = cmptMin(boundBox(mesh_.points(), true).span());
    irregularStart_ = irregularityTime_ > mesh_.time().startTime().value();

    const dictionary& wiresDict = coeffs_.subDict("wires");
    wires_.setSize(wiresDict.size());
    if (wires_.empty())
    {
        FatalIOErrorInFunction(wiresDict)
            << "Entry 'wires' must hold at least one wire dictionary"
            << exit(FatalIOError);
    }

    label k = 0;
    for (const entry& e : wiresDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(wiresDict)
                << "Entry '" << e.keyword() << "' in 'wires' must be a"
                << " dictionary of one wire" << exit(FatalIOError);
        }
        readWire(e.keyword(), e.dict(), k, defaults, wires_[k]);
        ++k;
    }
}


void Foam::fv::dropletSource::readWire
(
    const word& name,
    const dictionary& dict,
    const label k,
    const wireDefaults& defaults,
    wireStream& wire
)
{
    using ldna::interval;
    namespace limits = ldna::limits;

    // The wires stand in a row along x, the welding direction
    const vector spacingDirection(1, 0, 0);

    const metalGasMixture& mixture =
        mesh_.lookupObject<metalGasMixture>("thermophysicalProperties");

    wire.name = name;
    ldna::checkKeys
    (
        dict,
        {
            "wireRadius", "feedSpeed", "wireDensity", "dropletRadius",
            "detachmentFrequency", "temperature", "position",
            "longitudinalSign"
        }
    );
    wire.wireRadius = ldna::getChecked<scalar>
    (
        dict, "wireRadius", interval::open(0, limits::length)
    );
    wire.feedSpeed = ldna::getChecked<scalar>
    (
        dict, "feedSpeed", interval::open(0, limits::speed)
    );
    wire.wireDensity = ldna::getCheckedOrDefault<scalar>
    (
        dict, "wireDensity", interval::openClosed(0, limits::density),
        defaults.wireDensity
    );

    const scalar wireVolumeRate =
        wire.feedSpeed*pi*sqr(wire.wireRadius);
    const bool hasRadius = dict.found("dropletRadius");
    const bool hasFrequency = dict.found("detachmentFrequency");
    if (hasRadius == hasFrequency)
    {
        FatalIOErrorInFunction(dict)
            << "Give exactly one of 'dropletRadius' and"
            << " 'detachmentFrequency' for wire " << wire.name
            << " (the other follows from eq. 16)" << exit(FatalIOError);
    }
    if (hasRadius)
    {
        wire.dropletRadius = ldna::getChecked<scalar>
        (
            dict, "dropletRadius", interval::open(0, limits::length)
        );
        wire.frequency =
            wireVolumeRate/(4.0/3.0*pi*pow3(wire.dropletRadius));
    }
    else
    {
        wire.frequency = ldna::getChecked<scalar>
        (
            dict, "detachmentFrequency",
            interval::openClosed(0, limits::frequency)
        );
        wire.dropletRadius =
            cbrt(3*wireVolumeRate/wire.frequency/(4*pi));
    }

    const scalar largest =
        2*wire.dropletRadius*(irregularStart_ ? irregularDiameterFactor_ : 1);
    if (largest >= defaults.domainSize)
    {
        FatalIOErrorInFunction(dict)
            << "The droplets of wire " << wire.name << " ("
            << largest << " m across) must be smaller than the domain,"
            << " whose smallest extent is " << defaults.domainSize << " m"
            << exit(FatalIOError);
    }

    const scalar dropletTemperature = 2100;
    wire.temperature = ldna::getCheckedOrDefault<scalar>
    (
        dict, "temperature", interval::open(0, limits::temperature),
        dropletTemperature
    );
    wire.enthalpy =
        mixture.metal().sensibleEnthalpy(wire.temperature)
      + mixture.metal().equilibriumLiquidFraction(wire.temperature)
       *mixture.metal().latentHeat();

    wire.position =
        dict.found("position")
      ? dict.get<vector>("position")
      : defaults.position + k*defaults.spacing*spacingDirection;

    const scalar sign = (k % 2 == 0) ? -1 : 1;
    wire.longitudinalSign = dict.lookupOrDefault<scalar>
    (
        "longitudinalSign", sign
    );
    if (mag(mag(wire.longitudinalSign) - 1) > SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'longitudinalSign' must be -1 or 1, not "
            << wire.longitudinalSign << exit(FatalIOError);
    }

    wire.irregularPosition =
        wire.position + k*irregularSpacingIncrease_*spacingDirection;
    checkResolution(wire);
    transfer_->setUp(k);

    wire.addedMass = 0;
    wire.onTime = 0;

    Info<< "    " << name_ << " wire " << wire.name
        << ": mass rate " << wire.massRate() << " kg/s, droplet radius "
        << wire.dropletRadius << " m, frequency " << wire.frequency
        << " 1/s, droplet mass " << wire.massRate()/wire.frequency
        << " kg at " << wire.temperature << " K (enthalpy "
        << wire.enthalpy << " J/kg), source at " << wire.position
        << ", duty fraction " << dutyFraction()
        << ", pulse mass rate " << wire.massRate()/dutyFraction()
        << " kg/s, transfer " << transfer_->type() << endl;

}


void Foam::fv::dropletSource::checkResolution(const wireStream& wire) const
{
    // Cell size at the droplet source: the cube root of the volume of the
    // cell that holds the wire tip
    const label celli = mesh_.findCell(wire.position);
    const scalar cellSize = returnReduce
    (
        celli != -1 ? cbrt(mesh_.V()[celli]) : GREAT,
        minOp<scalar>()
    );
    if (cellSize == GREAT)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'position' in " << coeffs_.name() << ": the droplet"
            << " source of wire " << wire.name << " at " << wire.position
            << " m is outside the mesh, whose bounds are "
            << boundBox(mesh_.points(), true) << exit(FatalIOError);
    }

    // Droplets detach above the workpiece: a source in the metal (the
    // substrate) would add metal where there is no room for it.  Checked on
    // the initial fields only: a restart may find a droplet just inserted
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    const scalar metalAtSource = returnReduce
    (
        celli != -1 ? alpha[celli] : -GREAT,
        maxOp<scalar>()
    );
    if (mesh_.time().value() == 0 && !(metalAtSource < 0.5))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'position' in " << coeffs_.name() << ": the droplet"
            << " source of wire " << wire.name << " at " << wire.position
            << " m lies in metal (" << alphaName_ << " = " << metalAtSource
            << "): it must lie in the gas above the substrate surface"
            << exit(FatalIOError);
    }

    const scalar R = wire.dropletRadius;
    const scalar cellsPerRadius = R/cellSize;

    const scalar minCellsPerRadius = transfer_->minCellsPerRadius();
    if (!(cellsPerRadius >= minCellsPerRadius))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Droplets of wire " << wire.name << " (radius " << R
            << " m) span " << cellsPerRadius << " cells of " << cellSize
            << " m at their source " << wire.position << ": transferring"
            << " them by " << transfer_->type() << " needs at least "
            << minCellsPerRadius << " cells per radius, cells of at most "
            << R/minCellsPerRadius << " m (the LDNA template's levels and"
            << " their cells: ldna mesh-levels)"
            << exit(FatalIOError);
    }
    if (!(cellsPerRadius >= resolvedCellsPerRadius))
    {
        WarningInFunction
            << "Droplets of wire " << wire.name << " (radius " << R
            << " m) span " << cellsPerRadius << " cells of " << cellSize
            << " m at their source: the droplet shape is under-resolved"
            << " (fewer than " << resolvedCellsPerRadius
            << " cells per radius; cells of at most "
            << R/resolvedCellsPerRadius << " m resolve it: ldna mesh-levels"
            << " lists the LDNA template's levels and their cells)"
            << endl;
    }
}


// ************************************************************************* //
