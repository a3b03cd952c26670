/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "layeredConductivity.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Thermal resistance times area [m2 K/W] between the centre of the heat
// capacity of a cell and its face at distance d, the cell's metal fraction
// alpha lying as a layer against the face (thickness 2 alpha d) and its gas
// behind it; metalHeatShare is the metal's share of the cell's heat
// capacity.  Pure gas and pure metal give d/kappa
Foam::scalar layeredHalfResistance
(
    const Foam::scalar d,
    const Foam::scalar alpha,
    const Foam::scalar metalHeatShare,
    const Foam::scalar kappaMetal,
    const Foam::scalar kappaGas
)
{
    const Foam::scalar centre = d*(1 + alpha - metalHeatShare);
    const Foam::scalar metalLayer = 2*alpha*d;
    if (centre <= metalLayer)
    {
        return centre/kappaMetal;
    }
    return metalLayer/kappaMetal + (centre - metalLayer)/kappaGas;
}


// One cell of a face: its distance to the face, metal fraction, metal's
// share of its heat capacity, phase and volume-mean conductivities
struct faceCell
{
    Foam::scalar d, alpha, metalHeatShare, kappaMetal, kappaGas, kappa;
};

Foam::scalar seriesConductivity(const faceCell& lean, const faceCell& rich)
{
    return
        (lean.d + rich.d)
       /(
            layeredHalfResistance
            (
                lean.d, lean.alpha, lean.metalHeatShare,
                lean.kappaMetal, lean.kappaGas
            )
          + rich.d/rich.kappa
        );
}


// Symmetric in a and b, so that both sides of a processor face agree
Foam::scalar layeredFaceConductivity(const faceCell& a, const faceCell& b)
{
    if (a.alpha < b.alpha)
    {
        return seriesConductivity(a, b);
    }
    if (b.alpha < a.alpha)
    {
        return seriesConductivity(b, a);
    }
    return 0.5*(seriesConductivity(a, b) + seriesConductivity(b, a));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField>
Foam::layeredConductivity::faceConductivity
(
    const volScalarField& metal,
    const volScalarField& metalHeatShare,
    const volScalarField& kappaMetal,
    const volScalarField& kappaGas,
    const volScalarField& kappa
)
{
    const fvMesh& mesh = metal.mesh();

    const auto cellOf = [&](const label celli, const scalar d)
    {
        return faceCell
        {
            d, metal[celli], metalHeatShare[celli],
            kappaMetal[celli], kappaGas[celli], kappa[celli]
        };
    };

    tmp<surfaceScalarField> tkappaf
    (
        new surfaceScalarField
        (
            IOobject("kappaf", mesh.time().timeName(), mesh),
            mesh,
            kappa.dimensions()
        )
    );
    surfaceScalarField& kf = tkappaf.ref();

    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    const vectorField& C = mesh.C();
    const vectorField& Cf = mesh.Cf();
    const vectorField& Sf = mesh.Sf();
    const scalarField& magSf = mesh.magSf();

    forAll(owner, facei)
    {
        const vector n(Sf[facei]/magSf[facei]);
        kf[facei] = layeredFaceConductivity
        (
            cellOf(owner[facei], mag(n & (Cf[facei] - C[owner[facei]]))),
            cellOf(neighbour[facei], mag(n & (C[neighbour[facei]] - Cf[facei])))
        );
    }

    forAll(kf.boundaryField(), patchi)
    {
        fvsPatchScalarField& kfp = kf.boundaryFieldRef()[patchi];
        const fvPatch& patch = mesh.boundary()[patchi];
        if (!patch.coupled())
        {
            kfp = kappa.boundaryField()[patchi];
            continue;
        }
        const labelUList& faceCells = patch.faceCells();
        const vectorField nf(patch.nf());
        const vectorField ownerDelta(patch.Cf() - patch.Cn());
        const vectorField delta(patch.delta());
        const scalarField nbrMetal
        (
            metal.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrShare
        (
            metalHeatShare.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa1
        (
            kappaMetal.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa2
        (
            kappaGas.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField nbrKappa
        (
            kappa.boundaryField()[patchi].patchNeighbourField()
        );
        forAll(kfp, i)
        {
            const scalar dOwner = mag(nf[i] & ownerDelta[i]);
            kfp[i] = layeredFaceConductivity
            (
                cellOf(faceCells[i], dOwner),
                faceCell
                {
                    max(mag(nf[i] & delta[i]) - dOwner, SMALL),
                    nbrMetal[i], nbrShare[i],
                    nbrKappa1[i], nbrKappa2[i], nbrKappa[i]
                }
            );
        }
    }

    return tkappaf;
}


// ************************************************************************* //
