"""The template's process-zone mesh, its levels and the gmsh route.

blockMesh takes whole cell counts from system/meshLevels/level<N>, written by
'ldna mesh-levels' from system/caseParameters; the files must match the
parameters.  After snappyHexMesh's refinement the process zone (the bead and
pool box and the droplet column of caseParameters) must hold cubic cells of
0.45 mm / 2^level, but for the fusion skin (the substrate's top skinDepth
under the zone), whose cells are split 2^skinLevel times across the
surface, and the cells must grow outside it.  With bandLevel the cells
where the weld a run starts from has its deposit (its metal above the
substrate), its pool and its droplets, and a cell around them, are split
again, and only those.  A process zone that
misses the laser's footprint or the droplets is refused.  The gmsh route
(ldna gmsh-mesh, Allrun -gmsh) must give the same mesh as blockMesh.
"""
from __future__ import annotations

import gzip
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from ldna import meshing
from ldna import post
from ldna.case import Case
from ldna.case import RUN_FUNCTIONS
from ldna.foamdict import read_scalars
from solver_cases import STEADY_WELD, TEMPLATE

#: Relative cell-volume difference of the gmsh and block meshes: both place
#: the same uniform points, written with the case's 8 significant digits
GMSH_VOLUME_TOLERANCE = 1e-7
#: The fusion skin's splits in the mesh test (the template's default is 0)
SKIN_LEVEL = 2
#: Cubic cells: edge lengths of the refined cells equal within this
CUBE_TOLERANCE = 0.02
#: Cells between metal and gas in the band test: a margin inside the band's
#: own 0.02-0.98 (system/topoSetDict.band), so that the check does not
#: repeat its choice
SURFACE_FRACTIONS = (0.05, 0.95)
#: The band test's bead zone [mm]: the bead study's (docs/accuracy-cost.md),
#: above the saved weld's bead, whose top reaches into the template's base
#: cells above 3.6 mm (docs/limitations.md)
BAND_ZONE_HEIGHT_MM = 6
#: Depth below which the band test expects the zone's substrate unsplit [mm]:
#: the saved weld does not melt the substrate, and the band grows its pool
#: by one 0.45 mm cell
DEEP_SUBSTRATE_MM = 1.0
#: The weld run on the band test's mesh [s]: with the band's two cell sizes
#: on the substrate's surface, 0.69 mm3 of gas entered the substrate and
#: 1.36 mm3 of base metal rose above it in 0.1 s (CHANGELOG)
BAND_WELD_RUN = 0.1
#: Metal that may cross the substrate's surface while nothing melts it, as
#: a share of the metal the wires feed meanwhile: base metal read in the
#: bead without fusion is a chemical dilution the weld does not have, and a
#: low-dilution clad's is a few per cent
SURFACE_CROSSING_SHARE = 0.01
#: Metal the mapping onto the band's mesh may gain or lose, as a share of
#: the weld's bead: its cells beside the band are twice the weld's cell
#: size and hold eight of them, whose metal the volume weights sum; a
#: hundredth of a per cent, far below the 5 % the bead study resolves
#: (measured 2026-12-06: equal to 0.0001 mm3, the 0.06 mm3 bound is a
#: margin for meshes that do not nest exactly, as the study's longer one:
#: 0.009 mm3).  A mapping that is not volume-weighted fails it: with
#: mapFieldsPar's ``direct`` method (each cell takes the value of the
#: source cell holding its centre) the metal read 6 103.06 mm3 and the
#: bead 458.29 of 602.24 mm3 (2026-12-06; ``mapNearest`` stops v1912's
#: mapFieldsPar with a segmentation fault on this mesh)
BAND_MAP_SHARE = 1e-4
#: Simulated time of the run on the gmsh mesh [s] (a few steps)
GMSH_RUN_TIME = "0.0005"

@pytest.mark.parametrize("level", range(meshing.MAX_LEVEL + 1))
def test_level_files_match_case_parameters(level: int) -> None:
    parameters = read_scalars(TEMPLATE / "system" / "caseParameters")
    expected = meshing.level_file_text(meshing.mesh_counts(parameters, level), level)
    written = (TEMPLATE / "system" / "meshLevels" / f"level{level}").read_text()
    assert written == expected, "run 'ldna mesh-levels cases/ldna' after changing the geometry"

def cell_field(case: Case, function: str, field: str) -> np.ndarray:
    case.run(f"postProcess -func {function} -time 0", log_name=f"postProcess.{function}")
    return case.field(field, "0")

