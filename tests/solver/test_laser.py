"""Laser heating and free-surface heat losses.

A closed 8 x 8 x 4 mm box of argon over a 2 mm slab of 316L (0.25 mm
cells, surface on cell faces, no gravity) is lit by a vertical beam of
radius 1 mm for one time step.  The laser writes its target and power
balance every step (postProcessing/laser/0/power.dat) and the absorbed
power density; the tests check them against the beam power, the Fresnel
equations, the Beer-Lambert law and Monte-Carlo statistics, on meshes with
cells larger and smaller than the beam and unequal heights at the surface,
in a V-groove (multiple reflections) and under a metal sphere (shadowing),
and the heat-loss model against the Stefan-Boltzmann law.
"""
from __future__ import annotations

import math
import shutil
from typing import Callable

import numpy as np
import pytest

from solver_cases import TEST_CASES
from ldna.case import Case

#: Beam power [W], radius [m] and the slab's absorptivity in these tests
POWER = 1000.0
BEAM_RADIUS = 1e-3
ABSORPTIVITY = 0.36
#: Target: the centre of the slab surface [m]
CENTRE = (4e-3, 4e-3, 2e-3)
#: Cell size [m] and the box's horizontal area [m2] (tests/cases/laserSlab)
CELL = 0.25e-3
SURFACE_AREA = 8e-3 * 8e-3
#: Default Beer-Lambert attenuation: -ln(exp(-4))/1 mm (paper eq. 10-11)
MU = 4000.0

#: Allowed errors: absorbed power on the flat slab, and on any mesh
ABSORBED_TOLERANCE = 0.01
ANY_MESH_TOLERANCE = 0.005
PARALLEL_TOLERANCE = 0.005
V_GROOVE_TOLERANCE = 0.01
SHADOW_TOLERANCE = 0.02
BALANCE_TOLERANCE = 1e-9
DECAY_TOLERANCE = 0.05
RADIATION_TOLERANCE = 0.01
#: Fresnel test: a narrower beam (0.5 mm), so that even at 75 degrees its
#: elongated footprint stays on the 8 mm slab; every ray meets the surface at
#: the laser angle, so a(theta) P holds up to the share of rays that cross
#: the 2 mm slab (exp(-8) at normal incidence)
FRESNEL_BEAM_RADIUS = 0.5e-3
FRESNEL_TOLERANCE = 0.002

#: Columns of postProcessing/laser/<time>/power.dat
BALANCE_COLUMNS = ("time", "x", "y", "z", "emitted", "metal", "gas", "reflected", "escaped",
                   "stopped", "imbalance", "pool", "deposit", "substrate")


def laser_entry(model: str, extra: str = "", coeffs: str = "") -> str:
    """An fvOptions entry for a laser on the slab centre (no oscillation unless given)."""
    oscillation = "" if "oscillation" in extra else "oscillationAmplitude 0;"
    return f"""
laser
{{
    type            laserHeatSource;
    absorptionModel {model};
    power           constant {POWER};
    beamRadius      {BEAM_RADIUS};
    position        ({CENTRE[0]} {CENTRE[1]} {CENTRE[2]});
    absorptivity    constant {ABSORPTIVITY};
    {oscillation}
    {extra}
    {model}Coeffs
    {{
        {coeffs}
    }}
}}
"""


def write_fv_options(case: Case, entries: str) -> None:
    """Replace the case's fvOptions by ``entries``."""
    header = (case / "constant" / "fvOptions").read_text().split("// The test writes")[0]
    (case / "constant" / "fvOptions").write_text(header + entries + "\n")


def laser_balances(case: Case) -> np.ndarray:
    """The laser's target and power balance per time step (its postProcessing table)."""
    rows = case.function_object("laser", "power.dat")
    assert len(rows), f"no laser table in {case}/postProcessing/laser"
    return np.array([tuple(row) for row in rows], dtype=[(n, float) for n in BALANCE_COLUMNS])


def absorbed_total(balance: np.ndarray) -> np.ndarray:
    """Power absorbed in metal and gas cells [W]."""
    return balance["metal"] + balance["gas"]


def assert_balance_closes(balance: np.ndarray) -> None:
    """Emitted = absorbed + reflected + escaped + stopped, every step, and no negative share."""
    booked = (absorbed_total(balance) + balance["reflected"] + balance["escaped"]
              + balance["stopped"])
    assert np.abs(balance["emitted"] - booked).max() < BALANCE_TOLERANCE * POWER
    for share in ("metal", "gas", "reflected", "escaped", "stopped"):
        assert balance[share].min() >= -BALANCE_TOLERANCE * POWER, share


