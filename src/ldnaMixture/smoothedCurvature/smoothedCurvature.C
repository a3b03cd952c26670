/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "smoothedCurvature.H"
#include "checkedInput.H"
#include "interfaceDelta.H"
#include "fvc.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::smoothedCurvature::smoothedCurvature(const volScalarField& alpha)
:
    alpha_(alpha),
    nSmooth_(0),
    curvature_
    (
        IOobject("curvature", alpha.time().timeName(), alpha.mesh()),
        alpha.mesh(),
        dimensionedScalar(dimless/dimLength, Zero)
    ),
    faceCurvature_
    (
        IOobject("curvaturef", alpha.time().timeName(), alpha.mesh()),
        alpha.mesh(),
        dimensionedScalar(dimless/dimLength, Zero)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::smoothedCurvature::read(const dictionary& dict)
{
    // More passes smooth the curvature over more than the interface's
    // neighbourhood
    const label maxSmooth = 100;
    nSmooth_ = ldna::getCheckedOrDefault<label>
    (
        dict, "curvatureSmoothing", ldna::interval::closed(0, maxSmooth), 2
    );
}


void Foam::smoothedCurvature::correct()
{
    const fvMesh& mesh = alpha_.mesh();

    volScalarField alphaSmooth("alphaSmooth", alpha_);
    for (label pass = 0; pass < nSmooth_; ++pass)
    {
        alphaSmooth = fvc::average(fvc::interpolate(alphaSmooth));

        // The boundary values follow alpha's conditions (zeroGradient at
        // walls); left at the unsmoothed values, they bent the smoothed
        // interface where it meets a wall
        alphaSmooth.correctBoundaryConditions();
    }

    // Unit normals in the cells of the (smoothed) interface band only
    const volVectorField gradAlpha(fvc::grad(alphaSmooth, "nHat"));
    volVectorField nHat
    (
        IOobject("nHat", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimless, Zero)
    );
    nHat.primitiveFieldRef() = metalInterfaceNormal(gradAlpha);

    // Processor and symmetry faces take their neighbour's (mirrored) normal;
    // on walls and open patches nHat stays zero: no capillary flux through
    // them (the 90 degree contact angle of a zeroGradient alpha)
    nHat.correctBoundaryConditions();
    curvature_ = -fvc::div(fvc::interpolate(nHat) & mesh.Sf());

    // A face of the sharp interface takes the curvature of the cells the
    // interface passes through, not that of the band's edge cells, where
    // the normals fade out and -div(nHat) is an artefact of the fading
    const volScalarField weight(mag(gradAlpha));
    faceCurvature_ =
        fvc::interpolate(weight*curvature_)
       /(
            fvc::interpolate(weight)
          + dimensionedScalar("small", weight.dimensions(), VSMALL)
        );
}


// ************************************************************************* //