def write_cell_geometry(case: Case, time: str) -> None:
    """The cells' centres C and volumes V at ``time``, uncompressed."""
    for function in ("writeCellCentres", "writeCellVolumes"):
        case.run(f"postProcess -func {function} -time {time}",
                 log_name=f"postProcess.{function}")
    for packed in (case / time).glob("*.gz"):
        packed.with_suffix("").write_bytes(gzip.decompress(packed.read_bytes()))
        packed.unlink()


def metal_and_bead(alpha: np.ndarray, volume: np.ndarray, z: np.ndarray,
                   inside: np.ndarray | None = None) -> tuple[float, float]:
    """The metal [m3] of the cells ``inside`` (all by default) and of those
    above the substrate's surface (z = 0, a face of every cell column)."""
    keep = np.ones_like(z, dtype=bool) if inside is None else inside
    return (float((alpha * volume)[keep].sum()),
            float((alpha * volume)[keep & (z > 0)].sum()))


def written_metal_and_bead(case: Case, time: str,
                           inside: np.ndarray | None = None) -> tuple[float, float]:
    """metal_and_bead of the fields written at ``time`` (write_cell_geometry first)."""
    return metal_and_bead(case.field("alpha.metal", time), case.field("V", time),
                          case.field("C", time)[:, 2], inside)


def section_profile(alpha: np.ndarray, volume: np.ndarray, centres: np.ndarray,
                    section: float) -> tuple[float, float, float]:
    """The bead's transverse area [m2], height and width [m] in the plane
    x = ``section``, summed from the cells it cuts above the substrate's
    surface (cubic there: the process zone's cells), each column's metal
    thickness the sum of its cells' alpha times their edge.  The width is
    the span between the centres of the outermost columns at least half a
    cell thick (a cell narrower than toe to toe)."""
    edge = np.cbrt(volume)
    x, y, z = centres.T
    cut = (np.abs(x - section) < 0.5 * edge) & (z > 0)
    area = float((alpha * volume / edge)[cut].sum())
    columns = np.round(y[cut], 9)
    thickness = {c: float((alpha * edge)[cut][columns == c].sum()) for c in np.unique(columns)}
    half_edge = {c: 0.5 * float(edge[cut][columns == c].max()) for c in thickness}
    covered = [c for c, h in thickness.items() if h >= half_edge[c]]
    width = float(max(covered) - min(covered)) if covered else 0.0
    return area, max(thickness.values(), default=0.0), width


def zone_mask(centres: np.ndarray, p: dict[str, float], shrink: float) -> np.ndarray:
    """Cells whose centre is inside the process zone shrunk by ``shrink`` [m]."""
    x, y, z = (centres[:, i] * 1e3 for i in range(3))
    s = shrink * 1e3
    bead = ((x > p["processPosition"] - p["processZoneUpstream"] + s)
            & (x < p["processPosition"] + p["processZoneDownstream"] - s)
            & (abs(y) < p["processZoneHalfWidth"] - s)
            & (z > -p["processZoneDepth"] + s) & (z < p["beadZoneHeight"] - s))
    column = ((x > p["processPosition"] - 0.5 * p["wireSpacing"] - p["dropletZoneHalfWidth"] + s)
              & (x < p["processPosition"] + 0.5 * p["wireSpacing"] + p["dropletZoneHalfWidth"] - s)
              & (abs(y) < p["dropletZoneHalfWidth"] - s) & (z > s)
              & (z < p["dropletZoneHeight"] - s))
    return bead | column

