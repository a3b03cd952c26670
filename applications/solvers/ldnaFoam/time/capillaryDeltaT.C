/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "capillaryDeltaT.H"
#include "checkedInput.H"
#include "mathematicalConstants.H"
#include "surfaceInterpolate.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::scalar Foam::ldna::capillaryDeltaT
(
    const metalGasMixture& mixture,
    const volScalarField& rho1,
    const volScalarField& rho2,
    const dictionary& controlDict
)
{
    const fvMesh& mesh = rho1.mesh();
    scalar capillaryDeltaT = GREAT;

    // Above 10 the limit no longer restrains the step: capillary waves
    // grow unresolved
    const scalar largestCapillaryNo = 10;
    const scalar maxCapillaryNo = ldna::getCheckedOrDefault<scalar>
    (
        controlDict, "maxCapillaryNo",
        ldna::interval::openClosed(0, largestCapillaryNo), 1
    );
    const scalar largestNormalCos = 1/Foam::sqrt(3.0);

    const surfaceScalarField sigmaf
    (
        fvc::interpolate(mixture.sigma())*mixture.liquidMetalFaceFraction()
    );
    const surfaceScalarField rhoMeanf
    (
        0.5*(fvc::interpolate(rho1) + fvc::interpolate(rho2))
    );
    const surfaceScalarField interfacef
    (
        fvc::interpolate(mixture.nearInterface())
    );
    // |cos| of the angle between the face normal and the interface normal
    const surfaceScalarField normalCos(mag(mixture.nHatf())/mesh.magSf());
    const surfaceScalarField& deltaCoeffs = mesh.deltaCoeffs();

    auto faceLimit = [&]
    (
        const scalar interface,
        const scalar cosNormal,
        const scalar rhoMean,
        const scalar sigma,
        const scalar dc
    )
    {
        if (interface > 0 && sigma > 0 && cosNormal <= largestNormalCos)
        {
            return Foam::sqrt
            (
                rhoMean/(constant::mathematical::twoPi*sigma*pow3(dc))
            );
        }
        return GREAT;
    };

    forAll(deltaCoeffs, facei)
    {
        capillaryDeltaT = min
        (
            capillaryDeltaT,
            faceLimit
            (
                interfacef[facei], normalCos[facei], rhoMeanf[facei],
                sigmaf[facei], deltaCoeffs[facei]
            )
        );
    }

    // Faces between processors count as internal faces of the whole mesh
    forAll(mesh.boundary(), patchi)
    {
        if (!mesh.boundary()[patchi].coupled())
        {
            continue;
        }
        const scalarField& interfacep = interfacef.boundaryField()[patchi];
        const scalarField& cosp = normalCos.boundaryField()[patchi];
        const scalarField& sigmap = sigmaf.boundaryField()[patchi];
        const scalarField& rhoMeanp = rhoMeanf.boundaryField()[patchi];
        const scalarField& dcp = deltaCoeffs.boundaryField()[patchi];
        forAll(interfacep, facei)
        {
            capillaryDeltaT = min
            (
                capillaryDeltaT,
                faceLimit
                (
                    interfacep[facei], cosp[facei], rhoMeanp[facei],
                    sigmap[facei], dcp[facei]
                )
            );
        }
    }

    reduce(capillaryDeltaT, minOp<scalar>());
    capillaryDeltaT *= maxCapillaryNo;

    return capillaryDeltaT;
}

// ************************************************************************* //
