"""Laser heating and free-surface heat losses on a flat metal slab.

A closed 8 x 8 x 4 mm box of argon over a 2 mm slab of 316L (0.25 mm
cells, surface on cell faces, no gravity) is lit by a vertical beam of
radius 1 mm for one time step.  The laser logs its power balance every step
and writes the absorbed power density; the tests check them against the
beam power, the Beer-Lambert law and Monte-Carlo statistics, and the
heat-loss model against the Stefan-Boltzmann law.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from ldna.foamcase import read_internal_field, run, run_parallel, time_directories
from ldna.foamdict import set_entry

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

#: Allowed errors (issue 4)
ABSORBED_TOLERANCE = 0.01
MONTE_CARLO_BALANCE_TOLERANCE = 0.005
DECAY_TOLERANCE = 0.05
RADIATION_TOLERANCE = 0.01
#: Fresnel test: a narrower beam (0.5 mm), so that even at 75 degrees its
#: elongated footprint stays on the 8 mm slab; every ray meets the surface at
#: the laser angle, so a(theta) P holds up to the share of rays that cross
#: the 2 mm slab (exp(-8) at normal incidence)
FRESNEL_BEAM_RADIUS = 0.5e-3
FRESNEL_TOLERANCE = 0.002

BALANCE = re.compile(
    r"^laserHeatSource \S+: t = (\S+) s, target = \((\S+) (\S+) (\S+)\), direction = \(.*\), "
    r"emitted = (\S+) W, absorbed by metal = (\S+) W, absorbed by gas = (\S+) W, "
    r"escaped = (\S+) W, imbalance = (\S+) W$", re.M)


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


def write_fv_options(case: Path, entries: str) -> None:
    """Replace the case's fvOptions by ``entries``."""
    header = (case / "constant" / "fvOptions").read_text().split("// The test writes")[0]
    (case / "constant" / "fvOptions").write_text(header + entries + "\n")


def laser_balances(log: Path) -> np.ndarray:
    """The laser's power balance per time step from a solver log."""
    rows = [tuple(float(v) for v in m.groups()) for m in BALANCE.finditer(log.read_text())]
    assert rows, f"no laser balance in {log}"
    return np.array(rows, dtype=[(n, float) for n in (
        "time", "x", "y", "z", "emitted", "metal", "gas", "escaped", "imbalance")])


def absorbed_per_cell(case: Path) -> np.ndarray:
    """Absorbed power per cell [W] of the last written time (power density x volume)."""
    last = time_directories(case)[-1]
    return read_internal_field(last / "laserPowerDensity") * CELL**3


def cell_centres(case: Path) -> np.ndarray:
    """Cell centres of the slab mesh (i fastest, then j, then k: blockMesh order)."""
    n = (32, 32, 16)
    k, j, i = np.meshgrid(*(np.arange(m) for m in n[::-1]), indexing="ij")
    return np.stack([(i.ravel() + 0.5) * CELL, (j.ravel() + 0.5) * CELL,
                     (k.ravel() + 0.5) * CELL], axis=1)


@pytest.mark.parametrize("model", ["gaussianSurface", "beerLambert"])
def test_absorbed_power_is_a_times_P(laser_slab_case: Path, model: str) -> None:
    case = laser_slab_case
    write_fv_options(case, laser_entry(model))
    run(case, "ldnaFoam")

    balance = laser_balances(case / "log.ldnaFoam")[-1]
    absorbed = absorbed_per_cell(case).sum()
    expected = ABSORPTIVITY * POWER
    print(f"{model}: absorbed {absorbed:.4f} W (log: metal {balance['metal']:.4f}, gas "
          f"{balance['gas']:.4f}), a P = {expected:.4f} W, escaped {balance['escaped']:.4f} W")
    assert abs(absorbed - expected) / expected < ABSORBED_TOLERANCE
    # The log books the same power, and what is not absorbed escapes
    assert balance["metal"] + balance["gas"] == pytest.approx(absorbed, rel=1e-6)
    assert abs(balance["emitted"] - absorbed - balance["escaped"]) < 1e-6 * POWER


def test_beer_lambert_decays_exponentially(laser_slab_case: Path) -> None:
    case = laser_slab_case
    write_fv_options(case, laser_entry("beerLambert"))
    run(case, "ldnaFoam")

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


