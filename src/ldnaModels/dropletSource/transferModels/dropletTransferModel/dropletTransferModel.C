/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "dropletTransferModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dropletTransferModel, 0);
    defineRunTimeSelectionTable(dropletTransferModel, dropletSource);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletTransferModel::dropletTransferModel
(
    const fv::dropletSource& source,
    const fvMesh& mesh
)
:
    source_(source),
    mesh_(mesh)
{}


// ************************************************************************* //
