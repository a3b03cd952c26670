"""The LDNA mesh of each resolution level: a refined process zone in a coarse box.

The moving frame keeps the process fixed in space, so one static refined
region serves the whole run.  ``level`` sets the size of the **cubic** cells
of the process zone, ``h = 0.45 mm / 2**level``: level 0 puts 1.5 cells on
the radius of the template's droplet (0.68 mm; the least that inserts a
droplet as a body), level 1 three (0.225 mm, droplets resolved).

The mesh is made in two OpenFOAM steps, both reading ``system/caseParameters``:

- ``blockMesh``: the whole domain in uniform cubic base cells of
  ``h 2**n`` with ``n = floor(level) + 1`` (0.9 mm at every whole level),
  the substrate surface z = 0 on cell faces;
- ``snappyHexMesh`` (castellation only): refinement regions split the base
  cells ``n`` times inside the process zone, with ``nCellsBetweenLevels``
  buffer cells per level around it, so the cells grow smoothly outside.

The process zone is the union of two boxes: the bead and pool box (ahead of
the wires, to where the bead has solidified behind them, across the laser's
oscillation footprint, from the pool's depth to above the bead) and the
droplet column (around both wire tips down to the surface).  blockMesh needs
whole cell counts, which OpenFOAM v1912's ``#eval`` cannot compute, so they
are written per level into ``system/meshLevels/level<N>`` by
``ldna mesh-levels``, which also checks that the process zone encloses the
wire tips, the droplets' flight and the laser's footprint.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from . import _foamcase as foamcase
from .foamdict import read_scalars, set_entry

#: Process-zone cell size at level 0 [mm]: 1.5 cells on the radius of the
#: template's droplet (0.68 mm, 7.5 kg/h from two wires at 100 Hz)
LEVEL0_CELL = 0.45
#: Highest level offered
MAX_LEVEL = 3
#: Lowest level offered: the base cells unsplit (0.9 mm).  Below 0 a droplet
#: (0.68 mm radius) has less than the 1.5 cells on its radius that insert it
#: as a body: only the background of a band (bandLevel >= 1), which splits
#: the droplets' column and the weld's surface and pool
MIN_LEVEL = -1
#: Droplet diameter factor of the irregular start (paper eq. 25-27)
IRREGULAR_DIAMETER_FACTOR = 2.0


@dataclass(frozen=True)
class MeshCounts:
    """Whole cell counts of the base block mesh and the refinement of the zone."""

    nx: int
    ny: int
    n_sub: int
    n_clad: int
    n_refine: int

    @property
    def n_base_cells(self) -> int:
        """Cells of the block mesh before the refinement."""
        return self.nx * self.ny * (self.n_sub + self.n_clad)


def process_cell_size(level: float) -> float:
    """Cubic cell size [mm] of the process zone at a resolution level."""
    if not MIN_LEVEL <= level <= MAX_LEVEL:
        raise ValueError(f"level must be in [{MIN_LEVEL}, {MAX_LEVEL}], not {level}")
    return LEVEL0_CELL / 2**level


def refinement_levels(level: float) -> int:
    """How often snappyHexMesh splits the base cells in the process zone."""
    return math.floor(level) + 1


def base_cell_size(level: float) -> float:
    """Base (block mesh) cell size [mm]."""
    return process_cell_size(level) * 2**refinement_levels(level)


def droplet_radius(parameters: dict[str, float]) -> float:
    """Radius [mm] of a regular droplet: the wire volume of one detachment period."""
    wire_volume_rate = parameters["wireFeedSpeed"] * math.pi * parameters["wireRadius"] ** 2
    volume = wire_volume_rate / parameters["dropletFrequency"]
    return 1e3 * (3 * volume / (4 * math.pi)) ** (1 / 3)


def check_domain(parameters: dict[str, float]) -> None:
    """The domain's extents must be positive and finite (a mesh needs them)."""
    for entry in ("length", "width", "substrateDepth", "claddingHeight"):
        if not 0 < parameters[entry] < 1e4:
            raise ValueError(f"caseParameters: {entry} must be in (0, 1e4) mm, "
                             f"not {parameters[entry]}")