def test_monte_carlo_balance_and_noise(laser_slab_case: Path) -> None:
    """Absorbed + escaped = P; the scatter of the absorbed total falls like 1/sqrt(N).

    Each step draws new rays (the seed advances with the time index), so one
    run of eight steps gives eight independent samples of the absorbed power.
    """
    case = laser_slab_case
    steps = 8
    set_entry(case / "system" / "controlDict", "endTime", f"{steps * 1e-5:g}")
    spreads = {}
    for n_rays in (250, 1000, 4000):
        write_fv_options(case, laser_entry("monteCarlo", coeffs=f"nRays {n_rays}; seed 7;"))
        run(case, "ldnaFoam", log_name=f"ldnaFoam.{n_rays}")
        balances = laser_balances(case / f"log.ldnaFoam.{n_rays}")
        assert len(balances) == steps
        absorbed = balances["metal"] + balances["gas"]
        worst = np.max(np.abs(absorbed + balances["escaped"] - POWER)) / POWER
        assert worst < MONTE_CARLO_BALANCE_TOLERANCE
        spreads[n_rays] = absorbed.std(ddof=1)
        print(f"N = {n_rays}: absorbed {absorbed.mean():.2f} +- {spreads[n_rays]:.2f} W, "
              f"worst balance error {100 * worst:.2e} %")
    # The written field (last step) holds what the log says was absorbed
    field_total = absorbed_per_cell(case).sum()
    assert field_total == pytest.approx(absorbed[-1], rel=1e-6)

    ns = np.array(sorted(spreads), dtype=float)
    slope = np.polyfit(np.log(ns), np.log([spreads[n] for n in sorted(spreads)]), 1)[0]
    print(f"scatter of the absorbed power ~ N^{slope:.3f} (expected -0.5)")
    assert -0.8 < slope < -0.2


def test_serial_and_parallel_agree(laser_slab_case: Path) -> None:
    """A tilted beam crosses the processor boundary at x = 4 mm.

    Beer-Lambert rays are deterministic: the decomposed run must absorb the
    same power in every cell.  Monte-Carlo rays scatter with per-processor
    random numbers: the totals agree within the Monte-Carlo noise, measured
    as the spread between steps.
    """
    case = laser_slab_case
    tilt = "angle 30;"
    run(case, "decomposePar")

    write_fv_options(case, laser_entry("beerLambert", extra=tilt))
    run(case, "ldnaFoam", log_name="ldnaFoam.serial")
    serial = absorbed_per_cell(case)
    run_parallel(case, "ldnaFoam", 2, log_name="ldnaFoam.parallel")
    run(case, "reconstructPar -latestTime", log_name="reconstructPar")
    parallel = absorbed_per_cell(case)
    difference = np.abs(serial - parallel).max() / serial.max()
    print(f"Beer-Lambert: total {serial.sum():.6f} W serial, {parallel.sum():.6f} W parallel, "
          f"largest cell difference {difference:.2e} of the peak")
    assert parallel.sum() == pytest.approx(serial.sum(), rel=1e-9)
    assert difference < 1e-9

    # Monte-Carlo: a few steps each, so the comparison uses the measured
    # step-to-step spread of the absorbed total
    steps = 4
    set_entry(case / "system" / "controlDict", "endTime", f"{steps * 1e-5:g}")
    write_fv_options(case, laser_entry("monteCarlo", extra=tilt, coeffs="nRays 10000;"))
    run(case, "ldnaFoam", log_name="ldnaFoam.mc.serial")
    run_parallel(case, "ldnaFoam", 2, log_name="ldnaFoam.mc.parallel")
    samples = {}
    for label in ("serial", "parallel"):
        balances = laser_balances(case / f"log.ldnaFoam.mc.{label}")
        assert len(balances) == steps
        samples[label] = balances["metal"] + balances["gas"]
        worst = np.abs(balances["emitted"] - samples[label] - balances["escaped"]).max()
        assert worst < 1e-6 * POWER
    difference = samples["parallel"].mean() - samples["serial"].mean()
    standard_error = math.sqrt(sum(x.var(ddof=1) for x in samples.values()) / steps)
    print(f"Monte-Carlo: serial {samples['serial'].mean():.2f} W, parallel "
          f"{samples['parallel'].mean():.2f} W, standard error of the difference "
          f"{standard_error:.2f} W")
    assert abs(difference) < 4 * standard_error


