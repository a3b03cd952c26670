"""The fusion line below the cell size: meltPoolMetrics on the template's level-0 mesh.

A clad of low dilution bonds to the substrate through a fused layer 0.05-0.3
mm deep, thinner than a level-0 cell (0.45 mm).  A prescribed weld section
on the template's own mesh: a half-ellipsoidal fusion zone of depth c and
width 2 b under a 35 mm2 bead 15 mm wide, the temperature linear across the
fusion isotherm (rising upwards, the isotherm at z = -c sqrt(1 - r^2)
inside the zone's footprint and above the surface outside it).  In the
moving frame the fused section is the zone's projection: a half-ellipse of
depth c, area pi b c / 2, bonded over its width 2 b.  The function object
must recover the depth within 0.05 mm and the area within 10 % at several
depths, from a tenth of a cell to more than one, and with the zone's centre
at several positions relative to the cell centres; on two ranks the same.
The depth and area also on the bead study's finest mesh (level 0 with
bandLevel 1 from the saved weld: 0.225 mm cells where the weld has its
deposit and pool), whose fusion outputs ``ldna accuracy`` judges against
the same 0.05 mm.
"""
from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from foamlib import FoamFile

from ldna.case import Case
from ldna.post import (POST_FUNCTION, BeadMetrics, fusion_temperature,
                       function_object_metrics, read_fusion_line)

from solver_cases import STEADY_WELD, TEMPLATE

#: Required accuracy (issue: a fusion zone a fraction of a cell deep)
DEPTH_TOLERANCE = 0.05e-3
AREA_TOLERANCE = 0.10
#: Digits of the function object's table (writePrecision 12)
TABLE_PRECISION = 1e-10
#: Fusion zone: semi-axes along the weld and across it [m]; depths [m]
ZONE_HALF_LENGTH = 5e-3
ZONE_HALF_WIDTH = 6e-3
DEPTHS = (0.05e-3, 0.15e-3, 0.3e-3, 0.6e-3)
#: Offsets of the zone's centre from the template's seam (x = processPosition, y = 0) [m]
OFFSETS = ((0.0, 0.0), (0.1e-3, 0.07e-3), (0.225e-3, 0.225e-3))
#: The bead: half-elliptic, 35 mm2 (the template's mass-balance section), 15 mm wide
BEAD_HALF_WIDTH = 7.5e-3
BEAD_AREA = 35e-6
BEAD_HEIGHT = 2 * BEAD_AREA / (math.pi * BEAD_HALF_WIDTH)
#: Temperature gradient across the isotherm [K/m] and the range the field is kept in [K]
GRADIENT = 1e6
FIELD_RANGE = (300.0, 3000.0)
#: Largest relative difference of serial and parallel metrics
AGREEMENT = 1e-9


@pytest.fixture(scope="module")
def level0_mesh(tmp_path_factory: pytest.TempPathFactory) -> Case:
    """The template at level 0, meshed, with its cell centres written at time 0."""
    case = Case.copy_of(TEMPLATE, tmp_path_factory.mktemp("fusion") / "ldna")
    case.set("system/caseParameters", "level", "0")
    case.set("system/controlDict", "writeFormat", "ascii")
    # Fields decomposed and tables written to 12 digits
    case.set("system/controlDict", "writePrecision", "12")
    case.mesh()
    case.run("postProcess -func writeCellCentres -time 0", log_name="writeCellCentres")
    return case


@pytest.fixture(scope="module")
def band_mesh(tmp_path_factory: pytest.TempPathFactory) -> Case:
    """The template at level 0 with bandLevel 1 from the saved weld (the bead
    study's level 1), meshed, with its cell centres written at time 0."""
    case = Case.copy_of(TEMPLATE, tmp_path_factory.mktemp("fusion-band") / "ldna")
    case.set("system/caseParameters", "level", "0")
    case.set("system/caseParameters", "bandLevel", "1")
    case.set("system/controlDict", "writeFormat", "ascii")
    case.set("system/controlDict", "writePrecision", "12")
    start_time = max(float(t.name) for t in Case(STEADY_WELD).times)
    case.mesh(start=(STEADY_WELD, start_time))
    case.run("postProcess -func writeCellCentres -time 0", log_name="writeCellCentres")
    return case