def absorbed_per_cell(case: Case) -> np.ndarray:
    """Absorbed power per cell [W] of the last written time (power density x volume)."""
    last = case.times[-1]
    return case.field("laserPowerDensity", last) * CELL**3


def cell_centres(case: Case) -> np.ndarray:
    """Cell centres of the slab mesh (i fastest, then j, then k: blockMesh order)."""
    n = (32, 32, 16)
    k, j, i = np.meshgrid(*(np.arange(m) for m in n[::-1]), indexing="ij")
    return np.stack([(i.ravel() + 0.5) * CELL, (j.ravel() + 0.5) * CELL,
                     (k.ravel() + 0.5) * CELL], axis=1)


MODELS = ("gaussianSurface", "beerLambert", "monteCarlo")


@pytest.mark.parametrize("model", MODELS)
def test_absorbed_power_is_a_times_P(laser_slab_case: Case, model: str) -> None:
    """A flat slab absorbs a P with each model at its default settings.

    Monte-Carlo rays reflect at the surface and leave (nothing sends them
    back), Beer-Lambert rays lose all their power in the 2 mm slab
    (exp(-8) passes), surface rays give a at the surface.
    """
    case = laser_slab_case
    write_fv_options(case, laser_entry(model))
    case.run("ldnaFoam")

    balance = laser_balances(case)
    absorbed = absorbed_per_cell(case).sum()
    expected = ABSORPTIVITY * POWER
    print(f"{model}: absorbed {absorbed:.4f} W (table: metal {balance['metal'][-1]:.4f}, "
          f"gas {balance['gas'][-1]:.4f}), a P = {expected:.4f} W, reflected "
          f"{balance['reflected'][-1]:.4f} W, escaped {balance['escaped'][-1]:.4f} W")
    assert abs(absorbed - expected) / expected < ABSORBED_TOLERANCE
    # The table books the power of the field, and the balance closes
    assert absorbed_total(balance)[-1] == pytest.approx(absorbed, rel=1e-6)
    assert_balance_closes(balance)


def test_beer_lambert_decays_exponentially(laser_slab_case: Case) -> None:
    case = laser_slab_case
    write_fv_options(case, laser_entry("beerLambert"))
    case.run("ldnaFoam")

    absorbed = absorbed_per_cell(case)
    z = cell_centres(case)[:, 2]
    depths = np.unique(z[z < CENTRE[2]])[::-1]
    per_layer = np.array([absorbed[np.isclose(z, d)].sum() for d in depths])
    depth_below_surface = CENTRE[2] - depths
    # The first six layers (1.5 mm, 6 optical depths): beyond, the layers
    # hold less than 1e-3 of the power
    fitted = -np.polyfit(depth_below_surface[:6], np.log(per_layer[:6]), 1)[0]
    print(f"per-layer absorbed power {per_layer[:6]} W; fitted mu {fitted:.2f} 1/m, "
          f"expected {MU} 1/m")
    assert abs(fitted - MU) / MU < DECAY_TOLERANCE
    # No power above the metal surface
    assert absorbed[z > CENTRE[2]].sum() < 1e-9 * POWER


def test_monte_carlo_sampling_noise(laser_slab_case: Case) -> None:
    """The Monte-Carlo beam's footprint converges like 1/sqrt(N).

    On the flat slab every ray gives a at the surface, so the absorbed total
    is a P at any N; where the rays land is random.  The power absorbed
    in the cells within one beam radius of the target (about 95 % of a P
    for the Gaussian of eq. 48) scatters from step to step (each step draws
    new rays) like 1/sqrt(N).
    """
    case = laser_slab_case
    steps = 8
    case.set("system/controlDict", "endTime", f"{steps * 1e-5:g}")
    case.set("system/controlDict", "writeInterval", "1")
    centres = cell_centres(case)
    inside = np.hypot(centres[:, 0] - CENTRE[0], centres[:, 1] - CENTRE[1]) < BEAM_RADIUS
    spreads = {}
    for n_rays in (250, 1000, 4000):
        write_fv_options(case, laser_entry("monteCarlo", coeffs=f"nRays {n_rays}; seed 7;"))
        case.run("ldnaFoam", log_name=f"ldnaFoam.{n_rays}")
        balance = laser_balances(case)
        assert len(balance) == steps
        assert_balance_closes(balance)
        assert np.abs(absorbed_total(balance) - ABSORPTIVITY * POWER).max() < (
            ABSORBED_TOLERANCE * ABSORPTIVITY * POWER)
        central = np.array([
            (case.field("laserPowerDensity", time) * CELL**3)[inside].sum()
            for time in case.times[1:]])
        spreads[n_rays] = central.std(ddof=1)
        print(f"N = {n_rays}: within r_l {central.mean():.2f} +- {spreads[n_rays]:.2f} W")

    ns = np.array(sorted(spreads), dtype=float)
    slope = np.polyfit(np.log(ns), np.log([spreads[n] for n in sorted(spreads)]), 1)[0]
    print(f"scatter of the central power ~ N^{slope:.3f} (expected -0.5)")
    assert -0.8 < slope < -0.2


