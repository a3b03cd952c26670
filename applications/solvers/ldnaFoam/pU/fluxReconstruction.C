/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "fluxReconstruction.H"
#include "fvcSurfaceIntegrate.H"
#include "extrapolatedCalculatedFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluxReconstruction::fluxReconstruction(const fvMesh& mesh)
:
    mesh_(mesh),
    faceNormals_("faceNormals", mesh.Sf()/mesh.magSf()),
    inverse_
    (
        inv(fvc::surfaceSum(faceNormals_*mesh.Sf())().primitiveField())
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::fluxReconstruction::operator()(const surfaceScalarField& flux) const
{
    tmp<volVectorField> tresult
    (
        volVectorField::New
        (
            "reconstruct(" + flux.name() + ')',
            mesh_,
            dimensionedVector(flux.dimensions()/dimArea, Zero),
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );
    volVectorField& result = tresult.ref();

    result.primitiveFieldRef() =
        inverse_ & fvc::surfaceSum(faceNormals_*flux)().primitiveField();
    result.correctBoundaryConditions();

    return tresult;
}


// ************************************************************************* //
