/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "insertion.H"
#include "metalGasMixture.H"
#include "isoCutCell.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dropletTransferModels
{
    defineTypeNameAndDebug(insertion, 0);
    addToRunTimeSelectionTable(dropletTransferModel, insertion, dropletSource);
}
}

constexpr Foam::scalar
Foam::dropletTransferModels::insertion::minCellsPerDropletRadius;


// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * * //

namespace
{

// The cut radius of an inserted sphere lies between R and this multiple of
// it: a planar cut falls short of the sphere by less than a third of its
// volume at the 1.5 cells per radius insertion allows
const Foam::scalar maxCutRadius = 1.5;

// Bisection of the cut radius: stop when the bracket is this share of R
// (the volume then within 3e-12 of its own), or after so many halvings
const Foam::scalar cutRadiusTolerance = 1e-12;
const Foam::label maxCutRadiusIterations = 60;

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::dropletTransferModels::insertion::insertedSphere
Foam::dropletTransferModels::insertion::insertSphere
(
    metalGasMixture& mixture,
    volVectorField& U,
    const fv::dropletSource::wireStream& wire,
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


void Foam::dropletTransferModels::insertion::reportInsertion
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
        insertionFile_.reset
        (
            new tableFile(mesh_, source_.name(), "insertions")
        );
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletTransferModels::insertion::insertion
(
    const fv::dropletSource& source,
    const fvMesh& mesh
)
:
    dropletTransferModel(source, mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dropletTransferModels::insertion::insert
(
    metalGasMixture& mixture,
    volVectorField& U,
    const label wirei,
    const scalar onset,
    const vector& centre,
    const scalar R,
    const vector& velocity
)
{
    const insertedSphere sphere = insertSphere
    (
        mixture, U, source_.wires()[wirei], centre, R, velocity
    );
    reportInsertion(wirei, onset, centre, R, sphere);
    return sphere.mass;
}

// ************************************************************************* //