def footprint_share(x0: np.ndarray, x1: np.ndarray, y0: np.ndarray, y1: np.ndarray,
                    target: tuple[float, float], radius: float) -> np.ndarray:
    """Share of eq. 48's Gaussian, 3 P/(pi r^2) exp(-3 r^2 / r_l^2), that falls
    on the rectangles [x0, x1] x [y0, y1] (separable: a product of erfs)."""
    k = math.sqrt(3) / radius
    erf = np.vectorize(math.erf)
    return 0.25 * ((erf(k * (x1 - target[0])) - erf(k * (x0 - target[0])))
                   * (erf(k * (y1 - target[1])) - erf(k * (y0 - target[1]))))


#: The beam's target off the cell corners by a fraction of a cell [m]: the
#: pixels the beam is traced as (64 over 4 radii, 1/16 mm) then straddle
#: the cells' faces
OFF_GRID = (0.1e-3, 0.037e-3)
#: What normalising the pixels to the whole beam adds (the Gaussian beyond
#: two radii, exp(-12)) and round-off: a share of a P per cell
PIXEL_NORMALISATION = 1e-5


@pytest.mark.parametrize("shift", [(0.0, 0.0), OFF_GRID])
def test_each_surface_cell_gets_the_beam_over_its_footprint(laser_slab_case: Case,
                                                            shift: tuple[float, float]) -> None:
    """gaussianSurface on the flat slab: each surface cell absorbs a times the
    beam's power over its footprint (eq. 48 integrated here), not only the
    slab in total.  With the target on a cell corner the beam's pixels tile
    the cells; off it, a pixel across a face gives its power to one side, so
    a cell may be off by at most the power in a band of half a pixel on both
    sides of its edges."""
    case = laser_slab_case
    target = (CENTRE[0] + shift[0], CENTRE[1] + shift[1])
    entry = laser_entry("gaussianSurface").replace(
        f"position        ({CENTRE[0]} {CENTRE[1]} {CENTRE[2]});",
        f"position        ({target[0]} {target[1]} {CENTRE[2]});")
    write_fv_options(case, entry)
    case.run("ldnaFoam")

    absorbed = absorbed_per_cell(case)
    centres = cell_centres(case)
    top = np.isclose(centres[:, 2], CENTRE[2] - 0.5 * CELL)
    assert absorbed[~top].sum() < 1e-9 * POWER, "all the power in the surface cells"
    x0, y0 = centres[top, 0] - 0.5 * CELL, centres[top, 1] - 0.5 * CELL
    x1, y1 = x0 + CELL, y0 + CELL
    expected = ABSORPTIVITY * POWER * footprint_share(x0, x1, y0, y1, target, BEAM_RADIUS)
    pixel = 4 * BEAM_RADIUS / 64
    half = 0.5 * pixel if shift != (0.0, 0.0) else 0.0
    band = ABSORPTIVITY * POWER * (
        footprint_share(x0 - half, x1 + half, y0 - half, y1 + half, target, BEAM_RADIUS)
        - footprint_share(x0 + half, x1 - half, y0 + half, y1 - half, target, BEAM_RADIUS))
    allowed = band + PIXEL_NORMALISATION * ABSORPTIVITY * POWER
    difference = np.abs(absorbed[top] - expected)
    worst = int(np.argmax(difference / allowed))
    print(f"target shifted {1e3 * np.array(shift)} mm: largest cell difference "
          f"{difference.max():.4e} W (peak cell {expected.max():.4f} W); worst against its "
          f"bound: {difference[worst]:.4e} of {allowed[worst]:.4e} W; "
          f"sum |difference| {difference.sum():.4f} W of a P {ABSORPTIVITY * POWER:.1f} W")
    assert np.all(difference <= allowed)


