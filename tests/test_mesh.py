"""The template's mesh levels and the gmsh route.

blockMesh takes whole cell counts from system/meshLevels/level<N>, written by
'ldna mesh-levels' from system/caseParameters; the files must match the
parameters, and the finest level must reach the paper's 0.15 mm interface
cells (about 0.7 million cells, as the paper's 690 000).  The gmsh route
(ldna gmsh-mesh, Allrun -gmsh) must give the same mesh as blockMesh.
"""
from __future__ import annotations

import re
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from ldna import meshing
from ldna.foamcase import dictionary_value, read_internal_field, run
from ldna.foamdict import read_scalars, set_entry

TEMPLATE = Path(__file__).resolve().parents[1] / "cases" / "ldna"
#: The paper's smallest cells, at the free surface [m]
PAPER_INTERFACE_CELL = 0.15e-3
#: Relative cell-volume difference of the gmsh and block meshes: both place
#: the same graded points, written with the case's 8 significant digits
GMSH_VOLUME_TOLERANCE = 1e-7
#: Simulated time of the run on the gmsh mesh [s] (a few steps)
GMSH_RUN_TIME = "0.002"


@pytest.mark.parametrize("level", range(meshing.MAX_LEVEL + 1))
def test_level_files_match_case_parameters(level: int) -> None:
    parameters = read_scalars(TEMPLATE / "system" / "caseParameters")
    expected = meshing.level_file_text(meshing.mesh_counts(parameters, level), level)
    written = (TEMPLATE / "system" / "meshLevels" / f"level{level}").read_text()
    assert written == expected, "run 'ldna mesh-levels cases/ldna' after changing the geometry"


def test_finest_level_reaches_paper_resolution(ldna_case: Path) -> None:
    set_entry(ldna_case / "system" / "caseParameters", "level", str(meshing.MAX_LEVEL))
    result = run(ldna_case, "blockMesh")
    n_cells = int(re.search(r"nCells: (\d+)", result.output).group(1))
    assert 500_000 < n_cells < 900_000

    checked = run(ldna_case, "checkMesh", check=False)
    assert "Mesh OK" in checked.output

    # Heights of the cell layers touching the substrate surface z = 0
    points_text = (ldna_case / "constant" / "polyMesh" / "points").read_text()
    body = points_text[points_text.index("(", points_text.index("FoamFile") + 200):]
    z = np.unique(np.round(np.array(re.findall(r"\(\S+ \S+ (\S+)\)", body), dtype=float), 9))
    surface = int(np.argmin(np.abs(z)))
    below, above = z[surface] - z[surface - 1], z[surface + 1] - z[surface]
    print(f"{n_cells} cells; surface layers {below * 1e3:.4f} mm below, {above * 1e3:.4f} mm above")
    assert abs(z[surface]) < 1e-9
    assert max(below, above) <= PAPER_INTERFACE_CELL * (1 + 1e-6)
    assert min(below, above) > 0.9 * PAPER_INTERFACE_CELL


def sorted_cell_volumes(case: Path) -> np.ndarray:
    """The case's cell volumes, in increasing order."""
    run(case, "postProcess -func writeCellVolumes -time 0", log_name="writeCellVolumes")
    return np.sort(read_internal_field(case / "0" / "V"))


def test_gmsh_route_gives_the_block_mesh(ldna_case: Path, tmp_path: Path) -> None:
    """'Allrun -gmsh' meshes the template with gmsh: the same hexahedra as blockMesh, and runs."""
    block = ldna_case
    gmsh_case = Path(shutil.copytree(block, tmp_path / "gmsh"))
    run(block, "blockMesh")
    run(gmsh_case, f"{Path(sys.executable).parent / 'ldna'} gmsh-mesh .", log_name="gmsh")

    checked = run(gmsh_case, "checkMesh", check=False)
    assert "Mesh OK" in checked.output
    block_volumes, gmsh_volumes = sorted_cell_volumes(block), sorted_cell_volumes(gmsh_case)
    assert block_volumes.shape == gmsh_volumes.shape
    difference = np.abs(gmsh_volumes - block_volumes).max() / block_volumes.max()
    print(f"{len(gmsh_volumes)} cells; largest cell volume difference {difference:.2e}")
    assert difference < GMSH_VOLUME_TOLERANCE
    for patch in ("substrateInlet", "substrateOutlet", "substrateWalls", "atmosphere"):
        face_counts = [int(run(case, f"foamDictionary -entry entry0/{patch}/nFaces -value "
                                     "constant/polyMesh/boundary", log_name="nFaces").output)
                       for case in (block, gmsh_case)]
        assert face_counts[0] == face_counts[1], patch
    assert dictionary_value(gmsh_case, "constant/polyMesh/boundary",
                            "entry0/substrateWalls/type") == "wall"

    # The scene runs on it
    set_entry(gmsh_case / "system" / "controlDict", "endTime", GMSH_RUN_TIME)
    run(gmsh_case, "setFields")
    result = run(gmsh_case, "ldnaFoam")
    assert "\nEnd\n" in result.output
