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

    // The limit over one set of faces, given their values
    auto limitOver = [&]
    (
        const scalarField& interface,
        const scalarField& cosNormal,
        const scalarField& rhoMean,
        const scalarField& sigma,
        const scalarField& dc
    )
    {
        forAll(interface, facei)
        {
            if
            (
                interface[facei] > 0 && sigma[facei] > 0
             && cosNormal[facei] <= largestNormalCos
            )
            {
                capillaryDeltaT = min
                (
                    capillaryDeltaT,
                    Foam::sqrt
                    (
                        rhoMean[facei]
                       /(
                            constant::mathematical::twoPi*sigma[facei]
                           *pow3(dc[facei])
                        )
                    )
                );
            }
        }
    };

    limitOver(interfacef, normalCos, rhoMeanf, sigmaf, deltaCoeffs);

    // Faces between processors count as internal faces of the whole mesh
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].coupled())
        {
            limitOver
            (
                interfacef.boundaryField()[patchi],
                normalCos.boundaryField()[patchi],
                rhoMeanf.boundaryField()[patchi],
                sigmaf.boundaryField()[patchi],
                deltaCoeffs.boundaryField()[patchi]
            );
        }
    }

    reduce(capillaryDeltaT, minOp<scalar>());
    capillaryDeltaT *= maxCapillaryNo;

    return capillaryDeltaT;
}

// ************************************************************************* //
