"""Cell counts of the LDNA block mesh for each resolution level.

blockMesh needs whole numbers of cells, which OpenFOAM v1912's ``#eval``
cannot produce, so the counts are written once per level into
``system/meshLevels/level<N>`` and ``system/blockMeshDict`` includes the file
of the chosen ``level``.  The formulas here and the grading in blockMeshDict
describe the same mesh:

- interface (finest) cell height ``dz_min = 1.2 mm / 2**level`` (level 3 is
  the paper's 0.15 mm), in-plane cells of ``2 dz_min``;
- a uniform band of ``dz_min`` cells on either side of the substrate surface;
- beyond it geometric growth to ``coarseCellSize`` with
  ``n = L ln(r) / (dz_max - dz_min)`` cells, the log-mean cell size of a
  geometric progression from ``dz_min`` to ``dz_max = r dz_min``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from .foamdict import read_scalars, set_entry

#: Interface cell height at level 0 [mm]; 1.2 / 2**3 = 0.15 mm, the paper's
#: finest cells
LEVEL0_INTERFACE_CELL = 1.2
#: In-plane cell size over interface cell height
IN_PLANE_ASPECT = 2.0
#: Highest level offered (the paper's resolution)
MAX_LEVEL = 3


@dataclass(frozen=True)
class MeshCounts:
    """Whole cell counts of the two blocks of the LDNA mesh."""

    nx: int
    ny: int
    n_sub_fine: int
    n_sub_coarse: int
    n_clad_fine: int
    n_clad_coarse: int

    @property
    def n_cells(self) -> int:
        """Total number of cells."""
        nz = self.n_sub_fine + self.n_sub_coarse + self.n_clad_fine + self.n_clad_coarse
        return self.nx * self.ny * nz


def interface_cell_size(level: float) -> float:
    """Finest cell height [mm] at a resolution level.

    Levels between the whole ones (``ldna accuracy`` uses halves) give cells
    of ``1.2 mm / 2**level`` as well.
    """
    if not 0 <= level <= MAX_LEVEL:
        raise ValueError(f"level must be in [0, {MAX_LEVEL}], not {level}")
    return LEVEL0_INTERFACE_CELL / 2**level


def _graded_cells(length: float, dz_min: float, dz_max: float) -> int:
    return max(1, round(length * math.log(dz_max / dz_min) / (dz_max - dz_min)))


def mesh_counts(parameters: dict[str, float], level: float) -> MeshCounts:
    """Cell counts for the geometry in ``caseParameters`` at ``level``."""
    dz_min = interface_cell_size(level)
    dxy = IN_PLANE_ASPECT * dz_min
    dz_max = max(parameters["coarseCellSize"], 1.0001 * dz_min)
    sub, clad = parameters["substrateDepth"], parameters["claddingHeight"]
    sub_fine, clad_fine = parameters["substrateFineBand"], parameters["claddingFineBand"]
    return MeshCounts(
        nx=round(parameters["length"] / dxy),
        ny=round(parameters["width"] / dxy),
        n_sub_fine=math.ceil(sub_fine / dz_min - 1e-9),
        n_sub_coarse=_graded_cells(sub - sub_fine, dz_min, dz_max),
        n_clad_fine=math.ceil(clad_fine / dz_min - 1e-9),
        n_clad_coarse=_graded_cells(clad - clad_fine, dz_min, dz_max),
    )


def level_name(level: float) -> str:
    """How a level is spelled in caseParameters and meshLevels file names: 1, 1.5."""
    return f"{level:g}"


def level_file_text(counts: MeshCounts, level: float) -> str:
    """Contents of ``system/meshLevels/level<N>``."""
    return (
        "// Cell counts of resolution level {level} (about {cells} cells), written by\n"
        "// 'ldna mesh-levels' from system/caseParameters: run it again after\n"
        "// changing the geometry there.\n"
        "nx          {c.nx};\n"
        "ny          {c.ny};\n"
        "nSubFine    {c.n_sub_fine};\n"
        "nSubCoarse  {c.n_sub_coarse};\n"
        "nCladFine   {c.n_clad_fine};\n"
        "nCladCoarse {c.n_clad_coarse};\n"
        "nSubTotal   {n_sub};\n"
        "nCladTotal  {n_clad};\n"
    ).format(
        level=level_name(level),
        cells=counts.n_cells,
        c=counts,
        n_sub=counts.n_sub_fine + counts.n_sub_coarse,
        n_clad=counts.n_clad_fine + counts.n_clad_coarse,
    )


def write_level_file(case: Path, level: float) -> Path:
    """Write ``system/meshLevels/level<level>`` of an LDNA case; return its path."""
    case = Path(case)
    parameters = read_scalars(case / "system" / "caseParameters")
    out_dir = case / "system" / "meshLevels"
    out_dir.mkdir(exist_ok=True)
    path = out_dir / f"level{level_name(level)}"
    path.write_text(level_file_text(mesh_counts(parameters, level), level))
    return path


#: How the template's blockMeshDict includes the counts of its level
LEVEL_INCLUDE = '#include "meshLevels/level$level"'


def set_level(case: Path, level: float) -> None:
    """Mesh an LDNA case at any ``level`` in [0, 3], whole or not (1.5: 0.42 mm).

    Writes the level's cell counts, sets ``level`` in caseParameters and makes
    blockMeshDict include that file by its name: OpenFOAM spells a fractional
    ``$level`` with trailing zeros (``level1.50000000``), which no file has.
    """
    case = Path(case)
    path = write_level_file(case, level)
    set_entry(case / "system" / "caseParameters", "level", level_name(level))
    block_mesh = case / "system" / "blockMeshDict"
    text = block_mesh.read_text()
    if LEVEL_INCLUDE not in text:
        raise ValueError(f"{block_mesh} does not include its counts by '{LEVEL_INCLUDE}'")
    block_mesh.write_text(text.replace(LEVEL_INCLUDE, f'#include "meshLevels/{path.name}"'))


def write_mesh_levels(case: Path) -> list[Path]:
    """Write ``system/meshLevels/level0..3`` of an LDNA case; return the paths."""
    return [write_level_file(case, level) for level in range(MAX_LEVEL + 1)]