def prescribed_section(case: Case, depth: float, centre: tuple[float, float]) -> None:
    """Write T and alpha.metal of the prescribed weld section at time 0."""
    x, y, z = case.field("C", "0").T
    t_fusion = fusion_temperature(case)
    r2 = ((x - centre[0]) / ZONE_HALF_LENGTH) ** 2 + ((y - centre[1]) / ZONE_HALF_WIDTH) ** 2
    isotherm_depth = np.where(r2 < 1, depth * np.sqrt(np.clip(1 - r2, 0, None)),
                              -depth * np.sqrt(np.clip(r2 - 1, 0, None)))
    temperature = np.clip(t_fusion + GRADIENT * (z + isotherm_depth), *FIELD_RANGE)
    in_bead = (z >= 0) & (((y - centre[1]) / BEAD_HALF_WIDTH) ** 2 + (z / BEAD_HEIGHT) ** 2 < 1)
    alpha = np.where((z < 0) | in_bead, 1.0, 0.0)
    case.write_field("T", time="0", values=temperature)
    case.write_field("alpha.metal", time="0", values=alpha)


def column_spacing(case: Case) -> float:
    """Distance across the weld between the cell columns under the seam [m]."""
    x, y, z = case.field("C", "0").T
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    near = (np.abs(x - seam) < 1e-3) & (np.abs(y) < ZONE_HALF_WIDTH) & (z < 0) & (z > -1e-3)
    return float(np.diff(np.unique(np.round(y[near], 6))).min())


def edge_tolerance(spacing: float) -> float:
    """How far linear interpolation between columns spacing h apart can put
    an edge where the fusion line meets the surface at a vertical tangent.

    Near the edge the line's depth is a square root, +-k sqrt(|y - b|) on
    either side; with columns at b - a h and b + (1 - a) h the interpolated
    zero lies at b + h (sqrt(a) / (sqrt(a) + sqrt(1 - a)) - a): the largest
    of that over a, computed here, bounds each edge.
    """
    a = np.linspace(0.0, 1.0, 100_001)
    shift = np.sqrt(a) / (np.sqrt(a) + np.sqrt(1 - a)) - a
    return spacing * float(np.abs(shift).max())


def measure(case: Case, n_procs: int = 1) -> BeadMetrics:
    """The function object's metrics at time 0, serial or on decomposed ranks
    (ldna post reads a case whose fields are only in processor directories
    in parallel)."""
    if n_procs > 1:
        case.decompose(n_procs)
        for field in ("T", "alpha.metal", "fillerFraction"):
            (case / "0" / field).unlink()
    return function_object_metrics(case, 0.0)


def measured_zone(case: Case, depth: float,
                  offset: tuple[float, float]) -> tuple[BeadMetrics, float]:
    """The metrics of the prescribed zone ``depth`` deep, its centre
    ``offset`` from the seam, and the zone's exact area; prints both."""
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    prescribed_section(case, depth, (seam + offset[0], offset[1]))
    result = measure(case)
    area = math.pi * ZONE_HALF_WIDTH * depth / 2
    print(f"depth {1e3 * depth:.3f} mm, offset {offset}: penetration "
          f"{1e3 * result.penetration:.4f} mm, fused area {1e6 * result.fused_area:.4f} mm2 "
          f"(exact {1e6 * area:.4f}), bonded width {1e3 * result.bonded_width:.3f} mm "
          f"(exact {2e3 * ZONE_HALF_WIDTH:.3f}), unbonded {1e3 * result.unbonded_width:.3f} mm, "
          f"dilution {result.dilution:.4f}")
    return result, area


@pytest.mark.parametrize("depth", DEPTHS)
@pytest.mark.parametrize("offset", OFFSETS)
def test_fusion_zone_below_the_cell_size(level0_mesh: Case, depth: float,
                                         offset: tuple[float, float]) -> None:
    case = level0_mesh
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    result, area = measured_zone(case, depth, offset)
    assert abs(result.penetration - depth) <= DEPTH_TOLERANCE
    assert abs(result.fused_area - area) <= AREA_TOLERANCE * area
    width_tolerance = 2 * edge_tolerance(column_spacing(case))
    print(f"  bonded width tolerance {1e3 * width_tolerance:.3f} mm")
    assert abs(result.bonded_width - 2 * ZONE_HALF_WIDTH) <= width_tolerance
    assert result.unbonded_width == pytest.approx(result.bead_width - result.bonded_width,
                                                  rel=TABLE_PRECISION)
    # The deepest fusion lies at the zone's centre along the weld, within a cell
    assert abs(result.fused_section - (seam + offset[0])) <= column_spacing(case)
    dilution = area / (area + result.bead_area)
    assert result.dilution == pytest.approx(dilution, rel=AREA_TOLERANCE)

    # The profile the pictures draw is the one measured: the deepest column
    # is the penetration
    line = read_fusion_line(case, POST_FUNCTION, 0.0)
    assert line[:, 1].max() == pytest.approx(result.penetration, rel=1e-9)


