"""Bead and melt-pool metrics: the meltPoolMetrics function object and ``ldna post``.

A synthetic case prescribes a half-ellipsoid pool below the substrate surface
and a half-elliptic bead on it; the function object (serial and on two MPI
ranks, through OpenFOAM's postProcess) and ``ldna post`` (which runs the
function object at the time it reads) must recover the prescribed sizes
between cell centres: the pool's edge from the temperature, the bead's toes
and top from the metal fraction (exact cut-cell fractions, as a solved
field has).  ``ldna post`` must also render its pictures without a
display, and on a real run of the LDNA template report what the function
object wrote during the run.
"""
from __future__ import annotations

import math
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from solver_cases import prepare_test_case
from ldna import section_fields
from ldna.case import Case
from ldna.material import Metal
from ldna.post import BODY_HEIGHT_SHARE, BeadMetrics, configured_bead_section, function_object_metrics, fusion_temperature, post_process, read_function_object_metrics

#: Cell size of the synthetic case [m] (tests/cases/syntheticPool)
CELL = 0.5e-3
#: Prescribed pool: half-ellipsoid below z = 0 centred at POOL_CENTRE, semi-axes [m]
POOL_CENTRE = (10e-3, 0.0)
POOL_SEMI_AXES = (4.1e-3, 3.1e-3, 2.1e-3)
#: Prescribed bead: half-elliptic cylinder on z = 0 from x = BEAD_START on, semi-axes [m]
BEAD_START = 8e-3
BEAD_HALF_WIDTH = 2.6e-3
BEAD_HEIGHT = 1.6e-3
#: Temperatures of the prescribed fields [K]: the pool's hottest, cold
#: elsewhere; in between the temperature falls linearly with the normalised
#: radius of the ellipsoid, passing the fusion temperature on its surface
#: at POOL_GRADIENT [K/m] across its bottom
POOL_TEMPERATURE = 2000.0
COLD_TEMPERATURE = 300.0
POOL_GRADIENT = 1e6
#: Sizes located between cell centres: within this share of a cell of the
#: prescribed ones (the rows of cell centres nearest the surface see the
#: shapes 0.04-0.06 mm narrower than the surface does)
SUBCELL = 0.2
#: Sub-samples per cell side for the bead's exact metal fractions
FRACTION_SAMPLES = 40
#: Height [m] above which the prescribed bead is liquid: on a cell face
#: (the mesh's faces lie at -5 mm + k CELL), so that every layer of cells
#: above it has one liquid fraction and the section's liquid share is a
#: sum of the half-ellipse's areas between faces
LIQUID_LEVEL = 1.0e-3
#: Depth of the prescribed mushy zone [m]: the liquid fraction rises
#: linearly with the cell centre's height from 0 at LIQUID_LEVEL to 1 at
#: LIQUID_LEVEL + MUSHY_DEPTH, so the two layers of cells in it are a
#: quarter and three quarters liquid (a solved pool's edge is mushy, and
#: the share weights each cell's metal by its fraction)
MUSHY_DEPTH = 2 * CELL
#: Preset liquid pool of the run (template coordinates [m]) and its temperature [K]
PRESET_POOL_BOX = "(0.008 -0.004 -0.003) (0.022 0.004 0)"
PRESET_POOL_TEMPERATURE = 2000.0
#: Transverse section of the bead's field-read metrics [m]: on the bead,
#: over the pool
FIELD_SECTION = 12e-3
#: Largest relative difference between the field-read metrics of the ranks'
#: folders and of the reconstructed time (the same numbers, summed in
#: another order)
RANKS_AGREEMENT = 1e-9
#: Largest relative difference between two evaluations of the function
#: object (serial and parallel; during a run and by ldna post from the fields
#: written with 12 digits)
AGREEMENT = 1e-5


