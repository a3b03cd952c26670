/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "laserBeam.H"
#include "checkedInput.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"

using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * * //

namespace
{

// Default oscillation: 6.6 mm at 10 Hz across the seam (LZH 2022, paper)
const Foam::scalar defaultOscillationAmplitude = 6.6e-3;
const Foam::scalar defaultOscillationFrequency = 10;

// Default distance from the laser optics to the workpiece [m]
const Foam::scalar defaultSourceDistance = 0.3;

// Largest beam power [W], radius and oscillation amplitude [m], frequency
// [1/s] and source distance [m] (the project's length limit) accepted:
// beyond welding lasers by orders of magnitude, but finite in every product
// of a step
const Foam::scalar maxPower = 1e6;
const Foam::scalar maxLength = 0.1;
const Foam::scalar maxFrequency = 1e4;
const Foam::scalar maxSourceDistance = Foam::ldna::limits::length;

// The Gaussian beam of eq. 48 holds all but exp(-3 k^2) of its power within
// k beam radii; pixels cover 2 radii (a share of 6e-6 left out, given to the
// pixels by normalisation)
const Foam::scalar gaussianExtent = 2;

} // End anonymous namespace


const Foam::Enum<Foam::laserBeam::beamProfile>
Foam::laserBeam::beamProfileNames
({
    { beamProfile::gaussian, "gaussian" },
    { beamProfile::topHat, "topHat" },
});


const Foam::wordList Foam::laserBeam::keys
({
    "power", "beamRadius", "profile", "position", "offset", "oscillation",
    "oscillationAmplitude", "oscillationFrequency", "oscillationDirection",
    "angle", "verticalDirection", "tiltDirection", "sourceDistance"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserBeam::laserBeam(const dictionary& dict)
:
    dict_(dict),
    radius_(0),
    topHat_(false),
    position_(Zero),
    oscillationAmplitude_(0),
    oscillationFrequency_(0),
    oscillationDirection_(0, 1, 0),
    angle_(0),
    verticalDirection_(0, 0, 1),
    tiltDirection_(1, 0, 0),
    sourceDistance_(defaultSourceDistance)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserBeam::read(const dictionary& dict)
{
    using ldna::interval;

    dict_ = dict;

    power_ = Function1<scalar>::New("power", dict);
    radius_ = ldna::getChecked<scalar>
    (
        dict, "beamRadius", interval::openClosed(0, maxLength)
    );

    topHat_ =
        ldna::getChoiceOrDefault
        (
            dict, "profile", beamProfileNames, beamProfile::gaussian
        )
     == beamProfile::topHat;

    position_ = dict.get<point>("position");
    for (label i = 0; i < vector::nComponents; ++i)
    {
        ldna::checkValue
        (
            dict, "position", position_[i],
            interval::closed(-maxSourceDistance, maxSourceDistance)
        );
    }

    offset_.clear();
    if (dict.found("offset"))
    {
        offset_ = Function1<vector>::New("offset", dict);
    }

    oscillation_.clear();
    if (dict.found("oscillation"))
    {
        oscillation_ = Function1<scalar>::New("oscillation", dict);
    }
    oscillationAmplitude_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "oscillationAmplitude", interval::closed(0, maxLength),
        defaultOscillationAmplitude
    );
    oscillationFrequency_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "oscillationFrequency", interval::closed(0, maxFrequency),
        defaultOscillationFrequency
    );

    const auto unitVector = [&](const word& key, const vector& deflt)
    {
        return ldna::getDirection(dict, key, &deflt);
    };
    oscillationDirection_ = unitVector("oscillationDirection", vector(0, 1, 0));
    verticalDirection_ = unitVector("verticalDirection", vector(0, 0, 1));
    tiltDirection_ = unitVector("tiltDirection", vector(1, 0, 0));

    angle_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "angle", interval::open(-90, 90), 0
    );
    const scalar phi = degToRad(angle_);
    ldna::checkValue
    (
        dict, "tiltDirection",
        mag(cos(phi)*verticalDirection_ + sin(phi)*tiltDirection_),
        interval::open(SMALL, GREAT),
        "the beam direction it makes with verticalDirection and angle"
    );

    sourceDistance_ = ldna::getCheckedOrDefault<scalar>
    (
        dict, "sourceDistance", interval::openClosed(0, maxSourceDistance),
        defaultSourceDistance
    );
}