@pytest.mark.parametrize("model", ("beerLambert", "monteCarlo"))
def test_serial_and_parallel_agree(laser_slab_case: Case, model: str) -> None:
    """A tilted beam crosses the processor boundary at x = 4 mm.

    Beer-Lambert rays are deterministic, and Monte-Carlo rays start the same
    on every processor count and are handed over whole: the decomposed run
    must absorb the same power in every cell (the totals equal a P whatever
    the rays do, so the cells are compared).
    """
    case = laser_slab_case
    case.run("decomposePar")
    write_fv_options(case, laser_entry(model, extra="angle 30;"))
    case.run("ldnaFoam", log_name="ldnaFoam.serial")
    serial = absorbed_per_cell(case)
    serial_balance = laser_balances(case)
    case.run("ldnaFoam", n_procs=2, log_name="ldnaFoam.parallel")
    case.run("reconstructPar -latestTime", log_name="reconstructPar")
    parallel = absorbed_per_cell(case)
    parallel_balance = laser_balances(case)
    assert_balance_closes(parallel_balance)
    print(f"{model}: total {serial.sum():.6f} W serial, {parallel.sum():.6f} W parallel")
    assert parallel.sum() == pytest.approx(serial.sum(), rel=PARALLEL_TOLERANCE)
    assert absorbed_total(parallel_balance)[-1] == pytest.approx(
        absorbed_total(serial_balance)[-1], rel=PARALLEL_TOLERANCE)
    difference = np.abs(serial - parallel).max() / serial.max()
    print(f"largest cell difference {difference:.2e} of the peak")
    assert difference < 1e-9


def fresnel_absorptivity(theta: float, n: float, k: float) -> float:
    """1 - R of unpolarised light from vacuum on a medium n + i k (Fresnel, Snell's law)."""
    index = complex(n, k)
    cos_i = math.cos(theta)
    cos_t = np.sqrt(1 - (math.sin(theta) / index) ** 2)
    r_s = (cos_i - index * cos_t) / (cos_i + index * cos_t)
    r_p = (index * cos_i - cos_t) / (index * cos_i + cos_t)
    return 1 - 0.5 * (abs(r_s) ** 2 + abs(r_p) ** 2)


@pytest.mark.parametrize("angle", [0.0, 45.0, 75.0])
def test_fresnel_absorptivity_follows_the_incidence_angle(laser_slab_case: Case,
                                                          angle: float) -> None:
    """Iron at 1.03 um (n 3.2, k 4.2) lit at the laser angle, default settings.

    Every ray meets the flat slab at the laser angle, gives up a(theta) and
    is reflected away from it, so the absorbed power is a(theta) P.
    """
    case = laser_slab_case
    n, k = 3.2, 4.2
    entry = laser_entry("monteCarlo", extra=f"angle {angle};")
    entry = entry.replace(f"absorptivity    constant {ABSORPTIVITY};",
                          f"fresnel {{ n {n}; k {k}; }}")
    write_fv_options(case, entry.replace(f"beamRadius      {BEAM_RADIUS}",
                                         f"beamRadius      {FRESNEL_BEAM_RADIUS}"))
    case.run("ldnaFoam")

    balance = laser_balances(case)
    absorbed = absorbed_total(balance)[-1]
    expected = fresnel_absorptivity(math.radians(angle), n, k) * POWER
    print(f"angle {angle}: absorbed {absorbed:.4f} W, a(theta) P = {expected:.4f} W")
    assert abs(absorbed - expected) / expected < ABSORBED_TOLERANCE
    assert_balance_closes(balance)