def check_process_zone(parameters: dict[str, float]) -> None:
    """The process zone must enclose the wire tips, the droplets' flight and the laser.

    Raises ``ValueError`` naming the entry and the bound it misses.
    """
    check_domain(parameters)
    p = parameters
    centre_x = p["processPosition"]
    wires_x = (centre_x - 0.5 * p["wireSpacing"], centre_x + 0.5 * p["wireSpacing"])
    largest_droplet = IRREGULAR_DIAMETER_FACTOR * droplet_radius(p)
    laser_reach = 1e3 * (p["oscillationAmplitude"] + p["laserBeamRadius"])
    laser_x = centre_x + p["laserOffset"]
    requirements = [
        ("processZoneUpstream", p["processZoneUpstream"],
         centre_x - min(wires_x[0], laser_x) + largest_droplet,
         "reach the first wire's droplets and the laser spot ahead of the wires"),
        ("processZoneDownstream", p["processZoneDownstream"],
         max(wires_x[1], laser_x) - centre_x + largest_droplet,
         "reach the last wire's droplets and the laser spot behind the wires"),
        ("processZoneHalfWidth", p["processZoneHalfWidth"], laser_reach,
         "cover the laser's oscillation (amplitude + beam radius)"),
        ("dropletZoneHalfWidth", p["dropletZoneHalfWidth"], largest_droplet,
         "hold the largest (irregular-start) droplet"),
        ("dropletZoneHeight", p["dropletZoneHeight"], p["wireHeight"] + largest_droplet,
         "enclose the wire tips and the largest droplet there"),
    ]
    for entry, value, needed, why in requirements:
        if not value >= needed:
            raise ValueError(f"caseParameters: {entry} {value:g} mm must be >= {needed:.3g} mm "
                             f"to {why}")
    inside = [
        ("processZoneUpstream", centre_x - p["processZoneUpstream"], 0.0, p["length"]),
        ("processZoneDownstream", centre_x + p["processZoneDownstream"], 0.0, p["length"]),
        ("processZoneHalfWidth", p["processZoneHalfWidth"], 0.0, 0.5 * p["width"]),
        ("processZoneDepth", p["processZoneDepth"], 0.0, p["substrateDepth"]),
        ("beadZoneHeight", p["beadZoneHeight"], 0.0, p["claddingHeight"]),
        ("dropletZoneHeight", p["dropletZoneHeight"], 0.0, p["claddingHeight"]),
    ]
    for entry, value, low, high in inside:
        if not low < value < high:
            raise ValueError(f"caseParameters: {entry} puts the process zone at {value:g} mm, "
                             f"outside the domain ({low:g}, {high:g}) mm")


def mesh_counts(parameters: dict[str, float], level: float) -> MeshCounts:
    """Cell counts for the geometry in ``caseParameters`` at ``level``."""
    check_domain(parameters)
    base = base_cell_size(level)
    return MeshCounts(
        nx=max(1, round(parameters["length"] / base)),
        ny=max(1, round(parameters["width"] / base)),
        n_sub=max(1, round(parameters["substrateDepth"] / base)),
        n_clad=max(1, round(parameters["claddingHeight"] / base)),
        n_refine=refinement_levels(level),
    )


def level_file_text(counts: MeshCounts, level: float) -> str:
    """Contents of ``system/meshLevels/level<N>``."""
    return (
        "// Mesh of resolution level {level}: process-zone cells of {h:g} mm, base cells\n"
        "// of {base:g} mm ({base_cells} of them) split {c.n_refine} times in the zone.\n"
        "// Written by 'ldna mesh-levels' from system/caseParameters: run it again\n"
        "// after changing the geometry there.\n"
        "nx          {c.nx};\n"
        "ny          {c.ny};\n"
        "nSub        {c.n_sub};\n"
        "nClad       {c.n_clad};\n"
        "nRefine     {c.n_refine};\n"
    ).format(level=level_name(level), h=process_cell_size(level), base=base_cell_size(level),
             base_cells=counts.n_base_cells, c=counts)


def write_level_file(case: Path, level: float) -> Path:
    """Write ``system/meshLevels/level<level>`` of an LDNA case; return its path."""
    case = Path(case)
    parameters = read_scalars(case / "system" / "caseParameters")
    check_process_zone(parameters)
    out_dir = case / "system" / "meshLevels"
    out_dir.mkdir(exist_ok=True)
    path = out_dir / f"level{level_name(level)}"
    path.write_text(level_file_text(mesh_counts(parameters, level), level))
    return path


def level_name(level: float) -> str:
    """How a level is spelled in caseParameters and meshLevels file names: 1, 1.5."""
    return f"{level:g}"