#: Depth of the substrate the band splits under the weld's surface [m]: its
#: cells that touch the band, one background cell of the template's level 0
BAND_SPLIT_DEPTH = 0.45e-3


@pytest.mark.parametrize("depth", DEPTHS)
@pytest.mark.parametrize("offset", OFFSETS)
def test_fusion_depth_on_the_band(band_mesh: Case, depth: float,
                                  offset: tuple[float, float]) -> None:
    """The bead study's finest mesh: the penetration within the same 0.05 mm
    at every depth and offset (ldna accuracy's floor of a judged bond), the
    fused area within 10 % while the zone lies in the split cells.  Where
    the fusion line crosses into the background cells below them (0.6 mm)
    or meets the surface beside cells of the other size, the area and the
    bonded width are less exact (docs/limitations.md gives the figures)."""
    result, area = measured_zone(band_mesh, depth, offset)
    assert abs(result.penetration - depth) <= DEPTH_TOLERANCE
    if depth < BAND_SPLIT_DEPTH:
        assert abs(result.fused_area - area) <= AREA_TOLERANCE * area


@pytest.mark.parametrize("filler", [1.0, 0.3, 0.0])
def test_chemical_dilution_is_the_base_metal_share_of_the_bead(level0_mesh: Case,
                                                                 filler: float) -> None:
    """The template has two metals (AISI 1024 under 316L).  A bead whose metal
    is everywhere a mixture of ``filler`` filler and 1 - filler base metal
    over a substrate of base metal: the chemical dilution is 1 - filler
    whatever the mesh (the substrate below the surface is not the bead),
    while the geometric dilution is the fused area's share."""
    case = level0_mesh
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    prescribed_section(case, 0.15e-3, (seam, 0.0))
    z = case.field("C", "0")[:, 2]
    case.write_field("fillerFraction", time="0", values=np.where(z >= 0, filler, 0.0))
    result = measure(case)
    print(f"filler {filler}: chemical dilution {result.chemical_dilution:.12f}, "
          f"geometric {result.dilution:.4f}")
    assert result.chemical_dilution == pytest.approx(1 - filler, abs=TABLE_PRECISION)
    area = math.pi * ZONE_HALF_WIDTH * 0.15e-3 / 2
    assert result.dilution == pytest.approx(area / (area + result.bead_area), rel=AREA_TOLERANCE)


@pytest.mark.parametrize("hot_half_width", [None, 5e-3])
def test_a_substrate_that_did_not_melt_is_lack_of_fusion(level0_mesh: Case,
                                                         hot_half_width: float | None) -> None:
    """The isotherm 0.1 mm above the surface, everywhere or only within 5 mm of
    the seam (cold beyond: columns without any crossing beside unfused ones):
    nothing fused, the whole bead unbonded, the surface 100 K short of fusion."""
    case = level0_mesh
    x, y, z = case.field("C", "0").T
    above = 0.1e-3
    temperature = np.clip(fusion_temperature(case) + GRADIENT * (z - above), *FIELD_RANGE)
    if hot_half_width is not None:
        temperature = np.where(np.abs(y) < hot_half_width, temperature, FIELD_RANGE[0])
    in_bead = (z >= 0) & ((y / BEAD_HALF_WIDTH) ** 2 + (z / BEAD_HEIGHT) ** 2 < 1)
    case.write_field("T", time="0", values=temperature)
    case.write_field("alpha.metal", time="0", values=np.where((z < 0) | in_bead, 1.0, 0.0))
    result = measure(case)
    assert result.penetration == 0 and result.fused_area == 0 and result.dilution == 0
    assert result.bonded_width == 0
    assert result.bead_width > 0
    assert result.unbonded_width == pytest.approx(result.bead_width, rel=TABLE_PRECISION)
    # How near it came: the surface under the bead, linear between the
    # centres below and above it, is GRADIENT * above short of fusion
    surface = fusion_temperature(case) - GRADIENT * above
    print(f"peak surface temperature {result.peak_surface_temperature:.6f} K, "
          f"prescribed {surface:.6f} K")
    assert result.peak_surface_temperature == pytest.approx(surface, abs=1e-6)