@pytest.mark.parametrize("level", [0, 1])
def test_process_zone_has_cubic_cells_of_the_level(ldna_case: Case, level: int) -> None:
    ldna_case.set("system/caseParameters", "level", str(level))
    ldna_case.set("system/caseParameters", "skinLevel", str(SKIN_LEVEL))
    n_cells = meshing.mesh_case(ldna_case)
    checked = ldna_case.run("checkMesh", check=False)
    assert "Mesh OK" in checked.output

    p = read_scalars(ldna_case / "system" / "caseParameters")
    h = 1e-3 * meshing.process_cell_size(level)
    base = 1e-3 * meshing.base_cell_size(level)
    centres = cell_field(ldna_case, "writeCellCentres", "C")
    volumes = cell_field(ldna_case, "writeCellVolumes", "V")
    inside = zone_mask(centres, p, shrink=base)
    # The fusion skin: the substrate's top skinDepth, split skinLevel times
    # across the surface
    depth = -centres[:, 2] * 1e3
    skin = inside & (depth > 0) & (depth < p["skinDepth"])
    cubes = inside & ~skin
    skin_layers = 2 ** int(p["skinLevel"])
    print(f"level {level}: {n_cells} cells, {inside.sum()} well inside the process zone, "
          f"{skin.sum()} of them in the skin")
    assert cubes.sum() > 0 and skin.sum() > 0
    # (atol 0: cell volumes are some 1e-11 m3, below numpy's default atol)
    assert np.allclose(volumes[cubes], h**3, rtol=3 * CUBE_TOLERANCE, atol=0)
    assert np.allclose(volumes[skin], h**3 / skin_layers, rtol=3 * CUBE_TOLERANCE, atol=0)
    # as many skin layers as split cells: the skin's cells stack in
    # columns of skinDepth / (h / skin_layers)
    layer_depths = np.unique(np.round(depth[skin], 9))
    assert len(layer_depths) == round(p["skinDepth"] * 1e-3 / h) * skin_layers
    # Outside the zone and its buffer the cells are the base cells
    far = ~zone_mask(centres, p, shrink=-4 * base)
    assert volumes[far].min() > 0.9 * (base / 2) ** 3
    assert np.isclose(volumes.max(), base**3, rtol=0.1, atol=0)

def test_band_refines_only_the_start_welds_deposit_pool_and_droplets(ldna_case: Case) -> None:
    """Level 0 with bandLevel 1, started from the saved weld, in the bead
    study's zone (above the saved bead's top): the weld's deposit (its
    metal above the substrate, surface and all) up to the bead section and
    the droplets' column lie in cubes of h/2 (three cells on a droplet's
    radius), so that the bead section's top lies in them across the bead's
    width (ldna post's bead_surface_cells), the zone's deep substrate keeps
    h, and the mesh has fewer cells than the zone refined throughout
    (level 1)."""
    ldna_case.set("system/caseParameters", "bandLevel", "1")
    ldna_case.set("system/caseParameters", "beadZoneHeight", f"{BAND_ZONE_HEIGHT_MM:g}")
    start_time = max(float(t.name) for t in Case(STEADY_WELD).times)
    n_cells = meshing.mesh_case(ldna_case, start=(STEADY_WELD, start_time))
    checked = ldna_case.run("checkMesh", check=False)
    assert "Mesh OK" in checked.output

    p = read_scalars(ldna_case / "system" / "caseParameters")
    h = 1e-3 * meshing.process_cell_size(0)
    assert meshing.finest_cell_size(ldna_case, 0) == pytest.approx(0.5e3 * h)
    centres = cell_field(ldna_case, "writeCellCentres", "C")
    volumes = cell_field(ldna_case, "writeCellVolumes", "V")
    # The weld mapped onto the refined mesh, as Allrun -start-from does
    ldna_case.run("setFields")
    ldna_case.run(f". '{RUN_FUNCTIONS}' && startFromState '{STEADY_WELD}' {start_time:g}",
                  log_name="startFromState")
    alpha = ldna_case.field("alpha.metal", f"{start_time:g}")

    fine = np.isclose(volumes, (h / 2) ** 3, rtol=3 * CUBE_TOLERANCE, atol=0)
    coarse = np.isclose(volumes, h**3, rtol=3 * CUBE_TOLERANCE, atol=0)
    inside = zone_mask(centres, p, shrink=2 * h)
    x, z = centres[:, 0] * 1e3, centres[:, 2] * 1e3
    before_section = x < p["processPosition"] + p["beadSectionDistance"]
    surface = inside & before_section & (alpha > SURFACE_FRACTIONS[0]) & (alpha < SURFACE_FRACTIONS[1])
    deposit = inside & before_section & (z > 0) & (alpha > SURFACE_FRACTIONS[0])
    column = zone_mask(centres, {**p, "processZoneHalfWidth": 0.0}, shrink=2 * h)
    deep = inside & (z < -DEEP_SUBSTRATE_MM)
    zone_volume = 1e-9 * (
        (p["processZoneUpstream"] + p["processZoneDownstream"]) * 2 * p["processZoneHalfWidth"]
        * (p["processZoneDepth"] + p["beadZoneHeight"]))
    print(f"{n_cells} cells; {fine.sum()} of h/2, {surface.sum()} at the weld's surface, "
          f"{deposit.sum()} in its deposit, "
          f"{column.sum()} in the droplet column, {deep.sum()} in the deep substrate; "
          f"the zone refined throughout: {zone_volume / (h / 2) ** 3:.0f}")
    assert surface.sum() > 1000 and column.sum() > 1000 and deep.sum() > 1000
    assert fine[surface].all() and fine[deposit].all() and fine[column].all()
    assert coarse[deep].all()
    grid = post.read_case(ldna_case, start_time)
    finest, coarsest, coarse_top = post.bead_surface_cells(
        grid, post.configured_bead_section(ldna_case))
    print(f"the section's bead top in cells of {1e3 * finest:.3f}-{1e3 * coarsest:.3f} mm, "
          f"{100 * coarse_top:.1f} % of its width in coarser ones")
    assert finest == pytest.approx(0.5 * h, rel=CUBE_TOLERANCE) and coarse_top == 0
    assert meshing.droplet_radius(p) / (0.5e3 * h) >= 3 - CUBE_TOLERANCE
    # Level 1's mesh: the zone refined throughout, the cells outside it as here
    level1_cells = zone_volume / (h / 2) ** 3 + (~zone_mask(centres, p, shrink=0.0)).sum()
    print(f"level 1 (estimated): {level1_cells:.0f} cells")
    assert n_cells < level1_cells