def test_beam_follows_the_oscillation(laser_slab_case: Case) -> None:
    """Target and absorbed power move as offset + A sin(2 pi f t) across the seam."""
    case = laser_slab_case
    amplitude, frequency = 2e-3, 10.0
    case.set("system/controlDict", "deltaT", "0.005")
    case.set("system/controlDict", "maxDeltaT", "0.005")
    case.set("system/controlDict", "endTime", "0.02")
    write_fv_options(case, laser_entry(
        "gaussianSurface",
        extra=f"oscillationAmplitude {amplitude}; oscillationFrequency {frequency}; "
              "offset constant (0.0005 0 0);"))
    case.run("ldnaFoam")

    balances = laser_balances(case)
    expected_y = CENTRE[1] + amplitude * np.sin(2 * np.pi * frequency * balances["time"])
    assert np.abs(balances["y"] - expected_y).max() < 1e-12
    assert np.abs(balances["x"] - (CENTRE[0] + 5e-4)).max() < 1e-12

    # The absorbed power is centred on the target (last step, t = 0.02 s)
    absorbed = absorbed_per_cell(case)
    centroid = (cell_centres(case) * absorbed[:, None]).sum(axis=0) / absorbed.sum()
    print(f"target y {balances['y'][-1] * 1e3:.4f} mm, absorbed-power centroid "
          f"y {centroid[1] * 1e3:.4f} mm")
    assert abs(centroid[1] - balances["y"][-1]) < 0.2 * CELL
    assert abs(centroid[0] - balances["x"][-1]) < 0.2 * CELL


def box_mesh(case: Case, x: tuple[float, float, int], y: tuple[float, float, int],
             z_levels: list[float], z_cells: list[int]) -> None:
    """A box [mm] of stacked blocks: x and y (start, end, cells), blocks between
    the z_levels with z_cells layers each (cells of unequal heights where
    blocks meet), all faces walls.  Meshed with blockMesh, alpha.metal reset."""
    text = (case / "system" / "blockMeshDict").read_text()
    head = text.partition("vertices")[0]
    (x0, x1, nx), (y0, y1, ny) = x, y
    vertices = "\n".join(f"    ({x0} {y0} {z}) ({x1} {y0} {z}) ({x1} {y1} {z}) ({x0} {y1} {z})"
                         for z in z_levels)
    blocks, sides = [], []
    for k, nz in enumerate(z_cells):
        a, b = 4 * k, 4 * (k + 1)
        blocks.append(f"    hex ({a} {a + 1} {a + 2} {a + 3} {b} {b + 1} {b + 2} {b + 3}) "
                      f"({nx} {ny} {nz}) simpleGrading (1 1 1)")
        sides.append(f"({a} {b} {b + 3} {a + 3}) ({a + 1} {a + 2} {b + 2} {b + 1}) "
                     f"({a} {a + 1} {b + 1} {b}) ({a + 3} {b + 3} {b + 2} {a + 2})")
    top = 4 * len(z_cells)
    faces = [f"(0 3 2 1) ({top} {top + 1} {top + 2} {top + 3})"] + sides
    (case / "system" / "blockMeshDict").write_text(head + f"""vertices
(
{vertices}
);

blocks
(
{chr(10).join(blocks)}
);

boundary
(
    walls
    {{
        type wall;
        faces
        (
            {chr(10).join("            " + f for f in faces).strip()}
        );
    }}
);
""")
    case.run("blockMesh")
    shutil.copy(TEST_CASES / "laserSlab" / "0" / "alpha.metal", case / "0" / "alpha.metal")