def test_fusion_line_on_two_ranks(level0_mesh: Case, tmp_path: Path) -> None:
    """The same metrics from the decomposed case: the links across processor
    faces count like any other."""
    case = level0_mesh
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    prescribed_section(case, 0.15e-3, (seam + 0.1e-3, 0.07e-3))
    serial = measure(case)
    parallel_case = Case(Path(shutil.copytree(case, tmp_path / "parallel")))
    for processor in parallel_case.path.glob("processor*"):
        shutil.rmtree(processor)
    parallel = measure(parallel_case, n_procs=2)
    for name, value in serial.as_dict().items():
        if name in BeadMetrics.POST_ONLY:
            continue
        other = parallel.as_dict()[name]
        assert abs(value - other) <= AGREEMENT * max(abs(value), abs(other), 1e-12), name


def test_hot_gas_over_a_solid_substrate_is_no_fusion(level0_mesh: Case) -> None:
    """Metal everywhere 75 K below the solidus, the gas over it at 2500 K (as
    beside a droplet): the isotherm lies in the gas, whose temperature is not
    the surface's, so nothing fused."""
    case = level0_mesh
    x, y, z = case.field("C", "0").T
    in_bead = (z >= 0) & ((y / BEAD_HALF_WIDTH) ** 2 + (z / BEAD_HEIGHT) ** 2 < 1)
    alpha = np.where((z < 0) | in_bead, 1.0, 0.0)
    temperature = np.where(alpha > 0.5, fusion_temperature(case) - 75.0, 2500.0)
    case.write_field("T", time="0", values=temperature)
    case.write_field("alpha.metal", time="0", values=alpha)
    result = measure(case)
    assert result.penetration == 0 and result.fused_area == 0 and result.bonded_width == 0


#: A bead wider than the template's refined zone: its edges on faces of the
#: coarser cells beside it (y), its top on a face of both sizes (z) [m]
WIDE_BEAD_HALF_WIDTH = 9.5e-3
WIDE_BEAD_HEIGHT = 0.9e-3


def nearest_face(case: Case, axis: int, position: float) -> float:
    """The mesh's point coordinate nearest ``position`` along ``axis`` [m]."""
    points = np.asarray(FoamFile(case / "constant" / "polyMesh" / "points")[None])
    coordinates = np.unique(points[:, axis])
    return float(coordinates[np.abs(coordinates - position).argmin()])


@pytest.mark.parametrize("section_offset", [0.0, 0.5, 1.5, 3.5, 6.0])
def test_every_section_of_a_uniform_bead_has_its_area(level0_mesh: Case,
                                                      section_offset: float) -> None:
    """A rectangular bead, uniform along the weld, whose edges lie in the
    coarser cells beside the refined bead zone.  Every section, whether its
    slice's centre cuts the coarser cells through their middle or near a
    face, and whether the bead there is in refined or coarse cells, has the
    bead's own area, width and height: a section counts every cell its
    plane cuts (the sections offset by whole and half refined cells)."""
    case = level0_mesh
    half_width = nearest_face(case, 1, WIDE_BEAD_HALF_WIDTH)
    height = nearest_face(case, 2, WIDE_BEAD_HEIGHT)
    x, y, z = case.field("C", "0").T
    in_bead = (z >= 0) & (z < height) & (np.abs(y) < half_width)
    case.write_field("T", time="0", values=np.full_like(z, FIELD_RANGE[0]))
    case.write_field("alpha.metal", time="0", values=np.where((z < 0) | in_bead, 1.0, 0.0))
    case.write_field("fillerFraction", time="0", values=np.where(z >= 0, 1.0, 0.0))
    seam = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    spacing = column_spacing(case)
    section = seam + 11e-3 + section_offset * spacing
    result = function_object_metrics(case, 0.0, bead_section=section)
    print(f"section {1e3 * result.bead_section:.3f} mm: area {1e6 * result.bead_area:.6f} mm2 "
          f"(exact {2e6 * half_width * height:.6f}), width {1e3 * result.bead_width:.4f} mm "
          f"(exact {2e3 * half_width:.4f}), height {1e3 * result.bead_height:.4f} mm")
    assert result.bead_area == pytest.approx(2 * half_width * height, rel=TABLE_PRECISION)
    assert result.bead_width == pytest.approx(2 * half_width, rel=TABLE_PRECISION)
    assert result.bead_height == pytest.approx(height, rel=TABLE_PRECISION)