def fresnel_absorptivity(theta: float, n: float, k: float) -> float:
    """1 - R of unpolarised light from vacuum on a medium n + i k (Fresnel, Snell's law)."""
    index = complex(n, k)
    cos_i = math.cos(theta)
    cos_t = np.sqrt(1 - (math.sin(theta) / index) ** 2)
    r_s = (cos_i - index * cos_t) / (cos_i + index * cos_t)
    r_p = (index * cos_i - cos_t) / (index * cos_i + cos_t)
    return 1 - 0.5 * (abs(r_s) ** 2 + abs(r_p) ** 2)


@pytest.mark.parametrize("angle", [0.0, 45.0, 75.0])
def test_fresnel_absorptivity_follows_the_incidence_angle(laser_slab_case: Path,
                                                          angle: float) -> None:
    """Iron at 1.03 um (n 3.2, k 4.2) lit at the laser angle, no scattering.

    Every ray enters the flat slab at the laser angle and gives up the share
    a(theta) at its first interaction (maxScatteringEvents 0 discards the
    rest), so the absorbed power is a(theta) P, whatever the random depths.
    """
    case = laser_slab_case
    n, k = 3.2, 4.2
    entry = laser_entry("monteCarlo", extra=f"angle {angle};",
                        coeffs=f"nRays 2000; maxScatteringEvents 0; fresnel {{ n {n}; k {k}; }}")
    write_fv_options(case, entry.replace(f"beamRadius      {BEAM_RADIUS}",
                                         f"beamRadius      {FRESNEL_BEAM_RADIUS}"))
    run(case, "ldnaFoam")

    balance = laser_balances(case / "log.ldnaFoam")[-1]
    absorbed = balance["metal"] + balance["gas"]
    expected = fresnel_absorptivity(math.radians(angle), n, k) * POWER
    print(f"angle {angle}: absorbed {absorbed:.4f} W, a(theta) P = {expected:.4f} W")
    assert abs(absorbed - expected) / expected < FRESNEL_TOLERANCE
    assert abs(balance["emitted"] - absorbed - balance["escaped"]) < 1e-6 * POWER


def test_beam_follows_the_oscillation(laser_slab_case: Path) -> None:
    """Target and absorbed power move as offset + A sin(2 pi f t) across the seam."""
    case = laser_slab_case
    amplitude, frequency = 2e-3, 10.0
    set_entry(case / "system" / "controlDict", "deltaT", "0.005")
    set_entry(case / "system" / "controlDict", "maxDeltaT", "0.005")
    set_entry(case / "system" / "controlDict", "endTime", "0.02")
    write_fv_options(case, laser_entry(
        "gaussianSurface",
        extra=f"oscillationAmplitude {amplitude}; oscillationFrequency {frequency}; "
              "offset constant (0.0005 0 0);"))
    run(case, "ldnaFoam")

    balances = laser_balances(case / "log.ldnaFoam")
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


def test_radiation_loss_of_a_hot_surface(laser_slab_case: Path) -> None:
    """eps sigma (T^4 - T0^4) A from a flat surface at uniform temperature."""
    case = laser_slab_case
    temperature, ambient, emissivity = 2000.0, 300.0, 0.4
    set_entry(case / "0" / "T", "internalField", f"uniform {temperature}")
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
    run(case, "ldnaFoam")

    radiated = float(re.findall(r"radiated = (\S+) W", (case / "log.ldnaFoam").read_text())[0])
    stefan_boltzmann = 5.670374419e-8
    expected = emissivity * stefan_boltzmann * (temperature**4 - ambient**4) * SURFACE_AREA
    print(f"radiated {radiated:.5f} W, eps sigma (T^4 - T0^4) A = {expected:.5f} W")
    assert abs(radiated - expected) / expected < RADIATION_TOLERANCE


# (description, fvOptions entries with one bad value, expected texts)
BAD_INPUTS = [
    ("unknown absorption model", laser_entry("rayTracing"), ["absorptionModel", "rayTracing"]),
    ("zero beam radius", laser_entry("beerLambert").replace(f"beamRadius      {BEAM_RADIUS}",
                                                            "beamRadius      0"),
     ["beamRadius", "> 0"]),
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
def test_bad_laser_input(laser_slab_case: Path, description: str, entries: str,
                         expected: list[str]) -> None:
    case = laser_slab_case
    write_fv_options(case, entries)
    result = run(case, "ldnaFoam", check=False)
    error = result.output
    assert result.returncode != 0, description
    assert "FOAM FATAL IO ERROR" in error, description
    for text in expected:
        assert text in error, f"{description}: '{text}' missing"
