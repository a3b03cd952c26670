/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "laserRay.H"
#include "laserAbsorptionModel.H"
#include "processorCyclicPolyPatch.H"

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * //

namespace
{

// Steps in a row without progress (a ray on an edge or vertex passes a few
// cells at zero distance) before a ray counts as stuck
const Foam::label maxStuckSteps = 100;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::laserRay::trackingData::trackingData
(
    const polyMesh& mesh,
    const convexCells& cells,
    const laserAbsorptionModel& model,
    const scalarField& alpha,
    const scalarField& T,
    const vectorField& normal,
    const scalar stuckLength,
    const scalar powerCutoff,
    Random& rndGen,
    scalarField& absorbed
)
:
    mesh(mesh),
    cells(cells),
    model(model),
    alpha(alpha),
    T(T),
    normal(normal),
    stuckLength(stuckLength),
    powerCutoff(powerCutoff),
    rndGen(rndGen),
    absorbed(absorbed),
    reflected(0),
    escaped(0),
    stopped(0)
{}


Foam::laserRay::laserRay()
:
    laserRay(Zero, -1, vector(0, 0, -1), 0)
{}


Foam::laserRay::laserRay
(
    const point& position,
    const label celli,
    const vector& direction,
    const scalar power,
    const vector& surfaceNormal,
    const label nEvents,
    const label nStuck
)
:
    position_(position),
    direction_(normalised(direction)),
    cell_(celli),
    surfaceNormal_(surfaceNormal),
    power_(power),
    nEvents_(nEvents),
    reflectedCell_(-1),
    nStuck_(nStuck)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::laserRay::surfaceNormal
(
    const trackingData& td,
    const label celli
) const
{
    vector n = td.normal[celli];
    if (magSqr(n) < 0.5)
    {
        n = surfaceNormal_;
    }
    if (magSqr(n) < 0.5 || (direction_ & n) >= 0)
    {
        // No interface met, or one seen from behind: normal incidence
        n = -direction_;
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
    direction_ = normalised(d);
}


void Foam::laserRay::stop(trackingData& td, const bool asReflected)
{
    (asReflected ? td.reflected : td.stopped) += power_;
    power_ = 0;
    cell_ = -1;
}


void Foam::laserRay::leave(trackingData& td)
{
    (nEvents_ > 0 ? td.reflected : td.escaped) += power_;
    power_ = 0;
    cell_ = -1;
}


Foam::label Foam::laserRay::track(trackingData& td)
{
    const polyBoundaryMesh& patches = td.mesh.boundaryMesh();

    while (cell_ >= 0)
    {
        const label celli = cell_;
        if (celli != reflectedCell_)
        {
            reflectedCell_ = -1;
        }
        if (magSqr(td.normal[celli]) > 0.5)
        {
            surfaceNormal_ = td.normal[celli];
        }

        scalar toExit = 0;
        const convexCells::facePlane* exit =
            td.cells.exit(celli, position_, direction_, toExit);
        if (!exit)
        {
            // A degenerate cell with no face ahead
            stop(td, false);
            break;
        }

        const scalar toInteraction =
            td.model.interactionDistance(*this, td, celli);

        if (toInteraction < toExit)
        {
            // Interacts inside the cell; the stretch up to there counts
            position_ += toInteraction*direction_;
            td.model.cross(*this, td, celli, toInteraction);
            if (cell_ >= 0)
            {
                td.model.interact(*this, td, celli);
            }
        }
        else
        {
            // Crosses the cell; the stretch counts before the ray passes
            // the face (it may leave the domain there)
            position_ += toExit*direction_;
            td.model.cross(*this, td, celli, toExit);

            nStuck_ = (toExit < td.stuckLength) ? nStuck_ + 1 : 0;
            if (nStuck_ > maxStuckSteps)
            {
                stop(td, false);
            }
            else if (cell_ >= 0 && exit->next >= 0)
            {
                cell_ = exit->next;
            }
            else if (cell_ >= 0)
            {
                // A cyclic patch ends the ray as any other patch does,
                // in a serial and a parallel run alike
                const polyPatch& patch =
                    patches[patches.whichPatch(exit->face)];
                if
                (
                    isA<processorPolyPatch>(patch)
                 && !isA<processorCyclicPolyPatch>(patch)
                )
                {
                    // The neighbour processor continues; cell labels are
                    // local to a processor
                    reflectedCell_ = -1;
                    return exit->face;
                }
                leave(td);
            }
        }

        if (cell_ >= 0 && power_ < td.powerCutoff)
        {
            stop(td, false);
        }
    }

    return -1;
}


// ************************************************************************* //