def test_band_keeps_the_substrate_out_of_the_deposit(ldna_case: Case, tmp_path: Path) -> None:
    """The bead study's level 0 (level -1 with the saved weld's surface, pool
    and droplets split once) starts from the saved weld with its metal and
    its bead's (the mapping onto cells coarser than the weld's beside the
    band keeps the metal: each within a ten-thousandth of the weld's bead,
    summed from its fields), then continues it for 0.1 s: the
    substrate stays below its solidus, so no metal may cross its surface.
    The gas that enters the substrate's cells and the base metal that
    appears above its surface stay within 1 % of the metal fed meanwhile
    (each).  Measured (2026-12-05): 0.045 and 0.082 mm3 of the 26.2 fed;
    with the band's two cell sizes meeting on the surface under the
    deposit's gas-laden first layer (the band before the substrate's cells
    that touch it were added), 0.69 and 1.36 mm3, and the test failed."""
    from ldna import post

    meshing.set_level(ldna_case, -1)
    ldna_case.set("system/caseParameters", "bandLevel", "1")
    start_time = max(float(t.name) for t in Case(STEADY_WELD).times)
    meshing.mesh_case(ldna_case, start=(STEADY_WELD, start_time))
    centres = cell_field(ldna_case, "writeCellCentres", "C")
    volumes = cell_field(ldna_case, "writeCellVolumes", "V")
    ldna_case.run("setFields")
    ldna_case.run(f". '{RUN_FUNCTIONS}' && startFromState '{STEADY_WELD}' {start_time:g}",
                  log_name="startFromState")
    weld = Case(Path(shutil.copytree(STEADY_WELD, tmp_path / "weld")))
    write_cell_geometry(weld, f"{start_time:g}")
    weld_metal, weld_bead = written_metal_and_bead(weld, f"{start_time:g}")
    mapped_metal, mapped_bead = metal_and_bead(ldna_case.field("alpha.metal", f"{start_time:g}"),
                                               volumes, centres[:, 2])
    print(f"mapped onto the band: metal {1e9 * mapped_metal:.4f} mm3 (the weld's "
          f"{1e9 * weld_metal:.4f}), bead {1e9 * mapped_bead:.4f} mm3 ({1e9 * weld_bead:.4f})")
    assert abs(mapped_metal - weld_metal) <= BAND_MAP_SHARE * weld_bead
    assert abs(mapped_bead - weld_bead) <= BAND_MAP_SHARE * weld_bead
    end_time = start_time + BAND_WELD_RUN
    ldna_case.set("system/controlDict", "endTime", f"{end_time:g}")
    ldna_case.set("system/controlDict", "writeInterval", f"{BAND_WELD_RUN:g}")
    ldna_case.run("ldnaFoam")

    # The surface is z = 0, a face of every cell column
    below = centres[:, 2] < 0

    def crossing(time: float) -> tuple[float, float]:
        alpha = ldna_case.field("alpha.metal", f"{time:g}")
        filler = ldna_case.field("fillerFraction", f"{time:g}")
        gas_below = float(((1 - alpha) * volumes)[below].sum())
        base_above = float((alpha * (1 - filler) * volumes)[~below].sum())
        return gas_below, base_above

    (gas0, base0), (gas1, base1) = crossing(start_time), crossing(end_time)
    fed = post.expected_bead_area(ldna_case) * post.welding_speed(ldna_case) * BAND_WELD_RUN
    print(f"in {BAND_WELD_RUN} s, {fed * 1e9:.2f} mm3 fed: gas in the substrate "
          f"{gas0 * 1e9:.3f} -> {gas1 * 1e9:.3f} mm3, base metal above its surface "
          f"{base0 * 1e9:.3f} -> {base1 * 1e9:.3f} mm3")
    assert gas1 - gas0 <= SURFACE_CROSSING_SHARE * fed
    assert base1 - base0 <= SURFACE_CROSSING_SHARE * fed