#: How the template's mesh dictionaries include the counts of their level
LEVEL_INCLUDE = '#include "meshLevels/level$level"'
#: The mesh dictionaries that include them
MESH_DICTIONARIES = ("blockMeshDict", "snappyHexMeshDict")


def set_level(case: Path, level: float) -> None:
    """Mesh an LDNA case at any ``level`` in [0, 3], whole or not (1.5: 0.16 mm).

    Writes the level's cell counts, sets ``level`` in caseParameters and makes
    the mesh dictionaries include that file by its name: OpenFOAM spells a
    fractional ``$level`` with trailing zeros (``level1.50000000``), which no
    file has.
    """
    case = Path(case)
    path = write_level_file(case, level)
    set_entry(case / "system" / "caseParameters", "level", level_name(level))
    for name in MESH_DICTIONARIES:
        dictionary = case / "system" / name
        text = dictionary.read_text()
        included = f'#include "meshLevels/{path.name}"'
        if included in text:
            # Set before (a study that continues its members)
            continue
        if LEVEL_INCLUDE not in text:
            raise ValueError(f"{dictionary} does not include its counts by '{LEVEL_INCLUDE}'")
        dictionary.write_text(text.replace(LEVEL_INCLUDE, included))


def write_mesh_levels(case: Path) -> list[Path]:
    """Write ``system/meshLevels/level0..3`` of an LDNA case; return the paths."""
    return [write_level_file(case, level) for level in range(MAX_LEVEL + 1)]


def _split_count(case: Path, dictionary: str, entry: str) -> int:
    """A caseParameters count of splits (0 where the case lacks ``system/<dictionary>``)."""
    case = Path(case)
    if not (case / "system" / dictionary).is_file():
        return 0
    value = read_scalars(case / "system" / "caseParameters").get(entry, 0.0)
    if not (value >= 0 and value == int(value)):
        raise ValueError(f"{case}/system/caseParameters: {entry} {value} is not a whole number >= 0")
    return int(value)


def skin_level(case: Path) -> int:
    """How often the fusion skin is split across the substrate surface (0: no skin)."""
    return _split_count(case, "refineMeshDict", "skinLevel")


def band_level(case: Path) -> int:
    """How often the band (the start's deposit, pool and droplets) is split (0: no band)."""
    return _split_count(case, "topoSetDict.band", "bandLevel")


def finest_cell_size(case: Path, level: float) -> float:
    """Cubic cell size [mm] of the band, or of the process zone without one."""
    return process_cell_size(level) / 2**band_level(case)


def mesh_case(case: Path, start: tuple[Path, float] | None = None) -> int:
    """Mesh an LDNA case as its Allrun does (blockMesh, snappyHexMesh's
    refinement of the process zone, the fusion skin split ``skinLevel``
    times by topoSet + refineMesh, and with ``start`` = (run, time) the band
    where that state has its deposit, pool and droplets split ``bandLevel``
    times); return the number of cells."""
    def run(command: str, log_name: str | None = None) -> None:
        foamcase.run(Path(case), command, log_name=log_name)

    run("blockMesh")
    run("snappyHexMesh -overwrite")
    for split in range(1, skin_level(case) + 1):
        run("topoSet", log_name=f"topoSet.skin{split}")
        run("refineMesh -overwrite", log_name=f"refineMesh.skin{split}")
    start_case, start_time = start if start else ("", 0.0)
    # The shell step of Allrun (bin/tools/RunFunctions); without a start it
    # refuses a bandLevel above 0
    run(f". '{foamcase.RUN_FUNCTIONS}' && refineBand "
        f"'{Path(start_case).resolve() if start else ''}' {start_time:g}", log_name="refineBand")
    return cell_count(case)


def cell_count(case: Path) -> int:
    """Cells of a case's mesh, from the header of constant/polyMesh/owner
    (or of its gzipped copy, as a saved state keeps it)."""
    owner = Path(case) / "constant" / "polyMesh" / "owner"
    if owner.is_file():
        header = owner.read_bytes()[:2000]
    else:
        import gzip
        with gzip.open(owner.with_name("owner.gz")) as packed:
            header = packed.read(2000)
    match = re.search(rb"nCells:\s*(\d+)", header)
    if not match:
        raise ValueError(f"{case}: no cell count in constant/polyMesh/owner")
    return int(match.group(1))