def prescribed_fields(centres: np.ndarray,
                      fusion_temperature_: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Temperature, metal fraction and liquid fraction of the prescribed pool
    and bead at cell centres.

    The fusion line is located between cell centres by interpolating the
    temperature: the field is continuous, as a solved one is, not a step.
    """
    x, y, z = centres.T
    a, b, c = POOL_SEMI_AXES
    radius = np.sqrt(((x - POOL_CENTRE[0]) / a) ** 2 + ((y - POOL_CENTRE[1]) / b) ** 2
                     + (z / c) ** 2)
    temperature = np.clip(fusion_temperature_ + POOL_GRADIENT * c * (1 - radius),
                          COLD_TEMPERATURE, POOL_TEMPERATURE)
    # The bead's metal fraction: the share of each cell's (y, z) square
    # inside the half-ellipse (the bead is uniform along x)
    offsets = (np.arange(FRACTION_SAMPLES) + 0.5) / FRACTION_SAMPLES - 0.5
    sy = y[:, None, None] + CELL * offsets[None, :, None]
    sz = z[:, None, None] + CELL * offsets[None, None, :]
    fraction = ((sy / BEAD_HALF_WIDTH) ** 2 + (sz / BEAD_HEIGHT) ** 2 < 1).mean(axis=(1, 2))
    alpha = np.where(z < 0, 1.0, np.where(x > BEAD_START, fraction, 0.0))
    liquid = np.clip((z - LIQUID_LEVEL) / MUSHY_DEPTH, 0.0, 1.0)
    return temperature, alpha, liquid


def area_share_above(level: float) -> float:
    """Share of the half-ellipse bead's area above the height ``level``:
    (4/pi) times the integral of sqrt(1 - u^2) from level/BEAD_HEIGHT to 1."""
    s = min(level / BEAD_HEIGHT, 1.0)
    return 4 / math.pi * (math.pi / 4 - (s * math.sqrt(1 - s * s) + math.asin(s)) / 2)


def prescribed_liquid_share() -> float:
    """The bead's liquid share in the section: each layer of cells above
    LIQUID_LEVEL holds the half-ellipse's area between its faces, liquid by
    the prescribed fraction at its centre height."""
    share, bottom = 0.0, LIQUID_LEVEL
    while bottom < BEAD_HEIGHT:
        fraction = min((bottom + CELL / 2 - LIQUID_LEVEL) / MUSHY_DEPTH, 1.0)
        share += fraction * (area_share_above(bottom) - area_share_above(bottom + CELL))
        bottom += CELL
    return share


def pool_isotherm_radius(case: Case) -> float:
    """Normalised radius of the pool's edge, T = (solidus + liquidus)/2 of the metal."""
    metal = Metal.substrate_of(case.path)
    pool_temperature = 0.5 * (metal.solidus + metal.liquidus)
    return 1 - (pool_temperature - fusion_temperature(case)) / (POOL_GRADIENT * POOL_SEMI_AXES[2])


def expected_metrics(pool_radius: float) -> BeadMetrics:
    """The prescribed shapes' metrics; the pool ends at ``pool_radius`` of its ellipsoid."""
    a, b, c = POOL_SEMI_AXES
    fused_area = math.pi * b * c / 2
    bead_area = math.pi * BEAD_HALF_WIDTH * BEAD_HEIGHT / 2
    return BeadMetrics(
        pool_length=2 * a * pool_radius, pool_width=2 * b * pool_radius, penetration=c,
        pool_volume=2 * math.pi * a * b * c / 3,
        bead_width=2 * BEAD_HALF_WIDTH, bead_height=BEAD_HEIGHT,
        bead_area=bead_area, fused_area=fused_area,
        dilution=fused_area / (fused_area + bead_area),
        peak_temperature=POOL_TEMPERATURE,
    )


def area_tolerance(semi_axis_1: float, semi_axis_2: float) -> float:
    """Area a staircase of cells can miss on a half-ellipse: half a cell along its arc.

    The flat side lies on the substrate surface, on cell faces: no error there.
    """
    arc = math.pi * math.sqrt((semi_axis_1 ** 2 + semi_axis_2 ** 2) / 2) / 2
    return arc * CELL / 2


@pytest.fixture
def synthetic_pool_case(tmp_path: Path) -> Case:
    """The synthetic case, meshed, with the prescribed fields at time 0."""
    case = prepare_test_case("syntheticPool", tmp_path, material_from_template=True)
    case.run("blockMesh")
    case.run("postProcess -func writeCellCentres -time 0", log_name="writeCellCentres")
    temperature, alpha, liquid = prescribed_fields(case.field("C", "0"), fusion_temperature(case))
    case.write_field("T", time="0", values=temperature)
    case.write_field("alpha.metal", time="0", values=alpha)
    case.write_field("liquidFraction", time="0", values=liquid)
    return case


def check_against_prescribed(result: BeadMetrics, label: str, pool_radius: float) -> None:
    """Sizes within a fifth of a cell, areas within the staircase error, of the prescribed shapes."""
    expected = expected_metrics(pool_radius)
    print(f"{label}: {result}")
    for size in ("pool_length", "pool_width", "penetration", "bead_width", "bead_height"):
        error = abs(getattr(result, size) - getattr(expected, size))
        print(f"  {size}: {1e3 * getattr(result, size):.3f} mm against "
              f"{1e3 * getattr(expected, size):.3f} mm")
        assert error <= SUBCELL * CELL, size
    fused_tolerance = area_tolerance(POOL_SEMI_AXES[1], POOL_SEMI_AXES[2])
    bead_tolerance = area_tolerance(BEAD_HALF_WIDTH, BEAD_HEIGHT)
    print(f"  fused area {1e6 * result.fused_area:.3f} mm2 against "
          f"{1e6 * expected.fused_area:.3f} (tolerance {1e6 * fused_tolerance:.3f})")
    print(f"  bead area {1e6 * result.bead_area:.3f} mm2 against "
          f"{1e6 * expected.bead_area:.3f} (tolerance {1e6 * bead_tolerance:.3f})")
    assert abs(result.fused_area - expected.fused_area) <= fused_tolerance
    assert abs(result.bead_area - expected.bead_area) <= bead_tolerance
    low = (expected.fused_area - fused_tolerance) / (
        expected.fused_area - fused_tolerance + expected.bead_area + bead_tolerance)
    high = (expected.fused_area + fused_tolerance) / (
        expected.fused_area + fused_tolerance + expected.bead_area - bead_tolerance)
    print(f"  dilution {result.dilution:.4f} against {expected.dilution:.4f} "
          f"(bounds {low:.4f}-{high:.4f})")
    assert low <= result.dilution <= high
    assert result.peak_temperature == pytest.approx(POOL_TEMPERATURE)
    # The deepest fusion lies under the pool's centre, within a cell
    print(f"  deepest fusion at x = {1e3 * result.fused_section:.2f} mm")
    assert abs(result.fused_section - POOL_CENTRE[0]) <= CELL
    # The bead (5.2 mm wide) lies on the pool (6.2 mm wide): bonded across
    # its width, within one cell at each toe
    assert abs(result.bonded_width - 2 * BEAD_HALF_WIDTH) <= 2 * CELL
    assert result.bonded_width + result.unbonded_width == pytest.approx(result.bead_width)


def function_object_result(case: Case) -> BeadMetrics:
    """The last row of the case's meltPoolMetrics.dat."""
    row = read_function_object_metrics(case)[-1]
    return BeadMetrics(**dict(zip(BeadMetrics.FUNCTION_OBJECT_COLUMNS, row[1:])))


def check_agreement(a: BeadMetrics, b: BeadMetrics) -> None:
    """Two metric sets equal to AGREEMENT (relative to each metric's size)."""
    for name, value in a.as_dict().items():
        if name in BeadMetrics.POST_ONLY:
            continue
        other = b.as_dict()[name]
        if math.isnan(value) and math.isnan(other):
            continue  # the chemical dilution of a case with one metal
        assert abs(value - other) <= AGREEMENT * max(abs(value), abs(other), 1e-12), name


def test_metrics_of_a_prescribed_pool(synthetic_pool_case: Case, tmp_path: Path) -> None:
    case = synthetic_pool_case
    parallel = Case(Path(shutil.copytree(case, tmp_path / "parallel")))

    case.run("postProcess -fields '(T alpha.metal)' -time 0", log_name="postProcess")
    serial_result = function_object_result(case)
    pool_radius = pool_isotherm_radius(case)
    check_against_prescribed(serial_result, "function object, serial", pool_radius)

    parallel.run("decomposePar -time 0")
    parallel.run("postProcess -fields '(T alpha.metal)' -time 0", n_procs=2,
                 log_name="postProcess")
    parallel_result = function_object_result(parallel)
    check_against_prescribed(parallel_result, "function object, 2 ranks", pool_radius)

    check_agreement(serial_result, parallel_result)


def test_section_fields_of_the_ranks_folders(synthetic_pool_case: Case, tmp_path: Path) -> None:
    """The bead study's field-read metrics (``ldna.section_fields``) of a
    time that only the ranks' folders hold, as a running decomposed study
    has it, equal those of the same time reconstructed, and are the
    prescribed bead's.  The two ranks split the section across the weld
    (decomposeParDict: y), so a reader that saw one rank would halve the
    body width."""
    case = synthetic_pool_case
    case.set("system/controlDict", "functions/meltPoolMetrics/beadSection",
             f"{FIELD_SECTION:g}", create=True)
    # A written time after 0: the table skips the initial fields
    shutil.copytree(case / "0", case / "1")
    ranks = Case(Path(shutil.copytree(case, tmp_path / "ranks")))
    ranks.run("decomposePar -time 1")
    shutil.rmtree(ranks / "1")

    reconstructed = section_fields.update(case.path)
    decomposed = section_fields.update(ranks.path)
    assert list(reconstructed) == list(decomposed) == [1.0]
    kept = section_fields.read(ranks.path)
    for name in section_fields.COLUMNS:
        # the table keeps 9 significant digits
        assert kept[1.0][name] == pytest.approx(decomposed[1.0][name], rel=1e-8), name
    for name in section_fields.COLUMNS:
        print(f"{name}: ranks {decomposed[1.0][name]:.6g}, reconstructed {reconstructed[1.0][name]:.6g}")
        assert decomposed[1.0][name] == pytest.approx(reconstructed[1.0][name], rel=RANKS_AGREEMENT,
                                                      abs=1e-15), name

    # The prescribed half-ellipse: thicker than its body share of its height
    # (BODY_HEIGHT_SHARE) over 2 a sqrt(1 - share^2); the profile's edges lie on cell faces, each
    # within a cell of the exact point
    body = 2 * BEAD_HALF_WIDTH * math.sqrt(1 - BODY_HEIGHT_SHARE ** 2)
    assert abs(decomposed[1.0]["body_width"] - body) <= 2 * CELL
    # It stands on the substrate's surface: gas only where its flanks are
    # lower than the first layer of cells, near the toes
    assert 0 <= decomposed[1.0]["first_layer_gas"] < CELL / 10
    assert 0 < decomposed[1.0]["wetting_angle"] <= 90
    # The mushy and liquid top of the bead: its share of the area is the
    # exact half-ellipse's between the layers' faces, weighted by their
    # liquid fractions, within the metal fractions' sampling (half a
    # sub-sample along the arc, on both areas of the ratio)
    liquid = prescribed_liquid_share()
    sampling = area_tolerance(BEAD_HALF_WIDTH, BEAD_HEIGHT) / FRACTION_SAMPLES
    bead = math.pi * BEAD_HALF_WIDTH * BEAD_HEIGHT / 2
    print(f"section liquid share {decomposed[1.0]['section_liquid']:.5f} against {liquid:.5f}")
    assert decomposed[1.0]["section_liquid"] == pytest.approx(liquid, abs=2 * sampling / bead)


def test_post_writes_pictures_headless(synthetic_pool_case: Case) -> None:
    case = synthetic_pool_case
    result, pictures, _ = post_process(case, time=0.0)
    assert [p.name for p in pictures] == ["surface.png", "transverse.png", "longitudinal.png",
                                          "transverse-metal.png"]
    for picture in pictures:
        data = picture.read_bytes()
        assert data.startswith(b"\x89PNG"), picture
        assert len(data) > 10_000, f"{picture.name}: {len(data)} bytes"
    check_against_prescribed(result, "ldna post (pictures run)",
                             pool_isotherm_radius(synthetic_pool_case))
    table = (case / "pictures" / "metrics.csv").read_text().splitlines()
    assert len(table) == 2 and table[0].startswith("time,pool_length")


def test_function_object_and_post_agree_on_a_run(ldna_case: Case) -> None:
    """The LDNA template, run briefly: metrics written in the run and read by
    post agree, at the last written time and at an earlier one."""
    case = ldna_case
    end_time = "0.03"
    case.set("system/controlDict", "endTime", end_time)
    case.set("system/controlDict", "writeInterval", f"{float(end_time) / 2:g}")
    case.set("system/controlDict", "writePrecision", "12")
    # The bead section under the droplets: they have not reached the
    # template's section downstream yet
    under_droplets = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    for entry, value in (("writeControl", "writeTime"), ("writeInterval", "1"),
                         ("beadSection", f"{under_droplets:g}")):
        case.set("system/controlDict", f"functions/meltPoolMetrics/{entry}", value)
    # A liquid pool under the droplets from the start, so that every metric is exercised
    set_fields = case / "system" / "setFieldsDict"
    set_fields.write_text(set_fields.read_text().replace("regions\n(", f"""regions
(
    boxToCell
    {{
        box {PRESET_POOL_BOX};
        fieldValues (volScalarFieldValue T {PRESET_POOL_TEMPERATURE});
    }}""", 1))
    case.mesh()
    case.run("setFields")
    case.run("ldnaFoam")

    rows = read_function_object_metrics(case)
    for time in (float(end_time) / 2, float(end_time)):
        row = rows[np.argmin(np.abs(rows[:, 0] - time))]
        assert row[0] == pytest.approx(time)
        written = BeadMetrics(**dict(zip(BeadMetrics.FUNCTION_OBJECT_COLUMNS, row[1:])))
        computed = function_object_metrics(case, time, bead_section=configured_bead_section(case))
        print(f"t = {time} s\nfunction object: {written}\nldna post:       {computed}")
        assert written.bead_area > 0, "the droplets have built some bead"
        assert written.penetration > 0 and written.pool_length > 0, "the preset pool is still liquid"
        check_agreement(written, computed)
