/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "metalFractionLimiter.H"
#include "checkedInput.H"
#include "fvcSurfaceIntegrate.H"
#include "syncTools.H"
#include "bitSet.H"
#include "wedgeFvPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalFractionLimiter::metalFractionLimiter(const fvMesh& mesh)
:
    mesh_(mesh),
    maxSweeps_(1),
    tolerance_(0),
    traceFraction_(0),
    sweeps_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarField Foam::metalFractionLimiter::faceFactors
(
    const volScalarField& psi,
    const surfaceScalarField& phi,
    const surfaceScalarField& phiCorr,
    const scalarField& Sp,
    const scalarField& Su
)
{
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const scalarField& V = mesh_.V();
    const scalar rDeltaT = 1/mesh_.time().deltaTValue();
    const label nInternal = mesh_.nInternalFaces();
    const scalarField& psiI = psi.primitiveField();

    // The neighbours' extrema within [0, 1], and each cell's unlimited
    // outflow and inflow of the correction
    scalarField psiMax(psi.size(), 0);
    scalarField psiMin(psi.size(), 1);
    scalarField outflow(psi.size(), 0);
    scalarField inflow(psi.size(), 0);

    for (label facei = 0; facei < nInternal; ++facei)
    {
        const label own = owner[facei];
        const label nei = neighbour[facei];

        psiMax[own] = max(psiMax[own], psiI[nei]);
        psiMin[own] = min(psiMin[own], psiI[nei]);
        psiMax[nei] = max(psiMax[nei], psiI[own]);
        psiMin[nei] = min(psiMin[nei], psiI[own]);

        const scalar f = phiCorr[facei];
        if (f > 0)
        {
            outflow[own] += f;
            inflow[nei] += f;
        }
        else
        {
            inflow[own] -= f;
            outflow[nei] -= f;
        }
    }

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchScalarField& psip = psi.boundaryField()[patchi];
        const scalarField& phiCorrp = phiCorr.boundaryField()[patchi];
        const labelUList& cells = mesh_.boundary()[patchi].faceCells();

        if (psip.coupled() || psip.fixesValue())
        {
            const scalarField psiNext
            (
                psip.coupled() ? psip.patchNeighbourField() : psip
            );
            forAll(cells, i)
            {
                psiMax[cells[i]] = max(psiMax[cells[i]], psiNext[i]);
                psiMin[cells[i]] = min(psiMin[cells[i]], psiNext[i]);
            }
        }

        forAll(cells, i)
        {
            const scalar f = phiCorrp[i];
            if (f > 0)
            {
                outflow[cells[i]] += f;
            }
            else
            {
                inflow[cells[i]] -= f;
            }
        }
    }

    // What each cell may gain and lose through the correction: from
    // psi + dt (Su + Sp psiNew - div(phiCorr)) between the extrema
    const scalarField maxGain
    (
        V*((rDeltaT - Sp)*min(psiMax, 1.0) - Su - psiI*rDeltaT)
    );
    const scalarField maxLoss
    (
        V*(Su - (rDeltaT - Sp)*max(psiMin, 0.0) + psiI*rDeltaT)
    );

    // Each sweep sums the limited fluxes of every cell, takes the cells'
    // factors and lowers the faces' factors to them.  A cell whose faces'
    // factors did not change in the last sweep has the same sums and
    // factors, and a face whose cells' factors did not change keeps its
    // factor: after the first sweep only the cells of the faces that
    // changed are visited (on a fine mesh the sweeps over every face and
    // cell cost more than the rest of the metal fraction's solution).
    // Each visited cell sums its faces in increasing face order, as a sweep
    // over all faces does, so the factors are those of full sweeps to the
    // last bit.  Only faces that carry a correction contribute: in bulk
    // metal and gas most faces carry none.
    const cellList& cellFaces = mesh_.cells();
    const labelList& faceOwner = mesh_.faceOwner();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const label nBoundary = mesh_.nFaces() - nInternal;

    // The correction through every face, boundary faces included
    scalarField faceCorr(mesh_.nFaces(), 0);
    SubList<scalar>(faceCorr, nInternal) = phiCorr.primitiveField();
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        SubList<scalar>(faceCorr, patch.size(), patch.start()) =
            phiCorr.boundaryField()[patchi];
    }

    // Boundary faces that carry field values: not those of empty patches
    // (whose fields have no values, as in one- and two-dimensional cases)
    bitSet valuedFace(mesh_.nFaces());
    for (const fvPatch& patch : mesh_.boundary())
    {
        valuedFace.set(labelRange(patch.start(), patch.size()));
    }

    // Each cell's faces that take part (internal faces with a correction,
    // the valued boundary faces), in increasing order; cells without any do
    // not take part
    labelList firstFace(psi.size() + 1, 0);
    DynamicList<label> faces(nInternal/4);
    DynamicList<label> activeCells(psi.size()/4);
    forAll(cellFaces, celli)
    {
        const label begin = faces.size();
        for (const label facei : cellFaces[celli])
        {
            if
            (
                facei < nInternal
              ? faceCorr[facei] != 0
              : valuedFace.test(facei)
            )
            {
                faces.append(facei);
            }
        }
        if (faces.size() > begin)
        {
            std::sort(faces.begin() + begin, faces.end());
            activeCells.append(celli);
        }
        firstFace[celli + 1] = faces.size();
    }

    scalarField lambda(mesh_.nFaces(), 1);
    scalarField inFactor(psi.size(), 1);
    scalarField outFactor(psi.size(), 1);
    scalarField boundaryLambda0(nBoundary);
    // Cells to visit in this sweep, and the cells of faces that changed
    DynamicList<label> visit(activeCells);
    bitSet marked(psi.size());
    DynamicList<label> changed(activeCells.size());

    const auto markCells = [&](const label facei)
    {
        const label own = faceOwner[facei];
        if (marked.set(own))
        {
            changed.append(own);
        }
        if (facei < nInternal && marked.set(neighbour[facei]))
        {
            changed.append(neighbour[facei]);
        }
    };

    for (sweeps_ = 1; sweeps_ <= maxSweeps_; ++sweeps_)
    {
        // A cell takes in what it may gain plus what it gives off, and
        // gives off what it may lose plus what it takes in
        for (const label celli : visit)
        {
            scalar limitedOut = 0;
            scalar limitedIn = 0;
            for (label j = firstFace[celli]; j < firstFace[celli + 1]; ++j)
            {
                const label facei = faces[j];
                // Outward from this cell
                const scalar f =
                    (faceOwner[facei] == celli ? 1 : -1)
                   *lambda[facei]*faceCorr[facei];
                if (f > 0)
                {
                    limitedOut += f;
                }
                else
                {
                    limitedIn -= f;
                }
            }
            inFactor[celli] = max
            (
                min((limitedOut + maxGain[celli])/(inflow[celli] + ROOTVSMALL), 1),
                0
            );
            outFactor[celli] = max
            (
                min((limitedIn + maxLoss[celli])/(outflow[celli] + ROOTVSMALL), 1),
                0
            );
        }

        // A face's factor: the lesser of its upwind cell's out-factor and
        // its downwind cell's in-factor.  Factors only fall: the sweeps
        // stop when none falls by more than the tolerance
        boundaryLambda0 = scalarField::subField(lambda, nBoundary, nInternal);
        scalar largestFall = 0;
        changed.clear();
        for (const label celli : visit)
        {
            for (label j = firstFace[celli]; j < firstFace[celli + 1]; ++j)
            {
                const label facei = faces[j];
                scalar l = lambda[facei];
                if (facei < nInternal)
                {
                    const label own = owner[facei];
                    const label nei = neighbour[facei];
                    l = min
                    (
                        l,
                        faceCorr[facei] > 0
                      ? min(outFactor[own], inFactor[nei])
                      : min(inFactor[own], outFactor[nei])
                    );
                }
                else
                {
                    const label patchi = patches.whichPatch(facei);
                    const fvPatch& patch = mesh_.boundary()[patchi];
                    const label i = facei - patch.start();
                    if (isA<wedgeFvPatch>(patch))
                    {
                        l = 0;
                    }
                    // Other boundaries limit only where metal leaves
                    else if
                    (
                        psi.boundaryField()[patchi].coupled()
                     || phi.boundaryField()[patchi][i] + faceCorr[facei]
                      > SMALL*SMALL
                    )
                    {
                        l = min
                        (
                            l,
                            faceCorr[facei] > 0
                          ? outFactor[celli] : inFactor[celli]
                        );
                    }
                }
                if (l < lambda[facei])
                {
                    largestFall = max(largestFall, lambda[facei] - l);
                    lambda[facei] = l;
                    markCells(facei);
                }
            }
        }

        // Both sides of a processor face take the lesser factor
        syncTools::syncFaceList(mesh_, lambda, minEqOp<scalar>());

        for (label i = 0; i < nBoundary; ++i)
        {
            const label facei = nInternal + i;
            if (lambda[facei] < boundaryLambda0[i])
            {
                largestFall =
                    max(largestFall, boundaryLambda0[i] - lambda[facei]);
                markCells(facei);
            }
        }

        if (returnReduce(largestFall, maxOp<scalar>()) <= tolerance_)
        {
            break;
        }

        visit.clear();
        for (const label celli : changed)
        {
            marked.unset(celli);
            if (firstFace[celli + 1] > firstFace[celli])
            {
                visit.append(celli);
            }
        }
    }
    sweeps_ = min(sweeps_, maxSweeps_);

    return lambda;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::metalFractionLimiter::read(const word& psiName)
{
    // Sweeps beyond this only delay a step whose limiter does not settle
    const label mostSweeps = 1000;

    const dictionary& controls = mesh_.solverDict(psiName);
    maxSweeps_ = ldna::getChecked<label>
    (
        controls, "nLimiterIter", ldna::interval::closed(1, mostSweeps)
    );
    tolerance_ = ldna::getCheckedOrDefault<scalar>
    (
        controls, "limiterTolerance", ldna::interval::closed(0, 1), 0
    );
    // A larger one would remove metal, not the residue of a linear solution
    const scalar largestTraceFraction = 1e-3;
    traceFraction_ = ldna::getCheckedOrDefault<scalar>
    (
        controls, "traceMetalFraction",
        ldna::interval::closed(0, largestTraceFraction), 0
    );
}


