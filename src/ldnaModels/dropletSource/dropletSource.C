/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "dropletSource.H"
#include "cellSource.H"
#include "metalGasMixture.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "boundBox.H"
#include "unitConversion.H"
#include "isoCutCell.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;
using Foam::constant::mathematical::twoPi;

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(dropletSource, 0);
    addToRunTimeSelectionTable(option, dropletSource, dictionary);
}

const Foam::Enum<Foam::fv::dropletSource::transferMode>
Foam::fv::dropletSource::transferModeNames
({
    { transferMode::gaussian, "gaussian" },
    { transferMode::insertion, "insertion" },
});
}

// The cut radius of an inserted sphere lies between R and this multiple of
// it: a planar cut falls short of the sphere by less than a third of its
// volume at the 1.5 cells per radius insertion allows
static const Foam::scalar maxCutRadius = 1.5;

// Bisection of the cut radius: stop when the bracket is this share of R
// (the volume then within 3e-12 of its own), or after so many halvings
static const Foam::scalar cutRadiusTolerance = 1e-12;
static const Foam::label maxCutRadiusIterations = 60;


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
    insertion_ =
        ldna::getChoiceOrDefault
        (
            coeffs_, "mode", transferModeNames, transferMode::gaussian
        )
     == transferMode::insertion;

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    UName_ = coeffs_.lookupOrDefault<word>("U", "U");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    // Inserted droplets are no source in any equation
    if (insertion_)
    {
        fieldNames_.clear();
    }
    else
    {
        fieldNames_.setSize(nSourceFields);
        fieldNames_[alphaFieldi] = alphaName_;
        fieldNames_[UFieldi] = UName_;
        fieldNames_[TFieldi] = TName_;
    }
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
    defaults.irregularStart =
        irregularityTime_ > mesh_.time().startTime().value();

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
) const
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
        2*wire.dropletRadius*(defaults.irregularStart ? irregularDiameterFactor_ : 1);
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
    if (!insertion_)
    {
        wire.regular = footprint(wire, wire.position, wire.dropletRadius);
        if (defaults.irregularStart)
        {
            wire.irregular = footprint
            (
                wire,
                wire.irregularPosition,
                irregularDiameterFactor_*wire.dropletRadius
            );
        }
    }

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
        << " kg/s, " << (insertion_ ? "inserted as spheres" : "Gaussian")
        << endl;

}


