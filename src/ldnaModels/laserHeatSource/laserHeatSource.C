/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "laserHeatSource.H"
#include "fvMatrices.H"
#include "fvcGrad.H"
#include "interfaceDelta.H"
#include "treeBoundBox.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(laserHeatSource, 0);
    addToRunTimeSelectionTable(option, laserHeatSource, dictionary);
}
}

const Foam::Enum<Foam::fv::laserHeatSource::absorptionModel>
Foam::fv::laserHeatSource::absorptionModelNames
({
    { absorptionModel::gaussianSurface, "gaussianSurface" },
    { absorptionModel::beerLambert, "beerLambert" },
    { absorptionModel::monteCarlo, "monteCarlo" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Default attenuation of the paper: Tr = exp(-4) over l = 1 mm (eq. 10-11)
const Foam::scalar defaultTransmittance = Foam::exp(-4.0);
const Foam::scalar defaultPathLength = 1e-3;

// Default oscillation: 6.6 mm at 10 Hz across the seam (LZH 2022, paper)
const Foam::scalar defaultOscillationAmplitude = 6.6e-3;
const Foam::scalar defaultOscillationFrequency = 10;

// The Gaussian beam of eq. 48 holds all but exp(-3 k^2) of its power within
// k beam radii; rays cover 2 radii (a share of 6e-6 left out, given to the
// rays by normalisation)
const Foam::scalar gaussianExtent = 2;

// A ray is stopped below this share of its initial power
const Foam::scalar rayPowerCutoff = 1e-9;

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fv::laserHeatSource::readCoeffs()
{
    model_ = absorptionModelNames.get("absorptionModel", coeffs_);

    power_ = Function1<scalar>::New("power", coeffs_);

    beamRadius_ = coeffs_.get<scalar>("beamRadius");
    if (beamRadius_ <= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "beamRadius " << beamRadius_ << " must be > 0"
            << exit(FatalIOError);
    }

    const word profile(coeffs_.lookupOrDefault<word>("profile", "gaussian"));
    if (profile != "gaussian" && profile != "topHat")
    {
        FatalIOErrorInFunction(coeffs_)
            << "profile " << profile << " must be gaussian or topHat"
            << exit(FatalIOError);
    }
    topHat_ = (profile == "topHat");

    position_ = coeffs_.get<point>("position");

    offset_.clear();
    if (coeffs_.found("offset"))
    {
        offset_ = Function1<vector>::New("offset", coeffs_);
    }

    oscillation_.clear();
    if (coeffs_.found("oscillation"))
    {
        oscillation_ = Function1<scalar>::New("oscillation", coeffs_);
    }
    oscillationAmplitude_ = coeffs_.lookupOrDefault<scalar>
    (
        "oscillationAmplitude", defaultOscillationAmplitude
    );
    oscillationFrequency_ = coeffs_.lookupOrDefault<scalar>
    (
        "oscillationFrequency", defaultOscillationFrequency
    );
    if (oscillationAmplitude_ < 0 || oscillationFrequency_ < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "oscillationAmplitude " << oscillationAmplitude_
            << " and oscillationFrequency " << oscillationFrequency_
            << " must be >= 0" << exit(FatalIOError);
    }

    const auto unitVector = [&](const word& key, const vector& deflt)
    {
        const vector v(coeffs_.lookupOrDefault<vector>(key, deflt));
        if (mag(v) < SMALL)
        {
            FatalIOErrorInFunction(coeffs_)
                << key << ' ' << v << " must not be zero"
                << exit(FatalIOError);
        }
        return v/mag(v);
    };
    oscillationDirection_ = unitVector("oscillationDirection", vector(0, 1, 0));
    verticalDirection_ = unitVector("verticalDirection", vector(0, 0, 1));
    tiltDirection_ = unitVector("tiltDirection", vector(1, 0, 0));

    angle_ = coeffs_.lookupOrDefault<scalar>("angle", 0);
    if (mag(angle_) >= 90)
    {
        FatalIOErrorInFunction(coeffs_)
            << "angle " << angle_ << " must be in (-90, 90) degrees"
            << exit(FatalIOError);
    }

    sourceDistance_ = coeffs_.lookupOrDefault<scalar>("sourceDistance", 0.3);
    if (sourceDistance_ <= 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "sourceDistance " << sourceDistance_ << " must be > 0"
            << exit(FatalIOError);
    }

    const dictionary& mcDict = coeffs_.optionalSubDict("monteCarloCoeffs");
    const dictionary& blDict = coeffs_.optionalSubDict("beerLambertCoeffs");
    const dictionary& rayDict =
        model_ == absorptionModel::monteCarlo ? mcDict : blDict;

    fresnel_ =
        model_ == absorptionModel::monteCarlo && mcDict.found("fresnel");
    if (fresnel_)
    {
        const dictionary& fresnelDict = mcDict.subDict("fresnel");
        nRefraction_ = fresnelDict.get<scalar>("n");
        kExtinction_ = fresnelDict.get<scalar>("k");
        if (nRefraction_ <= 0 || kExtinction_ < 0)
        {
            FatalIOErrorInFunction(fresnelDict)
                << "fresnel n " << nRefraction_ << " must be > 0 and k "
                << kExtinction_ << " >= 0" << exit(FatalIOError);
        }
    }
    else
    {
        nRefraction_ = 1;
        kExtinction_ = 0;
    }

    absorptivity_.clear();
    if (!fresnel_ || coeffs_.found("absorptivity"))
    {
        absorptivity_ = Function1<scalar>::New("absorptivity", coeffs_);
    }

    const scalar transmittance = rayDict.lookupOrDefault<scalar>
    (
        "transmittance", defaultTransmittance
    );
    const scalar pathLength = rayDict.lookupOrDefault<scalar>
    (
        "pathLength", defaultPathLength
    );
    if (transmittance <= 0 || transmittance >= 1 || pathLength <= 0)
    {
        FatalIOErrorInFunction(rayDict)
            << "transmittance " << transmittance << " must be in (0, 1) and "
            << "pathLength " << pathLength << " > 0" << exit(FatalIOError);
    }
    mu_ = -Foam::log(transmittance)/pathLength;

    nRaysAcross_ = blDict.lookupOrDefault<label>("nRaysAcross", 64);
    nRays_ = mcDict.lookupOrDefault<label>("nRays", 10000);
    seed_ = mcDict.lookupOrDefault<label>("seed", 1);
    maxEvents_ = mcDict.lookupOrDefault<label>("maxScatteringEvents", 100);
    const word scattering
    (
        mcDict.lookupOrDefault<word>("scattering", "specular")
    );
    if (nRaysAcross_ < 2 || nRays_ < 1 || maxEvents_ < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "nRaysAcross " << nRaysAcross_ << " must be >= 2, nRays "
            << nRays_ << " >= 1 and maxScatteringEvents " << maxEvents_
            << " >= 0" << exit(FatalIOError);
    }
    if (scattering != "specular" && scattering != "isotropic")
    {
        FatalIOErrorInFunction(mcDict)
            << "scattering " << scattering << " must be specular or isotropic"
            << exit(FatalIOError);
    }
    specular_ = (scattering == "specular");

    alphaName_ = coeffs_.lookupOrDefault<word>("alpha", "alpha.metal");
    TName_ = coeffs_.lookupOrDefault<word>("T", "T");
    log_ = coeffs_.lookupOrDefault<bool>("log", true);

    fieldNames_.setSize(1, TName_);
    applied_.setSize(1, false);

    // Force an update with the new coefficients
    updatedTimeIndex_ = -1;
}


Foam::point Foam::fv::laserHeatSource::target(const scalar t) const
{
    point p = position_;
    if (offset_.valid())
    {
        p += offset_->value(t);
    }

    const scalar displacement =
        oscillation_.valid()
      ? oscillation_->value(t)
      : oscillationAmplitude_*sin(twoPi*oscillationFrequency_*t);

    return p + displacement*oscillationDirection_;
}


Foam::vector Foam::fv::laserHeatSource::direction(const scalar t) const
{
    const scalar phi = degToRad(angle_);
    const point source =
        target(t)
      + sourceDistance_*(cos(phi)*verticalDirection_ + sin(phi)*tiltDirection_);

    return normalised(target(t) - source);
}


Foam::scalar Foam::fv::laserHeatSource::profileShape(const scalar r) const
{
    if (topHat_)
    {
        return r <= beamRadius_ ? 1 : 0;
    }
    return exp(-3*sqr(r/beamRadius_));
}


Foam::tmp<Foam::scalarField>
Foam::fv::laserHeatSource::cellAbsorptivity() const
{
    const volScalarField& T = mesh_.lookupObject<volScalarField>(TName_);

    tmp<scalarField> ta(new scalarField(T.size(), Zero));
    if (!absorptivity_.valid())
    {
        return ta;
    }

    scalarField& a = ta.ref();
    forAll(a, celli)
    {
        a[celli] = absorptivity_->value(T[celli]);
        if (a[celli] < 0 || a[celli] > 1)
        {
            FatalIOErrorInFunction(coeffs_)
                << "absorptivity " << a[celli] << " at T = " << T[celli]
                << " K must be in [0, 1]" << exit(FatalIOError);
        }
    }
    return ta;
}


Foam::scalar Foam::fv::laserHeatSource::surfaceAbsorption
(
    scalarField& absorbed
) const
{
    const scalar t = mesh_.time().value();
    const scalar P = power_->value(t);
    const point c = target(t);
    const vector d = direction(t);

    const volScalarField& alpha = mesh_.lookupObject<volScalarField>(alphaName_);
    const volVectorField deltaNormal(metalSurfaceDeltaNormal(alpha));
    const scalarField a(cellAbsorptivity());

    // Peak flux of the profile (eq. 48, or the top hat)
    const scalar peak =
        topHat_ ? P/(pi*sqr(beamRadius_)) : 3*P/(pi*sqr(beamRadius_));

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    forAll(absorbed, celli)
    {
        const vector rc = C[celli] - c;
        const scalar r = mag(rc - (rc & d)*d);
        absorbed[celli] =
            a[celli]*peak*profileShape(r)
           *max(d & deltaNormal[celli], scalar(0))*V[celli];
    }

    // Everything the surfaces do not absorb is reflected or misses
    return P - gSum(absorbed);
}


Foam::scalar Foam::fv::laserHeatSource::traceRays(scalarField& absorbed)
{
    const scalar t = mesh_.time().value();
    const scalar P = power_->value(t);
    const point c = target(t);
    const vector d = direction(t);
    const bool monteCarlo = (model_ == absorptionModel::monteCarlo);

    // An orthonormal basis across the beam
    const vector e1 = normalised
    (
        mag(d ^ tiltDirection_) > 1e-6
      ? (d ^ tiltDirection_) ^ d
      : (d ^ oscillationDirection_) ^ d
    );
    const vector e2 = d ^ e1;

    // Rays start where their line enters the bounding box of the whole mesh
    const treeBoundBox bounds(boundBox(mesh_.points(), true));
    const scalar segmentLength = 2*bounds.mag();
    const scalar reach = sourceDistance_ + segmentLength;

    // Ray positions across the beam and their powers, the same on every
    // processor (the random numbers for sampling too), so serial and
    // parallel runs start the same rays
    DynamicList<vector2D> across;
    DynamicList<scalar> weight;

    Random rndGen(seed_ + 1000003*mesh_.time().timeIndex());

    if (monteCarlo)
    {
        // Gaussian exp(-3 r^2/r_l^2) = exp(-r^2/(2 s^2)), s^2 = r_l^2/6
        const scalar s = beamRadius_/sqrt(6.0);
        for (label rayi = 0; rayi < nRays_; ++rayi)
        {
            const scalar u = rndGen.sample01<scalar>();
            const scalar r =
                topHat_
              ? beamRadius_*sqrt(u)
              : s*sqrt(-2*Foam::log(max(1 - u, VSMALL)));
            const scalar theta = twoPi*rndGen.sample01<scalar>();
            across.append(vector2D(r*cos(theta), r*sin(theta)));
            weight.append(1);
        }
    }
    else
    {
        // Pixels over the beam: the exact integral of the Gaussian over each
        // pixel (separable, erf), or the pixels whose centre lies in the
        // top hat
        const scalar extent = topHat_ ? beamRadius_ : gaussianExtent*beamRadius_;
        const scalar h = 2*extent/nRaysAcross_;
        const scalar k = sqrt(3.0)/beamRadius_;
        for (label i = 0; i < nRaysAcross_; ++i)
        {
            const scalar x0 = -extent + i*h;
            for (label j = 0; j < nRaysAcross_; ++j)
            {
                const scalar y0 = -extent + j*h;
                const vector2D centre(x0 + 0.5*h, y0 + 0.5*h);
                scalar w;
                if (topHat_)
                {
                    w = mag(centre) <= beamRadius_ ? 1 : 0;
                }
                else
                {
                    w =
                        (erf(k*(x0 + h)) - erf(k*x0))
                       *(erf(k*(y0 + h)) - erf(k*y0));
                }
                if (w > 0)
                {
                    across.append(centre);
                    weight.append(w);
                }
            }
        }
    }

    const scalar weightSum = sum(weight);

    cloud_->clear();

    scalar started = 0;
    forAll(across, rayi)
    {
        const scalar rayPower = P*weight[rayi]/weightSum;
        const point onAxis = c + across[rayi].x()*e1 + across[rayi].y()*e2;
        const point start = onAxis - sourceDistance_*d;

        point entry;
        if (!bounds.intersects(start, start + reach*d, entry))
        {
            continue;
        }
        const point inside = entry + 1e-9*bounds.mag()*d;
        const label celli = mesh_.findCell(inside);
        if (celli < 0)
        {
            continue;
        }

        const scalar opticalDepth =
            monteCarlo ? -Foam::log(max(1 - rndGen.sample01<scalar>(), VSMALL)) : 0;

        cloud_->addParticle
        (
            new laserRay
            (
                mesh_, inside, celli, d, segmentLength, rayPower, opticalDepth
            )
        );
        started += rayPower;
    }
    reduce(started, sumOp<scalar>());

    // Fields the rays see
    const volScalarField& alpha =
        mesh_.lookupObject<volScalarField>(alphaName_);
    // Interface normals out of the metal
    const vectorField normal(-metalInterfaceNormal(fvc::grad(alpha)()));
    const scalarField a(cellAbsorptivity());

    // The random numbers of scattering differ per processor
    Random scatterGen
    (
        seed_ + 1000003*mesh_.time().timeIndex() + 7919*Pstream::myProcNo()
    );

    laserRay::trackingData td
    (
        cloud_(),
        alpha.primitiveField(),
        a,
        normal,
        mu_,
        monteCarlo,
        specular_,
        fresnel_,
        nRefraction_,
        kExtinction_,
        segmentLength,
        maxEvents_,
        rayPowerCutoff*P/max(across.size(), 1),
        scatterGen,
        absorbed
    );

    cloud_->move(cloud_(), td, mesh_.time().deltaTValue());

    scalar escaped = td.escaped + td.scattered + td.stopped;
    reduce(escaped, sumOp<scalar>());

    // Rays that found no cell of the mesh missed the domain
    return escaped + (P - started);
}


void Foam::fv::laserHeatSource::update()
{
    if (updatedTimeIndex_ == mesh_.time().timeIndex())
    {
        return;
    }
    updatedTimeIndex_ = mesh_.time().timeIndex();

    const scalar t = mesh_.time().value();
    const scalar P = power_->value(t);
    if (P < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "power " << P << " W at t = " << t << " s must be >= 0"
            << exit(FatalIOError);
    }

    scalarField absorbed(mesh_.nCells(), Zero);
    const scalar escaped =
        model_ == absorptionModel::gaussianSurface
      ? surfaceAbsorption(absorbed)
      : traceRays(absorbed);

    powerDensity_.primitiveFieldRef() = absorbed/mesh_.V();
    powerDensity_.correctBoundaryConditions();

    if (log_)
    {
        const volScalarField& alpha =
            mesh_.lookupObject<volScalarField>(alphaName_);
        const scalarField alphaClipped
        (
            min(max(alpha.primitiveField(), scalar(0)), scalar(1))
        );
        const scalar byMetal = gSum(alphaClipped*absorbed);
        const scalar byGas = gSum((1 - alphaClipped)*absorbed);

        Info<< type() << ' ' << name_ << ": t = " << t
            << " s, target = " << target(t)
            << ", direction = " << direction(t)
            << ", emitted = " << P
            << " W, absorbed by metal = " << byMetal
            << " W, absorbed by gas = " << byGas
            << " W, escaped = " << escaped
            << " W, imbalance = " << P - byMetal - byGas - escaped
            << " W" << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::laserHeatSource::laserHeatSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    model_(absorptionModel::gaussianSurface),
    beamRadius_(0),
    topHat_(false),
    position_(Zero),
    oscillationAmplitude_(0),
    oscillationFrequency_(0),
    oscillationDirection_(0, 1, 0),
    angle_(0),
    verticalDirection_(0, 0, 1),
    tiltDirection_(1, 0, 0),
    sourceDistance_(0),
    mu_(0),
    nRaysAcross_(0),
    nRays_(0),
    seed_(0),
    specular_(true),
    fresnel_(false),
    nRefraction_(1),
    kExtinction_(0),
    maxEvents_(0),
    log_(true),
    powerDensity_
    (
        IOobject
        (
            name + "PowerDensity",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPower/dimVolume, Zero)
    ),
    updatedTimeIndex_(-1),
    cloud_(new Cloud<laserRay>(mesh, name + "Rays", IDLList<laserRay>()))
{
    readCoeffs();

    Info<< "    absorption model " << absorptionModelNames[model_]
        << ", beam radius " << beamRadius_
        << (topHat_ ? " m (top hat)" : " m (Gaussian)")
        << ", attenuation coefficient " << mu_ << " 1/m" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::laserHeatSource::addSup
(
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    update();
    eqn += powerDensity_;
}


void Foam::fv::laserHeatSource::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::laserHeatSource::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