def cell_geometry(case: Case) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres and sizes (dx, dy, dz) of a box mesh of cuboid cells [m]."""
    case.run("postProcess -func writeCellCentres -time 0", log_name="writeCellCentres")
    case.run("postProcess -func writeCellVolumes -time 0", log_name="writeCellVolumes")
    centres = case.field("C", "0")
    volumes = case.field("V", "0")
    xs, ys = np.unique(centres[:, 0]), np.unique(centres[:, 1])
    dx, dy = xs[1] - xs[0], ys[1] - ys[0]
    sizes = np.stack([np.full(len(centres), dx), np.full(len(centres), dy),
                      volumes / (dx * dy)], axis=1)
    return centres, sizes


def fraction_below(centres: np.ndarray, sizes: np.ndarray, height: Callable,
                   samples: int = 8) -> np.ndarray:
    """Volume fraction of each cell below z = height(x, y) [m], sampled on
    samples x samples columns per cell (exact for a surface flat in a column)."""
    offsets = (np.arange(samples) + 0.5) / samples - 0.5
    fraction = np.zeros(len(centres))
    bottom = centres[:, 2] - 0.5 * sizes[:, 2]
    for ox in offsets:
        for oy in offsets:
            top = height(centres[:, 0] + ox * sizes[:, 0], centres[:, 1] + oy * sizes[:, 1])
            fraction += np.clip((top - bottom) / sizes[:, 2], 0.0, 1.0)
    return fraction / samples**2


#: Meshes of the any-mesh test on the 8 x 8 x 4 mm box: (cells across,
#: z levels [mm], layers per block, surface height [mm]): cells of 2 mm
#: (twice the beam radius), of 0.125 mm, of unequal heights at the surface
#: (0.5 mm below, 0.2 mm above), and a surface inside a layer of cells
#: (metal fraction 0.4 in the interface cells)
ANY_MESHES = {
    "cells_larger_than_the_beam": (4, [0, 2, 4], [1, 1], 2.0),
    "cells_smaller_than_the_beam": (64, [0, 1.5, 2, 4], [2, 4, 16], 2.0),
    "unequal_heights": (20, [0, 2, 4], [4, 10], 2.0),
    "surface_inside_cells": (32, [0, 4], [16], 2.1),
}


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("mesh", list(ANY_MESHES))
def test_configured_power_on_any_mesh(laser_slab_case: Case, model: str, mesh: str) -> None:
    """The absorbed power is a P within 0.5 % whatever the cells at the surface."""
    case = laser_slab_case
    across, z_levels, z_cells, surface = ANY_MESHES[mesh]
    box_mesh(case, (0, 8, across), (0, 8, across), z_levels, z_cells)
    centres, sizes = cell_geometry(case)
    alpha = fraction_below(centres, sizes, lambda x, y: np.full_like(x, surface * 1e-3))
    case.write_field("alpha.metal", time="0", values=alpha)
    write_fv_options(case, laser_entry(model))
    case.run("ldnaFoam")

    balance = laser_balances(case)
    absorbed = absorbed_total(balance)[-1]
    expected = ABSORPTIVITY * POWER
    print(f"{mesh}, {model}: absorbed {absorbed:.4f} W, a P = {expected:.4f} W")
    assert abs(absorbed - expected) / expected < ANY_MESH_TOLERANCE
    assert_balance_closes(balance)


#: V-groove: 45 degree walls meeting at x = 4 mm, z = 0.5 mm, up to the
#: 4 mm top; the beam (radius 0.5 mm) lights the left wall only, 2 mm from
#: the bottom, so every ray meets it at 45 degrees, crosses to the right
#: wall and leaves upwards: 1 - (1 - a)^2 absorbed
GROOVE_BOTTOM = (4e-3, 0.5e-3)
GROOVE_BEAM_X = 2.2e-3
GROOVE_BEAM_RADIUS = 0.5e-3


@pytest.mark.parametrize("n_procs", [1, 2])
def test_monte_carlo_multiple_reflections_in_a_v_groove(laser_slab_case: Case,
                                                        n_procs: int) -> None:
    case = laser_slab_case
    box_mesh(case, (0, 8, 64), (3, 5, 16), [0, 4], [32])
    centres, sizes = cell_geometry(case)
    bottom_x, bottom_z = GROOVE_BOTTOM
    alpha = fraction_below(centres, sizes,
                           lambda x, y: np.minimum(bottom_z + np.abs(x - bottom_x), 4e-3))
    case.write_field("alpha.metal", time="0", values=alpha)
    entry = laser_entry("monteCarlo")
    entry = entry.replace(f"position        ({CENTRE[0]} {CENTRE[1]} {CENTRE[2]})",
                          f"position        ({GROOVE_BEAM_X} {CENTRE[1]} {CENTRE[2]})")
    write_fv_options(case, entry.replace(f"beamRadius      {BEAM_RADIUS}",
                                         f"beamRadius      {GROOVE_BEAM_RADIUS}"))
    if n_procs > 1:
        case.run("decomposePar")
        case.run("ldnaFoam", n_procs=n_procs)
    else:
        case.run("ldnaFoam")

    balance = laser_balances(case)
    absorbed = absorbed_total(balance)[-1]
    expected = (1 - (1 - ABSORPTIVITY) ** 2) * POWER
    print(f"V-groove on {n_procs} rank(s): absorbed {absorbed:.3f} W, (1 - (1 - a)^2) P = "
          f"{expected:.3f} W; reflected {balance['reflected'][-1]:.3f} W")
    assert abs(absorbed - expected) / expected < V_GROOVE_TOLERANCE
    assert_balance_closes(balance)


#: Shadowing: a metal sphere of radius 0.6 mm centred 1 mm above the slab
#: surface, on the beam axis (radius 1 mm), in 0.1 mm cells over a 4 x 4 mm
#: box around the target (the beam's 2 radii)
SPHERE_RADIUS = 0.6e-3
SPHERE_HEIGHT = 1.0e-3


def sphere_shadow(mu: float | None) -> float:
    """Share of the Gaussian beam (eq. 48) the sphere takes out: all rays that
    meet it, or with Beer-Lambert attenuation mu [1/m] 1 - exp(-mu chord)."""
    rho = np.linspace(0.0, SPHERE_RADIUS, 20001)
    weight = 6 * rho / BEAM_RADIUS**2 * np.exp(-3 * rho**2 / BEAM_RADIUS**2)
    blocked = np.ones_like(rho) if mu is None else (
        1 - np.exp(-mu * 2 * np.sqrt(np.clip(SPHERE_RADIUS**2 - rho**2, 0, None))))
    return float(np.trapezoid(weight * blocked, rho))


@pytest.mark.parametrize("model", MODELS)
def test_metal_in_the_beam_shades_the_surface(laser_slab_case: Case, model: str) -> None:
    """A sphere in the beam takes its share; the slab beneath gets the rest.

    Monte-Carlo rays reflected by the sphere may land on the slab; without
    tracing reflections (maxScatteringEvents 0) the slab's power is
    a P (1 - share) for every model, the share being the beam's power
    through the sphere's disk (Beer-Lambert: what the chord attenuates).
    """
    case = laser_slab_case
    box_mesh(case, (2, 6, 40), (2, 6, 40), [0, 2, 4], [10, 20])
    centres, sizes = cell_geometry(case)
    alpha = fraction_below(centres, sizes, lambda x, y: np.full_like(x, CENTRE[2]))
    # The sphere by volume fraction: 4^3 samples per cell
    centre = np.array([CENTRE[0], CENTRE[1], CENTRE[2] + SPHERE_HEIGHT])
    h = sizes[:, 0].max()
    offsets = ((np.arange(4) + 0.5) / 4 - 0.5) * h
    near = np.linalg.norm(centres - centre, axis=1) < SPHERE_RADIUS + h
    inside = np.zeros(near.sum())
    for ox in offsets:
        for oy in offsets:
            for oz in offsets:
                inside += np.linalg.norm(centres[near] + (ox, oy, oz) - centre,
                                         axis=1) < SPHERE_RADIUS
    alpha[near] = np.maximum(alpha[near], inside / 64)
    case.write_field("alpha.metal", time="0", values=alpha)
    coeffs = "maxScatteringEvents 0;" if model == "monteCarlo" else ""
    write_fv_options(case, laser_entry(model, coeffs=coeffs))
    case.run("ldnaFoam")

    last = case.times[-1]
    absorbed = case.field("laserPowerDensity", last) * sizes.prod(axis=1)
    slab = absorbed[centres[:, 2] < CENTRE[2]].sum()
    share = sphere_shadow(MU if model == "beerLambert" else None)
    expected = ABSORPTIVITY * POWER * (1 - share)
    print(f"{model}: slab {slab:.3f} W, a P (1 - share {share:.4f}) = {expected:.3f} W; "
          f"sphere {absorbed[centres[:, 2] > CENTRE[2]].sum():.3f} W")
    assert abs(slab - expected) < SHADOW_TOLERANCE * ABSORPTIVITY * POWER
    assert_balance_closes(laser_balances(case))


#: Region test: the pool's edge POOL_EDGE beyond the beam's axis, and the
#: substrate surface DEPOSIT_DEPTH below the slab's top (cell faces both)
POOL_EDGE = 0.5e-3
DEPOSIT_DEPTH = 0.5e-3
POOL_TEMPERATURE = 1800.0
REGION_TOLERANCE = 1e-3


def test_absorbed_power_by_region(laser_slab_case: Case) -> None:
    """Beer-Lambert on a slab whose metal is molten for x < x_target + d, with
    the substrate surface 0.5 mm below its top: the pool takes the beam's
    share on that side, Phi(d sqrt(6) / R) for the profile exp(-3 r^2 / R^2);
    of the rest, the solid deposit above the surface takes
    (1 - exp(-mu 0.5 mm)) / (1 - exp(-mu 2 mm)) and the substrate below it
    the remainder (the rays cross the 2 mm slab)."""
    case = laser_slab_case
    centres = cell_centres(case)
    molten = (centres[:, 0] < CENTRE[0] + POOL_EDGE) & (centres[:, 2] < CENTRE[2])
    case.write_field("T", np.where(molten, POOL_TEMPERATURE, 300.0))
    surface = CENTRE[2] - DEPOSIT_DEPTH
    write_fv_options(case, laser_entry("beerLambert", extra=f"surfaceHeight {surface};"))
    case.run("ldnaFoam")

    first = laser_balances(case)[0]
    metal = first["metal"]
    pool_share = 0.5 * (1 + math.erf(POOL_EDGE * math.sqrt(6) / BEAM_RADIUS / math.sqrt(2)))
    top_share = (1 - math.exp(-MU * DEPOSIT_DEPTH)) / (1 - math.exp(-MU * CENTRE[2]))
    expected = {"pool": pool_share * metal,
                "deposit": (1 - pool_share) * top_share * metal,
                "substrate": (1 - pool_share) * (1 - top_share) * metal}
    for region, value in expected.items():
        print(f"{region}: {first[region]:.4f} W, expected {value:.4f} W")
        assert first[region] == pytest.approx(value, rel=REGION_TOLERANCE), region
    assert first["pool"] + first["deposit"] + first["substrate"] == pytest.approx(metal,
                                                                                rel=1e-9)


def test_radiation_loss_of_a_hot_surface(laser_slab_case: Case) -> None:
    """eps sigma (T^4 - T0^4) A from a flat surface at uniform temperature."""
    case = laser_slab_case
    temperature, ambient, emissivity = 2000.0, 300.0, 0.4
    case.set("0/T", "internalField", f"uniform {temperature}")
    write_fv_options(case, f"""
