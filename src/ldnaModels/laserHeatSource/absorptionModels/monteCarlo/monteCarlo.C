/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "monteCarlo.H"
#include "checkedInput.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace laserAbsorptionModels
{
    defineTypeNameAndDebug(monteCarlo, 0);
    addToRunTimeSelectionTable(laserAbsorptionModel, monteCarlo, dictionary);
}
}

const Foam::Enum<Foam::laserAbsorptionModels::monteCarlo::scattering>
Foam::laserAbsorptionModels::monteCarlo::scatteringNames
({
    { scattering::specular, "specular" },
    { scattering::diffuse, "diffuse" },
});


namespace
{

// The paper's CFX model traced 10,000 rays
const Foam::label defaultRays = 10000;
const Foam::label maxRays = 10000000;
const Foam::label maxSeed = 1000000000;
const Foam::label defaultMaxEvents = 100;
const Foam::label maxEventsLimit = 1000;

// Steps of the random sequence between time steps (a prime, so that the
// sequences of neighbouring seeds do not overlap)
const Foam::label seedStride = 1000003;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserAbsorptionModels::monteCarlo::monteCarlo
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    gaussianSurface(typeName, dict, mesh),
    nRays_(defaultRays),
    seed_(1),
    specular_(true),
    maxEvents_(defaultMaxEvents)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::laserAbsorptionModels::monteCarlo::read(const dictionary& dict)
{
    using ldna::interval;

    laserAbsorptionModel::read(dict);
    ldna::checkKeys
    (
        coeffs_, {"nRays", "seed", "scattering", "maxScatteringEvents"}
    );

    nRays_ = ldna::getCheckedOrDefault<label>
    (
        coeffs_, "nRays", interval::closed(1, maxRays), defaultRays
    );
    seed_ = ldna::getCheckedOrDefault<label>
    (
        coeffs_, "seed", interval::closed(0, maxSeed), 1
    );
    maxEvents_ = ldna::getCheckedOrDefault<label>
    (
        coeffs_, "maxScatteringEvents", interval::closed(0, maxEventsLimit),
        defaultMaxEvents
    );

    specular_ =
        ldna::getChoiceOrDefault
        (
            coeffs_, "scattering", scatteringNames, scattering::specular
        )
     == scattering::specular;
}


void Foam::laserAbsorptionModels::monteCarlo::rays
(
    const laserBeam& beam,
    const label timeIndex,
    DynamicList<vector2D>& across,
    DynamicList<scalar>& shares
) const
{
    // The same on every processor, so serial and parallel runs start the
    // same rays
    Random rndGen(seed_ + seedStride*timeIndex);
    beam.samples(nRays_, rndGen, across, shares);
}


void Foam::laserAbsorptionModels::monteCarlo::interact
(
    laserRay& ray,
    laserRay::trackingData& td,
    const label celli
) const
{
    const vector n = absorbAtSurface(ray, td, celli);

    if (ray.nEvents() >= maxEvents_)
    {
        ray.stop(td, true);
        return;
    }

    const vector d = ray.direction();
    vector reflected;
    if (specular_)
    {
        reflected = d - 2*(d & n)*n;
    }
    else
    {
        // Lambert's cosine law about n
        const vector t1 = normalised
        (
            mag(n.x()) < 0.9 ? vector(1, 0, 0) ^ n : vector(0, 1, 0) ^ n
        );
        const vector t2 = n ^ t1;
        const scalar u = td.rndGen.sample01<scalar>();
        const scalar phi =
            constant::mathematical::twoPi*td.rndGen.sample01<scalar>();
        const scalar r = sqrt(u);
        reflected =
            r*cos(phi)*t1 + r*sin(phi)*t2 + sqrt(max(1 - u, scalar(0)))*n;
    }

    ray.reflect(td, celli, reflected);
}


// ************************************************************************* //
