/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
\*---------------------------------------------------------------------------*/

#include "convexCells.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::convexCells::convexCells(const polyMesh& mesh)
:
    start_(mesh.nCells() + 1),
    planes_(2*mesh.nInternalFaces() + mesh.nBoundaryFaces()),
    radius_(mesh.nCells(), Zero)
{
    const cellList& cells = mesh.cells();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& Sf = mesh.faceAreas();
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    const pointField& points = mesh.points();
    const faceList& faces = mesh.faces();
    const vectorField& C = mesh.cellCentres();

    label i = 0;
    forAll(cells, celli)
    {
        start_[celli] = i;
        for (const label facei : cells[celli])
        {
            facePlane& p = planes_[i++];
            const bool owned = (owner[facei] == celli);
            p.outward = owned ? Sf[facei] : -Sf[facei];
            p.offset = p.outward & Cf[facei];
            p.next =
                mesh.isInternalFace(facei)
              ? (owned ? neighbour[facei] : owner[facei])
              : -1;
            p.face = facei;

            for (const label pointi : faces[facei])
            {
                radius_[celli] =
                    max(radius_[celli], mag(points[pointi] - C[celli]));
            }
        }
    }
    start_[cells.size()] = i;
}


// ************************************************************************* //
