/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "dropletSource.H"
#include "metalGasMixture.H"
#include "unitConversion.H"
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
}

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

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


void Foam::fv::dropletSource::update()
{
    const Time& time = mesh_.time();
    if (timeIndex_ == time.timeIndex())
    {
        return;
    }
    timeIndex_ = time.timeIndex();

    transfer_->clearSources();

    const scalar t1 = time.value();
    const scalar dt = time.deltaTValue();
    const scalar t0 = t1 - dt;
    const scalar ti = irregularityTime_;

    forAll(wires_, wirei)
    {
        wireStream& wire = wires_[wirei];

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
                transfer_->spread
                (
                    wirei,
                    irregular,
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
    irregularStart_(false),
    log_(true),
    timeIndex_(-1),
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
    transfer_->addSup(eqn, fieldi);
}


void Foam::fv::dropletSource::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    update();
    transfer_->addSup(eqn, fieldi);
}


bool Foam::fv::dropletSource::insert
(
    metalGasMixture& mixture,
    volVectorField& U
)
{
    if (!transfer_->insertsBodies())
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
            wire.addedMass += transfer_->insert
            (
                mixture, U, wirei, onset, centre, R, velocity
            );
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
