"""The template's mesh levels: consistent counts and the paper's resolution.

blockMesh takes whole cell counts from system/meshLevels/level<N>, written by
'ldna mesh-levels' from system/caseParameters; the files must match the
parameters, and the finest level must reach the paper's 0.15 mm interface
cells (about 0.7 million cells, as the paper's 690 000).
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from ldna import meshing
from ldna.foamcase import run
from ldna.foamdict import read_scalars, set_entry

TEMPLATE = Path(__file__).resolve().parents[1] / "cases" / "ldna"
#: The paper's smallest cells, at the free surface [m]
PAPER_INTERFACE_CELL = 0.15e-3


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