Foam::scalar Foam::laserBeam::power(const scalar t) const
{
    const scalar P = power_->value(t);
    ldna::checkValue
    (
        dict_, "power", P, ldna::interval::closed(0, maxPower),
        "at t = " + Foam::name(t) + " s"
    );
    return P;
}


Foam::point Foam::laserBeam::target(const scalar t) const
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

    p += displacement*oscillationDirection_;

    for (label i = 0; i < vector::nComponents; ++i)
    {
        ldna::checkValue
        (
            dict_, "position + offset + oscillation", p[i],
            ldna::interval::closed(-maxSourceDistance, maxSourceDistance),
            "the target at t = " + Foam::name(t) + " s"
        );
    }
    return p;
}


Foam::vector Foam::laserBeam::direction(const scalar t) const
{
    const scalar phi = degToRad(angle_);
    return -normalised(cos(phi)*verticalDirection_ + sin(phi)*tiltDirection_);
}


void Foam::laserBeam::across(const scalar t, vector& e1, vector& e2) const
{
    const vector d = direction(t);
    e1 = normalised
    (
        mag(d ^ tiltDirection_) > 1e-6
      ? (d ^ tiltDirection_) ^ d
      : (d ^ oscillationDirection_) ^ d
    );
    e2 = d ^ e1;
}


void Foam::laserBeam::pixels
(
    const label nAcross,
    DynamicList<vector2D>& centres,
    DynamicList<scalar>& shares
) const
{
    // The exact integral of the Gaussian over each pixel (separable, erf),
    // or the pixels whose centre lies in the top hat
    const scalar extent = topHat_ ? radius_ : gaussianExtent*radius_;
    const scalar h = 2*extent/nAcross;
    const scalar k = sqrt(3.0)/radius_;

    centres.clear();
    shares.clear();
    for (label i = 0; i < nAcross; ++i)
    {
        const scalar x0 = -extent + i*h;
        for (label j = 0; j < nAcross; ++j)
        {
            const scalar y0 = -extent + j*h;
            const vector2D centre(x0 + 0.5*h, y0 + 0.5*h);
            const scalar w =
                topHat_
              ? (mag(centre) <= radius_ ? 1 : 0)
              : (erf(k*(x0 + h)) - erf(k*x0))*(erf(k*(y0 + h)) - erf(k*y0));
            if (w > 0)
            {
                centres.append(centre);
                shares.append(w);
            }
        }
    }
    const scalar total = sum(shares);
    for (scalar& share : shares)
    {
        share /= total;
    }
}


void Foam::laserBeam::samples
(
    const label n,
    Random& rndGen,
    DynamicList<vector2D>& positions,
    DynamicList<scalar>& shares
) const
{
    // Gaussian exp(-3 r^2/r_l^2) = exp(-r^2/(2 s^2)), s^2 = r_l^2/6
    const scalar s = radius_/sqrt(6.0);

    positions.clear();
    shares.clear();
    for (label rayi = 0; rayi < n; ++rayi)
    {
        const scalar u = rndGen.sample01<scalar>();
        const scalar r =
            topHat_
          ? radius_*sqrt(u)
          : s*sqrt(-2*Foam::log(max(1 - u, VSMALL)));
        const scalar theta = twoPi*rndGen.sample01<scalar>();
        positions.append(vector2D(r*cos(theta), r*sin(theta)));
        shares.append(scalar(1)/n);
    }
}


// ************************************************************************* //
