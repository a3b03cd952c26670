/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "laserRay.H"
#include "laserAbsorptionModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebug(Cloud<laserRay>, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserRay::trackingData::trackingData
(
    Cloud<laserRay>& cloud,
    const laserAbsorptionModel& model,
    const scalarField& alpha,
    const scalarField& T,
    const vectorField& normal,
    const scalar segmentLength,
    const scalar powerCutoff,
    Random& rndGen,
    scalarField& absorbed
)
:
    particle::trackingData(cloud),
    model(model),
    alpha(alpha),
    T(T),
    normal(normal),
    segmentLength(segmentLength),
    powerCutoff(powerCutoff),
    rndGen(rndGen),
    absorbed(absorbed),
    reflected(0),
    escaped(0),
    stopped(0)
{}


Foam::laserRay::laserRay
(
    const polyMesh& mesh,
    const point& position,
    const label celli,
    const vector& direction,
    const scalar segmentLength,
    const scalar power
)
:
    particle(mesh, position, celli),
    p0_(position),
    p1_(position + segmentLength*direction),
    surfaceNormal_(Zero),
    power_(power),
    nEvents_(0),
    reflectedCell_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::laserRay::surfaceNormal
(
    const trackingData& td,
    const label celli
) const
{
    const vector d = direction();
    vector n = td.normal[celli];
    if (magSqr(n) < 0.5)
    {
        n = surfaceNormal_;
    }
    if (magSqr(n) < 0.5 || (d & n) >= 0)
    {
        // No interface met, or one seen from behind: normal incidence
        n = -d;
    }
    return n;
}


void Foam::laserRay::absorb
(
    trackingData& td,
    const label celli,
    const scalar P
)
{
    td.absorbed[celli] += P;
    power_ -= P;
}


void Foam::laserRay::reflectOut(trackingData& td, const scalar P)
{
    td.reflected += P;
    power_ -= P;
}


void Foam::laserRay::reflect
(
    trackingData& td,
    const label celli,
    const vector& d
)
{
    ++nEvents_;
    reflectedCell_ = celli;
    p0_ = position();
    p1_ = p0_ + td.segmentLength*normalised(d);
    stepFraction() = 0;
}


void Foam::laserRay::stop(trackingData& td, const bool asReflected)
{
    (asReflected ? td.reflected : td.stopped) += power_;
    power_ = 0;
    td.keepParticle = false;
}


void Foam::laserRay::leave(trackingData& td)
{
    (nEvents_ > 0 ? td.reflected : td.escaped) += power_;
    power_ = 0;
    td.keepParticle = false;
}


bool Foam::laserRay::move
(
    Cloud<laserRay>& cloud,
    trackingData& td,
    const scalar
)
{
    td.switchProcessor = false;
    td.keepParticle = true;

    // Guards against a ray stuck on a face (zero-length steps)
    label nStuck = 0;
    const label maxStuck = 100;

    while (td.keepParticle && !td.switchProcessor && stepFraction() < 1)
    {
        const label celli = cell();
        if (celli != reflectedCell_)
        {
            reflectedCell_ = -1;
        }
        if (magSqr(td.normal[celli]) > 0.5)
        {
            surfaceNormal_ = td.normal[celli];
        }

        const scalar f = 1 - stepFraction();
        const vector s = f*(p1_ - p0_) - deviationFromMeshCentre();
        const scalar sMag = mag(s);
        const point x0 = position();

        const scalar toInteraction =
            td.model.interactionDistance(*this, td, celli);
        const bool interacts = toInteraction < sMag;

        // Track up to the interaction, or to the face if that comes first;
        // the stretch crossed counts before the ray passes the face (it
        // may leave the domain there)
        const scalar frac = interacts ? toInteraction/sMag : 1;
        if (frac > 0)
        {
            trackToFace(frac*s, frac*f);
        }
        const scalar ds = mag(position() - x0);
        td.model.cross(*this, td, celli, ds);

        if (frac > 0 && onFace())
        {
            hitFace(frac*s, cloud, td);
        }
        else if (td.keepParticle && interacts)
        {
            td.model.interact(*this, td, celli);
        }

        if (!interacts && ds < SMALL*td.segmentLength && ++nStuck > maxStuck)
        {
            stop(td, false);
        }

        if (td.keepParticle && power_ < td.powerCutoff)
        {
            stop(td, false);
        }
    }

    return td.keepParticle;
}


void Foam::laserRay::hitProcessorPatch(Cloud<laserRay>&, trackingData& td)
{
    // Cell labels are local to the processor
    reflectedCell_ = -1;
    td.switchProcessor = true;
}


bool Foam::laserRay::hitPatch(Cloud<laserRay>&, trackingData& td)
{
    if (isA<processorPolyPatch>(mesh().boundaryMesh()[patch()]))
    {
        return false;
    }

    leave(td);
    return true;
}


void Foam::laserRay::hitWallPatch(Cloud<laserRay>&, trackingData& td)
{
    leave(td);
}


// ************************************************************************* //
