/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "laserRay.H"
#include "mathematicalConstants.H"
#include <complex>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebug(Cloud<laserRay>, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserRay::trackingData::trackingData
(
    Cloud<laserRay>& cloud,
    const scalarField& alpha,
    const scalarField& absorptivity,
    const vectorField& normal,
    const scalar mu,
    const bool monteCarlo,
    const bool specular,
    const bool fresnel,
    const scalar nRefraction,
    const scalar kExtinction,
    const scalar segmentLength,
    const label maxEvents,
    const scalar powerCutoff,
    Random& rndGen,
    scalarField& absorbed
)
:
    particle::trackingData(cloud),
    alpha(alpha),
    absorptivity(absorptivity),
    normal(normal),
    mu(mu),
    monteCarlo(monteCarlo),
    specular(specular),
    fresnel(fresnel),
    nRefraction(nRefraction),
    kExtinction(kExtinction),
    segmentLength(segmentLength),
    maxEvents(maxEvents),
    powerCutoff(powerCutoff),
    rndGen(rndGen),
    absorbed(absorbed),
    escaped(0),
    scattered(0),
    stopped(0)
{}


Foam::laserRay::laserRay
(
    const polyMesh& mesh,
    const point& position,
    const label celli,
    const vector& direction,
    const scalar segmentLength,
    const scalar power,
    const scalar opticalDepth
)
:
    particle(mesh, position, celli),
    p0_(position),
    p1_(position + segmentLength*direction),
    surfaceNormal_(Zero),
    power_(power),
    opticalDepth_(opticalDepth),
    nEvents_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::laserRay::fresnelAbsorptivity
(
    const scalar cosTheta,
    const scalar n,
    const scalar k
)
{
    typedef std::complex<scalar> complexScalar;

    const scalar c = min(max(cosTheta, scalar(0)), scalar(1));
    const complexScalar N2 = complexScalar(n, k)*complexScalar(n, k);
    const complexScalar root = std::sqrt(N2 - complexScalar(1 - c*c, 0));

    const scalar rs = std::norm((c - root)/(c + root));
    const scalar rp = std::norm((N2*c - root)/(N2*c + root));

    return 1 - 0.5*(rs + rp);
}


void Foam::laserRay::escape(trackingData& td)
{
    td.escaped += power_;
    power_ = 0;
    td.keepParticle = false;
}


void Foam::laserRay::interact(trackingData& td, const label celli)
{
    const vector d = normalised(p1_ - p0_);
    vector n = td.normal[celli];
    if (magSqr(n) < 0.5)
    {
        // Below the interface cells: the surface the ray came in through
        n = surfaceNormal_;
    }
    if (magSqr(n) < 0.5)
    {
        // No interface crossed (the ray started in the metal): as if at
        // normal incidence
        n = -d;
    }

    const scalar a =
        td.fresnel
      ? fresnelAbsorptivity(mag(d & n), td.nRefraction, td.kExtinction)
      : td.absorptivity[celli];

    const scalar absorbed = a*power_;
    td.absorbed[celli] += absorbed;
    power_ -= absorbed;

    if (power_ < td.powerCutoff || ++nEvents_ > td.maxEvents)
    {
        td.stopped += power_;
        power_ = 0;
        td.keepParticle = false;
        return;
    }

    vector dNew;
    if (td.specular)
    {
        dNew = d - 2*(d & n)*n;
    }
    else
    {
        // Uniform on the unit sphere
        const scalar z = 2*td.rndGen.sample01<scalar>() - 1;
        const scalar phi =
            constant::mathematical::twoPi*td.rndGen.sample01<scalar>();
        const scalar r = sqrt(max(1 - z*z, scalar(0)));
        dNew = vector(r*cos(phi), r*sin(phi), z);
    }

    p0_ = position();
    p1_ = p0_ + td.segmentLength*normalised(dNew);
    stepFraction() = 0;
    opticalDepth_ = -log(max(1 - td.rndGen.sample01<scalar>(), VSMALL));
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
        if (magSqr(td.normal[celli]) > 0.5)
        {
            surfaceNormal_ = td.normal[celli];
        }
        const scalar f = 1 - stepFraction();
        const vector s = f*(p1_ - p0_) - deviationFromMeshCentre();
        const scalar sMag = mag(s);
        const scalar attenuation = td.mu*max(td.alpha[celli], scalar(0));
        const point x0 = position();

        if (td.monteCarlo && attenuation*sMag > opticalDepth_)
        {
            // The interaction lies on this segment: track up to it, or to
            // the face if that comes first
            const scalar frac = opticalDepth_/(attenuation*sMag);
            trackToAndHitFace(frac*s, frac*f, cloud, td);
            const scalar ds = mag(position() - x0);
            opticalDepth_ = max(opticalDepth_ - attenuation*ds, scalar(0));

            if (td.keepParticle && !onFace())
            {
                interact(td, celli);
            }
        }
        else
        {
            trackToAndHitFace(s, f, cloud, td);
            const scalar ds = mag(position() - x0);

            if (td.monteCarlo)
            {
                opticalDepth_ -= attenuation*ds;
            }
            else if (power_ > 0)
            {
                const scalar lost = power_*(1 - exp(-attenuation*ds));
                const scalar absorbed = td.absorptivity[celli]*lost;
                td.absorbed[celli] += absorbed;
                td.scattered += lost - absorbed;
                power_ -= lost;

                if (td.keepParticle && power_ < td.powerCutoff)
                {
                    td.stopped += power_;
                    power_ = 0;
                    td.keepParticle = false;
                }
            }

            if (ds < SMALL*td.segmentLength && ++nStuck > maxStuck)
            {
                td.stopped += power_;
                power_ = 0;
                td.keepParticle = false;
            }
        }
    }

    return td.keepParticle;
}


void Foam::laserRay::hitProcessorPatch(Cloud<laserRay>&, trackingData& td)
{
    td.switchProcessor = true;
}


bool Foam::laserRay::hitPatch(Cloud<laserRay>&, trackingData& td)
{
    if (isA<processorPolyPatch>(mesh().boundaryMesh()[patch()]))
    {
        return false;
    }

    escape(td);
    return true;
}


void Foam::laserRay::hitWallPatch(Cloud<laserRay>&, trackingData& td)
{
    escape(td);
}


// ************************************************************************* //