void Foam::metalFractionLimiter::correct
(
    volScalarField& psi,
    const surfaceScalarField& phi,
    surfaceScalarField& phiCorr,
    const volScalarField::Internal& Sp,
    const volScalarField::Internal& Su
)
{
    const scalarField lambda(faceFactors(psi, phi, phiCorr, Sp, Su));

    scalarField& phiCorrI = phiCorr.primitiveFieldRef();
    phiCorrI *= scalarField::subField(lambda, mesh_.nInternalFaces());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& patch = mesh_.boundary()[patchi];
        phiCorr.boundaryFieldRef()[patchi] *=
            scalarField::subField(lambda, patch.size(), patch.start());
    }

    scalarField divPhiCorr(psi.size(), 0);
    fvc::surfaceIntegrate(divPhiCorr, phiCorr);

    const scalar rDeltaT = 1/mesh_.time().deltaTValue();
    scalarField& psiI = psi.primitiveFieldRef();
    psiI =
        (rDeltaT*psi.primitiveField() + Su.field() - divPhiCorr)
       /(rDeltaT - Sp.field());

    // The linear solution's residue in the gas
    scalar traceVolume = 0;
    if (traceFraction_ > 0)
    {
        const scalarField& V = mesh_.V();
        forAll(psiI, celli)
        {
            if (psiI[celli] < traceFraction_)
            {
                traceVolume += psiI[celli]*V[celli];
                psiI[celli] = 0;
            }
        }
        reduce(traceVolume, sumOp<scalar>());
    }
    psi.correctBoundaryConditions();

    Info<< "metalFractionLimiter: " << psi.name() << " limited in "
        << sweeps_ << " sweeps";
    if (traceFraction_ > 0)
    {
        Info<< ", trace metal removed: " << traceVolume << " m3";
    }
    Info<< endl;
}


// ************************************************************************* //
