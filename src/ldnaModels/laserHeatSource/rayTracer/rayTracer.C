/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "rayTracer.H"
#include "processorPolyPatch.H"
#include "globalMeshData.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * //

namespace
{

// Cells a walk to the next start point may cross before the octree search
// takes over (starts lie a few cells apart)
const Foam::label maxWalkCells = 1000;

// Relative margin of the processor's bounds (points on its faces)
const Foam::scalar boundsMargin = 1e-6;

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rayTracer::rayTracer(const polyMesh& mesh)
:
    mesh_(mesh),
    cells_(mesh),
    localBounds_(mesh.points(), false),
    lastStart_(Zero),
    lastStartCell_(-1)
{
    localBounds_.inflate(boundsMargin);

    // Built on demand by collective operations: build them here, where
    // every processor comes, not in a search only some processors make
    if (Pstream::parRun())
    {
        (void)mesh.tetBasePtIs();
        (void)mesh.globalData();
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::rayTracer::walk
(
    const point& from,
    label celli,
    const point& to
) const
{
    const scalar length = mag(to - from);
    if (length < VSMALL)
    {
        return celli;
    }
    const vector d = (to - from)/length;

    scalar travelled = 0;
    for (label n = 0; n < maxWalkCells; ++n)
    {
        scalar toExit = 0;
        const convexCells::facePlane* exit =
            cells_.exit(celli, from + travelled*d, d, toExit);
        if (!exit)
        {
            return -1;
        }
        if (travelled + toExit >= length)
        {
            return celli;
        }
        if (exit->next < 0)
        {
            return -1;
        }
        travelled += toExit;
        celli = exit->next;
    }
    return -1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::rayTracer::startCell(const point& p)
{
    if (!localBounds_.contains(p))
    {
        return -1;
    }

    label celli =
        lastStartCell_ >= 0 ? walk(lastStart_, lastStartCell_, p) : -1;
    if (celli < 0)
    {
        celli = mesh_.findCell(p);
    }
    if (celli >= 0)
    {
        lastStart_ = p;
        lastStartCell_ = celli;
    }
    return celli;
}


void Foam::rayTracer::trace
(
    DynamicList<laserRay>& rays,
    laserRay::trackingData& td
) const
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    // Neighbour processors, and for each processor patch the index of the
    // same patch among the neighbour's processor patches
    const labelList& neighbourProcs =
        Pstream::parRun() ? mesh_.globalData()[Pstream::myProcNo()] : labelList();
    labelList neighbourIndex(Pstream::nProcs(), -1);
    forAll(neighbourProcs, i)
    {
        neighbourIndex[neighbourProcs[i]] = i;
    }

    // Per neighbour and ray: the patch index there, the face in the patch,
    // the events and steps without progress (labels); position, direction
    // and surface normal (vectors); power
    List<DynamicList<label>> sendLabels(neighbourProcs.size());
    List<DynamicList<vector>> sendVectors(neighbourProcs.size());
    List<DynamicList<scalar>> sendPowers(neighbourProcs.size());

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);

    while (true)
    {
        forAll(neighbourProcs, i)
        {
            sendLabels[i].clear();
            sendVectors[i].clear();
            sendPowers[i].clear();
        }

        for (laserRay& ray : rays)
        {
            const label facei = ray.track(td);
            if (facei < 0)
            {
                continue;
            }

            const label patchi = patches.whichPatch(facei);
            const processorPolyPatch& procPatch =
                refCast<const processorPolyPatch>(patches[patchi]);
            const label i = neighbourIndex[procPatch.neighbProcNo()];

            sendLabels[i].append
            (
                mesh_.globalData().processorPatchNeighbours()[patchi]
            );
            sendLabels[i].append(facei - procPatch.start());
            sendLabels[i].append(ray.nEvents());
            sendLabels[i].append(ray.nStuck());
            sendVectors[i].append(ray.position());
            sendVectors[i].append(ray.direction());
            sendVectors[i].append(ray.lastSurfaceNormal());
            sendPowers[i].append(ray.power());
        }
        rays.clear();

        if (!Pstream::parRun())
        {
            break;
        }

        buffers.clear();
        forAll(neighbourProcs, i)
        {
            if (sendPowers[i].size())
            {
                UOPstream toNeighbour(neighbourProcs[i], buffers);
                toNeighbour << sendLabels[i] << sendVectors[i] << sendPowers[i];
            }
        }

        labelList receiveSizes(Pstream::nProcs(), 0);
        buffers.finishedSends(receiveSizes);
        if (!returnReduce(sum(receiveSizes) > 0, orOp<bool>()))
        {
            break;
        }

        const labelList& procPatches = mesh_.globalData().processorPatches();
        for (const label proci : neighbourProcs)
        {
            if (!receiveSizes[proci])
            {
                continue;
            }
            UIPstream fromNeighbour(proci, buffers);
            const labelList labels(fromNeighbour);
            const List<vector> vectors(fromNeighbour);
            const scalarList powers(fromNeighbour);

            forAll(powers, rayi)
            {
                const label* l = &labels[4*rayi];
                const vector* v = &vectors[3*rayi];
                const polyPatch& patch = patches[procPatches[l[0]]];
                rays.append
                (
                    laserRay
                    (
                        v[0], patch.faceCells()[l[1]], v[1], powers[rayi],
                        v[2], l[2], l[3]
                    )
                );
            }
        }
    }
}


// ************************************************************************* //