#: Base cells the longer domain of the mapping test adds behind the saved
#: weld's outlet
ADDED_BASE_CELLS = 5
#: The process zone's cell edge at level 0 [m]
LEVEL0_CELL = 0.45e-3
#: Share of a level-0 process-zone cell by which a mapping onto nested cells
#: may change the metal (of its volume), the bead section's area (of its
#: face), height and width (of its edge): the volume weights' round-off,
#: far below what the cells' interfaces hold (cells that do not nest shift
#: the metal a hundred times more)
NESTED_MAP_SHARE = 1e-3
NESTED_MAP_TOLERANCE = NESTED_MAP_SHARE * LEVEL0_CELL ** 3


def test_a_weld_maps_onto_a_longer_domain(ldna_case: Case, tmp_path: Path) -> None:
    """The saved weld (28 mm long, 31 base cells) started on a domain five
    base cells longer, whose cells nest in its own: the cells inside the
    weld's domain hold its metal and its bead's, and its bead's section
    where the weld reads it (each within a thousandth of a cell of the
    weld's own, summed from its fields), those beyond its outlet the
    case's initial flat substrate at the ambient temperature, which the
    bead then travels into (a bead section farther behind the wires than
    the weld's domain allows)."""
    weld = Case(Path(shutil.copytree(STEADY_WELD, tmp_path / "weld")))
    start_time = max(float(t.name) for t in weld.times)
    time = f"{start_time:g}"

    write_cell_geometry(weld, time)
    weld_length = weld.scalar("system/caseParameters", "length")
    # The weld's base cells along its length: its deepest layer's columns
    centres = weld.field("C", time)
    bottom = centres[:, 2] < centres[:, 2].min() + 1e-9
    base_cells = len(np.unique(np.round(centres[bottom, 0], 9)))
    length = weld_length * (base_cells + ADDED_BASE_CELLS) / base_cells
    ldna_case.set("system/caseParameters", "length", f"{length:.15g}")
    meshing.set_level(ldna_case, 0)
    meshing.mesh_case(ldna_case)
    ldna_case.run("setFields")
    ldna_case.run(f". '{RUN_FUNCTIONS}' && startFromState '{STEADY_WELD}' {start_time:g}",
                  log_name="startFromState")
    write_cell_geometry(ldna_case, time)

    x, _, z = ldna_case.field("C", time).T
    inside = x < 1e-3 * weld_length
    weld_metal, weld_bead = written_metal_and_bead(weld, time)
    mapped_metal, mapped_bead = written_metal_and_bead(ldna_case, time, inside)
    print(f"{length:.4f} mm long: metal {1e9 * mapped_metal:.6f} mm3 (the weld's "
          f"{1e9 * weld_metal:.6f}), bead {1e9 * mapped_bead:.6f} mm3 "
          f"({1e9 * weld_bead:.6f})")
    assert abs(mapped_metal - weld_metal) <= NESTED_MAP_TOLERANCE
    assert abs(mapped_bead - weld_bead) <= NESTED_MAP_TOLERANCE
    # The bead's shape, not only its metal: its section where the weld
    # reads it (its meltPoolMetrics' beadSection) alike to a thousandth of
    # a cell
    section = post.configured_bead_section(weld)
    assert section is not None
    weld_shape = section_profile(weld.field("alpha.metal", time), weld.field("V", time),
                                 centres, section)
    mapped_shape = section_profile(ldna_case.field("alpha.metal", time),
                                   ldna_case.field("V", time), ldna_case.field("C", time),
                                   section)
    print("section {:.4f} mm2, {:.3f} mm high, {:.3f} mm wide (the weld's "
          "{:.4f}, {:.3f}, {:.3f})".format(*(1e6 * mapped_shape[0], 1e3 * mapped_shape[1],
                                              1e3 * mapped_shape[2], 1e6 * weld_shape[0],
                                              1e3 * weld_shape[1], 1e3 * weld_shape[2])))
    assert weld_shape[1] > 0 and weld_shape[2] > 0
    assert abs(mapped_shape[0] - weld_shape[0]) <= NESTED_MAP_SHARE * LEVEL0_CELL ** 2
    assert abs(mapped_shape[1] - weld_shape[1]) <= NESTED_MAP_SHARE * LEVEL0_CELL
    assert abs(mapped_shape[2] - weld_shape[2]) <= NESTED_MAP_SHARE * LEVEL0_CELL
    alpha, temperature = ldna_case.field("alpha.metal", time), ldna_case.field("T", time)
    beyond = ~inside
    ambient = ldna_case.scalar("system/caseParameters", "ambientTemperature")
    assert beyond.sum() > 0
    assert np.all(alpha[beyond & (z < 0)] == 1) and np.all(alpha[beyond & (z > 0)] == 0)
    assert np.all(temperature[beyond] == ambient)


