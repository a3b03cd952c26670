/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
\*---------------------------------------------------------------------------*/

#include "metalFractionLimiter.H"
#include "checkedInput.H"
#include "fvcSurfaceIntegrate.H"
#include "syncTools.H"
#include "wedgeFvPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::metalFractionLimiter::metalFractionLimiter(const fvMesh& mesh)
:
    mesh_(mesh),
    maxSweeps_(1),
    tolerance_(0),
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

    // The sweeps visit only the internal faces that carry a correction (a
    // face without one adds nothing to its cells' fluxes, so its factor
    // changes no other: in bulk metal and gas, most faces), the boundary
    // faces, and the cells of both: on a fine mesh a sweep over every face
    // and cell cost more than the rest of the metal fraction's solution
    DynamicList<label> correctedFaces(nInternal);
    boolList active(psi.size(), false);
    for (label facei = 0; facei < nInternal; ++facei)
    {
        if (phiCorr[facei] != 0)
        {
            correctedFaces.append(facei);
            active[owner[facei]] = true;
            active[neighbour[facei]] = true;
        }
    }
    for (const fvPatch& patch : mesh_.boundary())
    {
        UIndirectList<bool>(active, patch.faceCells()) = true;
    }
    const labelList activeCells(findIndices(active, true));

    const label nBoundary = mesh_.nFaces() - nInternal;
    scalarField lambda(mesh_.nFaces(), 1);
    scalarField boundaryLambda0(nBoundary);
    scalarField limitedOutflow(psi.size(), 0);
    scalarField limitedInflow(psi.size(), 0);

    for (sweeps_ = 1; sweeps_ <= maxSweeps_; ++sweeps_)
    {
        for (const label celli : activeCells)
        {
            limitedOutflow[celli] = 0;
            limitedInflow[celli] = 0;
        }

        for (const label facei : correctedFaces)
        {
            const scalar f = lambda[facei]*phiCorr[facei];
            if (f > 0)
            {
                limitedOutflow[owner[facei]] += f;
                limitedInflow[neighbour[facei]] += f;
            }
            else
            {
                limitedInflow[owner[facei]] -= f;
                limitedOutflow[neighbour[facei]] -= f;
            }
        }
        forAll(mesh_.boundary(), patchi)
        {
            const fvPatch& patch = mesh_.boundary()[patchi];
            const scalarField& phiCorrp = phiCorr.boundaryField()[patchi];
            forAll(phiCorrp, i)
            {
                const scalar f = lambda[patch.start() + i]*phiCorrp[i];
                if (f > 0)
                {
                    limitedOutflow[patch.faceCells()[i]] += f;
                }
                else
                {
                    limitedInflow[patch.faceCells()[i]] -= f;
                }
            }
        }

        // A cell takes in what it may gain plus what it gives off, and
        // gives off what it may lose plus what it takes in
        scalarField& inFactor = limitedOutflow;
        scalarField& outFactor = limitedInflow;
        for (const label celli : activeCells)
        {
            const scalar out = limitedOutflow[celli];
            const scalar in = limitedInflow[celli];
            inFactor[celli] = max
            (
                min((out + maxGain[celli])/(inflow[celli] + ROOTVSMALL), 1),
                0
            );
            outFactor[celli] = max
            (
                min((in + maxLoss[celli])/(outflow[celli] + ROOTVSMALL), 1),
                0
            );
        }

        // A face's factor: the lesser of its upwind cell's out-factor and
        // its downwind cell's in-factor.  Factors only fall: the sweeps
        // stop when none falls by more than the tolerance
        scalar largestFall = 0;
        for (const label facei : correctedFaces)
        {
            const label own = owner[facei];
            const label nei = neighbour[facei];
            const scalar l = min
            (
                lambda[facei],
                phiCorr[facei] > 0
              ? min(outFactor[own], inFactor[nei])
              : min(inFactor[own], outFactor[nei])
            );
            largestFall = max(largestFall, lambda[facei] - l);
            lambda[facei] = l;
        }
        boundaryLambda0 = scalarField::subField(lambda, nBoundary, nInternal);
        forAll(mesh_.boundary(), patchi)
        {
            const fvPatch& patch = mesh_.boundary()[patchi];
            const scalarField& phiCorrp = phiCorr.boundaryField()[patchi];
            const scalarField& phip = phi.boundaryField()[patchi];
            const bool coupled = psi.boundaryField()[patchi].coupled();

            forAll(phiCorrp, i)
            {
                scalar& l = lambda[patch.start() + i];
                const label celli = patch.faceCells()[i];

                if (isA<wedgeFvPatch>(patch))
                {
                    l = 0;
                }
                // Other boundaries limit only where metal leaves
                else if (coupled || phip[i] + phiCorrp[i] > SMALL*SMALL)
                {
                    l = min
                    (
                        l,
                        phiCorrp[i] > 0 ? outFactor[celli] : inFactor[celli]
                    );
                }
            }
        }

        // Both sides of a processor face take the lesser factor
        syncTools::syncFaceList(mesh_, lambda, minEqOp<scalar>());

        for (label i = 0; i < nBoundary; ++i)
        {
            largestFall =
                max(largestFall, boundaryLambda0[i] - lambda[nInternal + i]);
        }

        if (returnReduce(largestFall, maxOp<scalar>()) <= tolerance_)
        {
            break;
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
    psi.primitiveFieldRef() =
        (rDeltaT*psi.primitiveField() + Su.field() - divPhiCorr)
       /(rDeltaT - Sp.field());
    psi.correctBoundaryConditions();

    Info<< "metalFractionLimiter: " << psi.name() << " limited in "
        << sweeps_ << " sweeps" << endl;
}


// ************************************************************************* //
