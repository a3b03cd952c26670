/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "dropletTransferModel.H"
#include "dropletSource.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dropletTransferModel> Foam::dropletTransferModel::New
(
    const fv::dropletSource& source,
    const fvMesh& mesh
)
{
    // The paper's CFX model spreads the droplets as sources
    const word defaultMode("gaussian");
    const dictionary& coeffs = source.coeffs();
    const word modelType(coeffs.lookupOrDefault<word>("mode", defaultMode));

    auto cstrIter = dropletSourceConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            coeffs,
            "mode",
            modelType,
            *dropletSourceConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<dropletTransferModel>(cstrIter()(source, mesh));
}


// ************************************************************************* //