surfaceLosses
{{
    type                interfaceHeatLoss;
    radiation           yes;
    emissivity          {emissivity};
    convection          no;
    ambientTemperature  {ambient};
}}
""")
    case.run("ldnaFoam")

    radiated = float(case.table("surfaceLosses", "losses")["radiated"][0])
    stefan_boltzmann = 5.670374419e-8
    expected = emissivity * stefan_boltzmann * (temperature**4 - ambient**4) * SURFACE_AREA
    print(f"radiated {radiated:.5f} W, eps sigma (T^4 - T0^4) A = {expected:.5f} W")
    assert abs(radiated - expected) / expected < RADIATION_TOLERANCE


# (description, fvOptions entries with one bad value, expected texts)
BAD_INPUTS = [
    ("unknown absorption model", laser_entry("rayTracing"), ["absorptionModel", "rayTracing"]),
    ("zero beam radius", laser_entry("beerLambert").replace(f"beamRadius      {BEAM_RADIUS}",
                                                            "beamRadius      0"),
     ["beamRadius", "(0, 0.1]"]),
    ("misspelt entry", laser_entry("beerLambert", extra="oscillationAmplitude0 1e-3;"),
     ["oscillationAmplitude0", "did you mean", "oscillationAmplitude"]),
    ("power of 1e300 W", laser_entry("gaussianSurface").replace(
        f"power           constant {POWER}", "power           constant 1e300"),
     ["power", "1e+300", "[0, 1000000]"]),
    ("absorptivity above 1", laser_entry("gaussianSurface").replace(
        f"absorptivity    constant {ABSORPTIVITY}", "absorptivity    constant 1.5"),
     ["absorptivity", "[0, 1]"]),
    ("transmittance of 1", laser_entry("beerLambert", coeffs="transmittance 1;"),
     ["transmittance", "(0, 1)"]),
    ("laser angle of 90 degrees", laser_entry("monteCarlo", extra="angle 90;"),
     ["angle", "(-90, 90)"]),
    ("negative emissivity", """
surfaceLosses
{
    type interfaceHeatLoss; emissivity -0.1; heatTransferCoeff 10; ambientTemperature 300;
}
""", ["emissivity", "[0, 1]"]),
]


@pytest.mark.parametrize("description,entries,expected", BAD_INPUTS,
                         ids=[b[0].replace(" ", "_") for b in BAD_INPUTS])
def test_bad_laser_input(laser_slab_case: Case, description: str, entries: str,
                         expected: list[str]) -> None:
    case = laser_slab_case
    write_fv_options(case, entries)
    result = case.run("ldnaFoam", check=False)
    error = result.output
    assert result.returncode != 0, description
    assert "FOAM FATAL IO ERROR" in error, description
    for text in expected:
        assert text in error, f"{description}: '{text}' missing"