Foam::fv::dropletSource::gaussianFootprint
Foam::fv::dropletSource::footprint
(
    const wireStream& wire,
    const vector& centre,
    const scalar R
) const
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    // exp(-3 r^2/R^2) is 6e-6 at twice the radius
    const scalar cutoff2 = sqr(2*R);

    DynamicList<label> cells;
    DynamicList<scalar> weights;
    forAll(C, celli)
    {
        const scalar r2 = magSqr(C[celli] - centre);
        if (r2 < cutoff2)
        {
            cells.append(celli);
            weights.append(exp(-3*r2/sqr(R)));
        }
    }

    scalar total = 0;
    forAll(cells, i)
    {
        total += weights[i]*V[cells[i]];
    }
    reduce(total, sumOp<scalar>());

    // A droplet smaller than the cells: the cell containing its centre
    const bool resolved = total > 0;
    if (!resolved)
    {
        cells.clear();
        weights.clear();
        const label celli = mesh_.findCell(centre);
        if (celli != -1)
        {
            cells.append(celli);
            weights.append(1);
            total = V[celli];
        }
        reduce(total, sumOp<scalar>());
    }

    if (!(total > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "The droplet source of wire " << wire.name << " at " << centre
            << " m is outside the mesh, whose bounds are "
            << boundBox(mesh_.points(), true) << exit(FatalIOError);
    }

    gaussianFootprint fp;
    fp.cells.transfer(cells);
    fp.weights.transfer(weights);
    fp.weights /= total;

    // The discrete integral over the analytic one, pi^1.5 R^3/(3 sqrt 3)
    const scalar analytic = pow(pi, 1.5)*pow3(R)/(3*sqrt(3.0));
    Info<< "    " << name_ << " wire " << wire.name << ": droplet of radius "
        << R << " m on " << returnReduce(fp.cells.size(), sumOp<label>())
        << " cells, discrete/analytic Gaussian integral "
        << (resolved ? total/analytic : 0)
        << (resolved ? "" : " (unresolved: one cell)") << endl;

    return fp;
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

    if (insertion_ && !(cellsPerRadius >= minCellsPerRadius))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Droplets of wire " << wire.name << " (radius " << R
            << " m) span " << cellsPerRadius << " cells of " << cellSize
            << " m at their source " << wire.position << ": inserting them"
            << " as spheres needs at least " << minCellsPerRadius
            << " cells per radius, cells of at most "
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


Foam::scalar Foam::fv::dropletSource::radiusAt
(
    const wireStream& wire,
    const scalar t
) const
{
    return
        t < irregularityTime_
      ? irregularDiameterFactor_*wire.dropletRadius
      : wire.dropletRadius;
}


Foam::vector Foam::fv::dropletSource::centreAt
(
    const wireStream& wire,
    const scalar t
) const
{
    return t < irregularityTime_ ? wire.irregularPosition : wire.position;
}


Foam::List<Foam::scalar> Foam::fv::dropletSource::pulseOnsets
(
    const scalar nu,
    const scalar t0,
    const scalar t1
) const
{
    // A pulse starts where the phase 2 pi nu t + xi passes asin(theta)
    // + 2 pi k
    const scalar a = asin(switchThreshold_);
    const scalar k0 = floor((twoPi*nu*t0 + switchPhase_ - a)/twoPi);
    const scalar k1 = floor((twoPi*nu*t1 + switchPhase_ - a)/twoPi);

    List<scalar> onsets(label(k1 - k0));
    forAll(onsets, i)
    {
        onsets[i] = (a + twoPi*(k0 + 1 + i) - switchPhase_)/(twoPi*nu);
    }
    return onsets;
}


Foam::fv::dropletSource::insertedSphere
Foam::fv::dropletSource::insertSphere
(
    metalGasMixture& mixture,
    volVectorField& U,
    const wireStream& wire,
    const vector& centre,
    const scalar R,
    const vector& velocity
) const
{
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    // The sphere is the iso-surface -r of minus the distance from its
    // centre at the mesh points; isoCutCell gives each cell's "submerged"
    // volume fraction, where the point values exceed the iso-value (the
    // liquid side in isoAdvection): inside the sphere
    scalarField minusDistance(-mag(mesh_.points() - centre));
    isoCutCell cutter(mesh_, minusDistance);

    DynamicList<label> candidates;
    forAll(C, celli)
    {
        // Cells whose centre is within the largest cut radius plus the
        // cell's size
        if (mag(C[celli] - centre) <= maxCutRadius*R + 2*cbrt(V[celli]))
        {
            candidates.append(celli);
        }
    }

    // Each candidate's fraction of the sphere cut at radius r, and the
    // sphere's volume on the mesh
    scalarField fractions(candidates.size());
    const auto cutAt = [&](const scalar r)
    {
        scalar volume = 0;
        forAll(candidates, i)
        {
            const label status = cutter.calcSubCell(candidates[i], -r);
            fractions[i] =
                status == -1 ? 1
              : status == 1 ? 0
              : min(cutter.volumeOfFluid(), scalar(1));
            volume += fractions[i]*V[candidates[i]];
        }
        return returnReduce(volume, sumOp<scalar>());
    };

    // The cut is planar within each cell, inside the sphere, so at r = R
    // the sphere falls short of its volume (by 14 % at two cells per
    // radius): the cut radius r >= R that gives the exact volume is found
    // by bisection, which keeps the sphere's shape
    const scalar exactVolume = 4.0/3.0*pi*pow3(R);
    insertedSphere sphere{0, 0, cutAt(R), 0, R};
    if (sphere.cutVolume < exactVolume && cutAt(maxCutRadius*R) > exactVolume)
    {
        scalar low = R;
        scalar high = maxCutRadius*R;
        for (label i = 0; i < maxCutRadiusIterations; ++i)
        {
            const scalar middle = 0.5*(low + high);
            (cutAt(middle) < exactVolume ? low : high) = middle;
            if (high - low < cutRadiusTolerance*R)
            {
                break;
            }
        }
        sphere.cutRadius = high;
    }
    cutAt(sphere.cutRadius);

    DynamicList<label> cells;
    DynamicList<scalar> cellFractions;
    forAll(candidates, i)
    {
        if (fractions[i] > 0)
        {
            cells.append(candidates[i]);
            cellFractions.append(fractions[i]);
        }
    }
    fractions.transfer(cellFractions);
    sphere.cells = returnReduce(cells.size(), sumOp<label>());

    // The cut cells take what the full ones leave of the exact volume (the
    // bisection's remainder, or all of it where the cut radius could not
    // reach it), in proportion to their fractions; a cut cell the scaling
    // would overfill is filled, and the rest shared again among the others
    for (label pass = 0; pass < 20; ++pass)
    {
        scalar fixedVolume = 0;
        scalar scalableVolume = 0;
        forAll(cells, i)
        {
            (fractions[i] < 1 ? scalableVolume : fixedVolume) +=
                fractions[i]*V[cells[i]];
        }
        reduce(fixedVolume, sumOp<scalar>());
        reduce(scalableVolume, sumOp<scalar>());
        if (!(scalableVolume > 0))
        {
            break;
        }
        const scalar scale =
            max(exactVolume - fixedVolume, scalar(0))/scalableVolume;
        forAll(fractions, i)
        {
            if (fractions[i] < 1)
            {
                fractions[i] = min(scale*fractions[i], scalar(1));
            }
        }
        if (mag(scale - 1) < 1e-12)
        {
            break;
        }
    }

    const volScalarField& alpha1 = mixture.alpha1();
    const volScalarField& rho1 = mixture.rho1();
    const volScalarField& rho2 = mixture.rho2();

    forAll(cells, i)
    {
        const label celli = cells[i];
        const scalar f = fractions[i];
        sphere.volume += f*V[celli];

        // The droplet displaces the gas it takes the place of
        const scalar a = alpha1[celli];
        const scalar dAlpha = f*(1 - a);
        const scalar r1 = rho1[celli];
        const scalar r2 = rho2[celli];

        // Its metal, alpha1, the composition and the enthalpy (mixture)
        const scalar rFiller =
            mixture.addFiller(celli, dAlpha, wire.enthalpy, wire.temperature);

        // Momentum per unit volume, before and after
        const scalar rhoOld = a*r1 + (1 - a)*r2;
        const scalar rhoNew = rhoOld + dAlpha*(rFiller - r2);
        U[celli] =
            (
                (rhoOld - dAlpha*r2)*U[celli] + dAlpha*rFiller*velocity
            )/rhoNew;

        sphere.mass += dAlpha*rFiller*V[celli];
    }

    reduce(sphere.mass, sumOp<scalar>());
    reduce(sphere.volume, sumOp<scalar>());
    return sphere;
}


void Foam::fv::dropletSource::reportInsertion
(
    const label wirei,
    const scalar onset,
    const vector& centre,
    const scalar R,
    const insertedSphere& sphere
)
{
    if (!insertionFile_.valid())
    {
        insertionFile_.reset(new tableFile(mesh_, name_, "insertions"));
        insertionFile_->writeHeader
        (
            "Droplets inserted as spheres, one row each: the wire (1, 2 ..."
            " in the order of 'wires'), its pulse's onset [s], the centre [m]"
            " and radius [m], the cells reached, the volume the cells cut at"
            " the radius give [m3], the radius of the cut that gives the"
            " sphere's volume [m], the volume put in [m3] and the metal mass"
            " added [kg]",
            {
                "wire", "onset", "centreX", "centreY", "centreZ", "radius",
                "cells", "cutVolume", "cutRadius", "volume", "mass"
            }
        );
    }
    insertionFile_->writeRow
    (
        {
            scalar(wirei + 1), onset, centre.x(), centre.y(), centre.z(), R,
            scalar(sphere.cells), sphere.cutVolume, sphere.cutRadius,
            sphere.volume, sphere.mass
        }
    );
}


void Foam::fv::dropletSource::writeMassFileHeader()
{
    wordList columns;
    for (const wireStream& wire : wires_)
    {
        for (const char* column : {"addedMass", "onTime", "dutyFraction"})
        {
            columns.append(wire.name + '_' + column);
        }
    }
    massFile_.writeHeader
    (
        "Per wire: metal added [kg] and time switched on [s] since the"
        " start of the run, and the switch's duty fraction",
        columns
    );
}


void Foam::fv::dropletSource::report()
{
    const Time& time = mesh_.time();
    const scalar elapsed = time.value() - time.startTime().value();

    scalarList row;
    for (const wireStream& wire : wires_)
    {
        const scalar duty = elapsed > 0 ? wire.onTime/elapsed : 0;
        if (log_)
        {
            Info<< type() << ' ' << name_ << ": wire " << wire.name
                << " added mass = " << wire.addedMass
                << " kg, on time = " << wire.onTime
                << " s, duty fraction = " << duty << endl;
        }
        row.append(wire.addedMass);
        row.append(wire.onTime);
        row.append(duty);
    }

    massFile_.writeRow(row);
}


Foam::scalar Foam::fv::dropletSource::switchOnTime
(
    const scalar nu,
    const scalar t0,
    const scalar t1
) const
{
    // In the phase phi = 2 pi nu t + xi the switch is on for
    // phi mod 2 pi in (asin theta, pi - asin theta)
    const scalar a = asin(switchThreshold_);
    const scalar width = pi - 2*a;

    auto onPhase = [&](const scalar phi)
    {
        const scalar periods = floor(phi/twoPi);
        const scalar r = phi - periods*twoPi;
        return periods*width + min(max(r - a, scalar(0)), width);
    };

    const scalar phi0 = twoPi*nu*t0 + switchPhase_;
    const scalar phi1 = twoPi*nu*t1 + switchPhase_;

    return (onPhase(phi1) - onPhase(phi0))/(twoPi*nu);
}


Foam::vector Foam::fv::dropletSource::dropletVelocity
(
    const wireStream& wire,
    const scalar t
) const
{
    const scalar nuP = parallelityFrequency_;
    const scalar alpha = degToRad
    (
        0.5*maxLongitudinalAngle_*(sin(twoPi*nuP*(t - 0.25/nuP)) + 1)
    );
    const scalar beta = degToRad(transverseAngle_);

    const scalar vxz = speed_*cos(beta);
    return vector
    (
        wire.longitudinalSign*vxz*sin(alpha),
        speed_*sin(beta),
       -vxz*cos(alpha)
    );
}


void Foam::fv::dropletSource::deposit
(
    const gaussianFootprint& fp,
    const scalar massRate,
    const vector& velocity,
    const scalar enthalpy
)
{
    forAll(fp.cells, i)
    {
        const label celli = fp.cells[i];
        const scalar S = massRate*fp.weights[i];
        massSource_[celli] += S;
        momentumSource_[celli] += S*velocity;
        enthalpySource_[celli] += S*enthalpy;
    }
}


void Foam::fv::dropletSource::update()
{
    const Time& time = mesh_.time();
    if (timeIndex_ == time.timeIndex())
    {
        return;
    }
    timeIndex_ = time.timeIndex();

    massSource_ = 0;
    enthalpySource_ = 0;
    momentumSource_ = Zero;

    const scalar t1 = time.value();
    const scalar dt = time.deltaTValue();
    const scalar t0 = t1 - dt;
    const scalar ti = irregularityTime_;

    for (wireStream& wire : wires_)
    {
        // Mass rate while the switch is on: one droplet per pulse
        const scalar pulseRate = wire.massRate()/dutyFraction();

        // Irregular start, then regular droplets
        const scalar bounds[3] = {t0, min(max(ti, t0), t1), t1};
        for (label segment = 0; segment < 2; ++segment)
        {
            const scalar ta = bounds[segment];
            const scalar tb = bounds[segment + 1];
            if (tb <= ta)
            {
                continue;
            }

            const bool irregular = segment == 0;
            const scalar on = switchOnTime(wire.frequency, ta, tb);
            const scalar mass =
                pulseRate*on*(irregular ? pow3(irregularDiameterFactor_) : 1);

            if (mass > 0)
            {
                deposit
                (
                    irregular ? wire.irregular : wire.regular,
                    mass/dt,
                    dropletVelocity(wire, 0.5*(ta + tb)),
                    wire.enthalpy
                );
            }

            wire.addedMass += mass;
            wire.onTime += on;
        }
    }

    report();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::dropletSource::dropletSource
(
    const word& sourceName,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(sourceName, modelType, dict, mesh),
    speed_(0),
    transverseAngle_(0),
    maxLongitudinalAngle_(0),
    parallelityFrequency_(0),
    switchPhase_(0),
    switchThreshold_(0),
    irregularityTime_(0),
    irregularDiameterFactor_(1),
    irregularSpacingIncrease_(0),
    insertion_(false),
    log_(true),
    timeIndex_(-1),
    massSource_(mesh.nCells(), Zero),
    enthalpySource_(mesh.nCells(), Zero),
    momentumSource_(mesh.nCells(), Zero),
    massFile_(mesh, sourceName, "droplets")
{
    readCoeffs();
    writeMassFileHeader();
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fv::dropletSource::dutyFraction() const
{
    return (pi - 2*asin(switchThreshold_))/twoPi;
}


void Foam::fv::dropletSource::addSup
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
        eqn += cellSource(eqn, name_ + ":massSource", massSource_);
    }
    else if (fieldi == TFieldi)
    {
        // The solver lets added metal arrive at the enthalpy h1 of the cell
        // at the current iterate; the droplet brings h1(T_d): the difference
        // S (h1(T_d) - h1), explicit, so that the energy added in the step
        // is exactly S h1(T_d) and the liquid-fraction projection of the
        // solver decides how the cell melts
        const metalGasMixture& mixture =
            mesh_.lookupObject<metalGasMixture>("thermophysicalProperties");
        const volScalarField h1(mixture.h1());

        eqn += cellSource
        (
            eqn,
            name_ + ":enthalpySource",
            scalarField(enthalpySource_ - massSource_*h1.primitiveField())
        );
    }
}


void Foam::fv::dropletSource::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    update();

    eqn += cellSource(eqn, name_ + ":momentumSource", momentumSource_);
}


bool Foam::fv::dropletSource::insert
(
    metalGasMixture& mixture,
    volVectorField& U
)
{
    if (!insertion_)
    {
        return false;
    }

    const Time& time = mesh_.time();
    const scalar t1 = time.value();
    const scalar t0 = t1 - time.deltaTValue();

    bool inserted = false;
    forAll(wires_, wirei)
    {
        wireStream& wire = wires_[wirei];
        for (const scalar onset : pulseOnsets(wire.frequency, t0, t1))
        {
            // Where the droplet has flown since it detached within the step
            // (ballistically), so that its position does not depend on the
            // time steps
            const vector velocity = dropletVelocity(wire, onset);
            const vector centre =
                centreAt(wire, onset) + (t1 - onset)*velocity;
            const scalar R = radiusAt(wire, onset);
            const insertedSphere sphere =
                insertSphere(mixture, U, wire, centre, R, velocity);
            wire.addedMass += sphere.mass;
            reportInsertion(wirei, onset, centre, R, sphere);
            inserted = true;
        }
        wire.onTime += switchOnTime(wire.frequency, t0, t1);
    }

    report();

    return inserted;
}


bool Foam::fv::dropletSource::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }

    return false;
}


// ************************************************************************* //