@pytest.mark.parametrize("value,start,message", [
    ("1", False, "start from one"),
    ("0.5", True, "not a whole number"),
])
def test_band_needs_a_start_and_a_whole_level(ldna_case: Case, value: str, start: bool,
                                              message: str) -> None:
    ldna_case.set("system/caseParameters", "bandLevel", value)
    start_state = (STEADY_WELD, max(float(t.name) for t in Case(STEADY_WELD).times))
    with pytest.raises(RuntimeError, match="bandLevel") as failure:
        meshing.mesh_case(ldna_case, start=start_state if start else None)
    assert message in str(failure.value)


@pytest.mark.parametrize("entry,value,message", [
    ("processZoneHalfWidth", "5", "laser's oscillation"),
    ("dropletZoneHeight", "4", "wire tips"),
    ("processZoneDownstream", "40", "outside the domain"),
])
def test_process_zone_must_enclose_the_process(entry: str, value: str, message: str) -> None:
    parameters = read_scalars(TEMPLATE / "system" / "caseParameters")
    parameters[entry] = float(value)
    with pytest.raises(ValueError, match=message):
        meshing.check_process_zone(parameters)

def sorted_cell_volumes(case: Case) -> np.ndarray:
    """The case's cell volumes, in increasing order."""
    return np.sort(cell_field(case, "writeCellVolumes", "V"))

def test_gmsh_route_gives_the_block_mesh(ldna_case: Case, tmp_path: Path) -> None:
    """'Allrun -gmsh' meshes the template with gmsh: the same hexahedra as blockMesh, and runs."""
    block = ldna_case
    gmsh_case = Case(Path(shutil.copytree(block, tmp_path / "gmsh")))
    block.run("blockMesh")
    gmsh_case.run(f"{Path(sys.executable).parent / 'ldna'} gmsh-mesh .", log_name="gmsh")

    checked = gmsh_case.run("checkMesh", check=False)
    assert "Mesh OK" in checked.output
    block_volumes, gmsh_volumes = sorted_cell_volumes(block), sorted_cell_volumes(gmsh_case)
    assert block_volumes.shape == gmsh_volumes.shape
    difference = np.abs(gmsh_volumes - block_volumes).max() / block_volumes.max()
    print(f"{len(gmsh_volumes)} cells; largest cell volume difference {difference:.2e}")
    assert difference < GMSH_VOLUME_TOLERANCE
    for patch in ("substrateInlet", "substrateOutlet", "substrateWalls", "atmosphere"):
        face_counts = [int(case.run(f"foamDictionary -entry entry0/{patch}/nFaces -value "
                                    "constant/polyMesh/boundary", log_name="nFaces").output)
                       for case in (block, gmsh_case)]
        assert face_counts[0] == face_counts[1], patch
    assert gmsh_case.value("constant/polyMesh/boundary",
                           "entry0/substrateWalls/type") == "wall"

    # The process zone refines it as it refines the block mesh, and the
    # scene runs on it
    gmsh_case.run("snappyHexMesh -overwrite")
    gmsh_case.set("system/controlDict", "endTime", GMSH_RUN_TIME)
    gmsh_case.run("setFields")
    result = gmsh_case.run("ldnaFoam")
    assert "\nEnd\n" in result.output
