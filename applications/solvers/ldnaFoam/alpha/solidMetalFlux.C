/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "solidMetalFlux.H"
#include "localMax.H"
#include "optionsImplementing.H"
#include "solidMetalMotion.H"
#include "upwind.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidMetalFlux::solidMetalFlux
(
    fv::optionList& options,
    const surfaceScalarField& phi,
    const volScalarField& alpha1,
    const volScalarField& liquidFraction
)
:
    tphiMetalMix_(phi),
    tphiMetalSolid_()
{
    const fvMesh& mesh = phi.mesh();

    const UPtrList<solidMetalMotion> motions
    (
        ldna::optionsImplementing<solidMetalMotion>(options)
    );
    if (motions.size() > 1)
    {
        FatalErrorInFunction
            << motions.size() << " fvOptions give the solid metal's velocity:"
            << " list one (e.g. one enthalpyPorosity)" << exit(FatalError);
    }
    if (motions.empty())
    {
        return;
    }
    const vector Us = motions[0].solidMetalVelocity();

    surfaceScalarField phiSolid
    (
        "phiSolid",
        dimensionedVector("Us", dimVelocity, Us) & mesh.Sf()
    );
    for (fvsPatchScalarField& phiSolidp : phiSolid.boundaryFieldRef())
    {
        if (!phiSolidp.coupled())
        {
            phiSolidp = max(phiSolidp, scalar(0));
        }
    }

    const volScalarField solidShare
    (
        "solidShare",
        min(max(1 - liquidFraction, scalar(0)), scalar(1))
    );
    const surfaceScalarField room
    (
        "room",
        max(1 - localMax<scalar>(mesh).interpolate(alpha1), scalar(0))
    );

    tphiMetalMix_ = surfaceScalarField::New
    (
        "phiMetalMix",
        phi
       *(1 - room*upwind<scalar>(mesh, phi).interpolate(solidShare))
    );
    tphiMetalSolid_ = surfaceScalarField::New
    (
        "phiMetalSolid",
        phiSolid
       *room*upwind<scalar>(mesh, phiSolid).interpolate(solidShare)
    );
}

// ************************************************************************* //
