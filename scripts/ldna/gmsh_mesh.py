"""The LDNA domain meshed with gmsh (``ldna gmsh-mesh``), an alternative to blockMesh.

Builds the template's box (``system/caseParameters``: length, width,
substrate depth, cladding height) with the gmsh Python API as two volumes
extruded from the substrate's bottom in structured layers, and converts it with OpenFOAM's gmshToFoam.

The mesh is the block mesh's base: structured, uniform (nearly) cubic
hexahedra of the counts of ``system/meshLevels``, the substrate surface on
cell faces; the case's Allrun -gmsh then refines the process zone with
snappyHexMesh as after blockMesh.  A tetrahedral mesh of the same domain runs away in ldnaFoam's first time
step (Courant number 1e48 on a level-0 mesh of 30,000 tetrahedra), so the
solver is only used on hexahedra for now.  The patches have the template's
names and types, so the template's fields and dictionaries apply unchanged.
"""
from __future__ import annotations

from pathlib import Path

from .case import Case
from .foamdict import read_scalars, set_entry
from .meshing import mesh_counts

#: Patch types of the template (gmshToFoam makes every patch a 'patch')
WALL_PATCHES = ("substrateWalls",)


def layer_fractions(heights: list[float]) -> list[float]:
    """Cumulative fractions of a stack of cell heights (gmsh's extrusion layers)."""
    total = sum(heights)
    return [sum(heights[: i + 1]) / total for i in range(len(heights))]


def build_msh(case: Path, level: float, msh_file: Path) -> int:
    """Write the gmsh mesh of the case's LDNA domain; returns its number of hexahedra."""
    import gmsh

    p = read_scalars(Path(case) / "system" / "caseParameters")
    counts = mesh_counts(p, level)
    length, width = p["length"], p["width"]
    depth, height = p["substrateDepth"], p["claddingHeight"]
    half = 0.5 * width
    substrate_heights = [depth / counts.n_sub] * counts.n_sub
    cladding_heights = [height / counts.n_clad] * counts.n_clad

    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("ldna")
        geo = gmsh.model.geo
        corners = [geo.addPoint(x, y, -depth) for x, y in
                   ((0, -half), (length, -half), (length, half), (0, half))]
        sides = [geo.addLine(corners[i], corners[(i + 1) % 4]) for i in range(4)]
        base = geo.addPlaneSurface([geo.addCurveLoop(sides)])
        for side, cells in zip(sides, (counts.nx, counts.ny, counts.nx, counts.ny)):
            geo.mesh.setTransfiniteCurve(side, cells + 1)
        geo.mesh.setTransfiniteSurface(base)
        geo.mesh.setRecombine(2, base)

        # Structured extrusion upwards, layer by layer: the substrate, then
        # the cladding from the substrate's top (the shared surface z = 0)
        def extrude(surface: int, thickness: float, heights: list[float]) -> dict[str, int]:
            out = geo.extrude([(2, surface)], 0, 0, thickness, [1] * len(heights),
                              layer_fractions(heights), recombine=True)
            # top, volume, then the sides built on the base's curves in order
            return {"top": out[0][1], "volume": out[1][1], "y-": out[2][1],
                    "x+": out[3][1], "y+": out[4][1], "x-": out[5][1]}

        substrate = extrude(base, depth, substrate_heights)
        cladding = extrude(substrate["top"], height, cladding_heights)
        geo.synchronize()

        patches = {
            "substrateInlet": [substrate["x-"]],
            "substrateOutlet": [substrate["x+"]],
            "substrateWalls": [base, substrate["y-"], substrate["y+"]],
            "atmosphere": [cladding["top"], cladding["x-"], cladding["x+"],
                           cladding["y-"], cladding["y+"]],
        }
        for name, faces in patches.items():
            gmsh.model.addPhysicalGroup(2, faces, name=name)
        gmsh.model.addPhysicalGroup(3, [substrate["volume"], cladding["volume"]], name="domain")

        gmsh.model.mesh.generate(3)
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        gmsh.option.setNumber("Mesh.Binary", 0)
        # Millimetres of caseParameters to metres
        gmsh.option.setNumber("Mesh.ScalingFactor", 1e-3)
        gmsh.write(str(msh_file))
        hexahedra = gmsh.model.mesh.getElementsByType(5)[0]
        return len(hexahedra)
    finally:
        gmsh.finalize()


def gmsh_mesh(case: Path, level: float | None = None) -> int:
    """Mesh ``case``'s base with gmsh + gmshToFoam at ``level`` (default: caseParameters)."""
    case = Path(case)
    if level is None:
        level = read_scalars(case / "system" / "caseParameters")["level"]
    msh_file = case / "ldna.msh"
    n_cells = build_msh(case, level, msh_file)
    Case(case).run(f"gmshToFoam {msh_file.name}", log_name="gmshToFoam")
    for patch in WALL_PATCHES:
        set_entry(case / "constant" / "polyMesh" / "boundary", f"{patch}/type", "wall")
    return n_cells
