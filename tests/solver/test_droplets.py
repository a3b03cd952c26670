"""Droplet transfer from two wires (paper eq. 14-33) in a closed box of argon.

The dropletSource model of the case (constant/fvOptions) adds Gaussian,
time-switched metal mass with the droplet velocity and the enthalpy of metal
at the droplet temperature.  Checked against quantities computed here,
independently of the solver, from the case's own dictionaries:

- mass: after ten droplet periods the metal in the box equals
  rho_w v_w pi R_w^2 t per wire within 1 %;
- duty fraction of the default switch: 0.2048 +- 0.002;
- energy: the enthalpy added equals the mass added times h(T_droplet) within
  1 % (h from the 316L data, latent heat included);
- momentum: without gravity and before anything reaches a wall, the metal's
  momentum equals the integral of mass rate times droplet velocity within 2 %
  (without surface tension: the continuum surface force put a net force of
  up to 75 % of the transverse momentum on droplets less than two cells
  across, measured here with OpenFOAM's curvature before the smoothed
  curvature became the default, and not measured since);
- boundedness: alpha stays within [-1e-6, 1 + 1e-6], no field is NaN.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from solver_cases import prepare_test_case
from ldna.balance import WIRE_COLUMNS, wire_table
from ldna.case import Case
from ldna.material import Metal

MASS_TOLERANCE = 0.01
ENERGY_TOLERANCE = 0.01
MOMENTUM_TOLERANCE = 0.02
#: eq. 18: (pi - 2 asin 0.8)/(2 pi)
DEFAULT_DUTY_FRACTION = (math.pi - 2 * math.asin(0.8)) / (2 * math.pi)
DUTY_TOLERANCE = 0.002
ALPHA_BOUND = 1e-6
#: dropletSource's default droplet temperature [K] (paper: measured 2100 K)
DEFAULT_DROPLET_TEMPERATURE = 2100.0

SOURCE = "constant/fvOptions"


def wire_names(case: Case) -> list[str]:
    """Names of the wire dictionaries of the droplet source."""
    text = case.value(SOURCE, "wireDroplets/wires")
    return re.findall(r"^\s*(\w+)\s*$", text, re.M)


def wire_mass_rate(case: Case, wire: str) -> float:
    """rho_w v_w pi R_w^2 of a wire [kg/s], from the case dictionary."""
    density = case.scalar(SOURCE, "wireDroplets/wireDensity")
    feed = case.scalar(SOURCE, f"wireDroplets/wires/{wire}/feedSpeed")
    radius = case.scalar(SOURCE, f"wireDroplets/wires/{wire}/wireRadius")
    return density * feed * math.pi * radius**2


def wire_values(case: Case, wire: str, key: str) -> np.ndarray:
    """Per-step values the droplet source writes for a wire (addedMass, onTime ...)."""
    return wire_table(case)[wire][:, WIRE_COLUMNS.index(key)]


def finite_fields(case: Case) -> bool:
    """Whether T, U, p_rgh and alpha.metal of the latest time hold only finite numbers."""
    return all(np.all(np.isfinite(case.field(f)))
               for f in ("T", "U", "p_rgh", "alpha.metal"))


@pytest.fixture
def droplet_case(tmp_path: Path) -> Case:
    """The meshed closed box of argon under two wires."""
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    case.run("blockMesh")
    return case


def test_droplet_mass_energy_and_switch(droplet_case: Case) -> None:
    case = droplet_case
    case.run("ldnaFoam")
    balances = case.balances()
    start, end = balances[0], balances[-1]
    elapsed = end["time"] - start["time"]
    wires = wire_names(case)
    assert len(wires) == 2

    # Mass: what the box holds against what the wires feed
    expected = sum(wire_mass_rate(case, w) for w in wires) * elapsed
    gained = end["metal_mass"] - start["metal_mass"]
    mass_error = abs(gained - expected) / expected
    print(f"metal gained {gained:.6e} kg, wires fed {expected:.6e} kg: {100 * mass_error:.3f} %")
    assert mass_error < MASS_TOLERANCE

    # The default switch is on 20.48 % of the time
    for wire in wires:
        duty = wire_values(case, wire, "dutyFraction")[-1]
        print(f"{wire}: duty fraction {duty:.5f}")
        assert abs(duty - DEFAULT_DUTY_FRACTION) < DUTY_TOLERANCE

    # Energy: the closed adiabatic box gains the enthalpy of the droplet metal
    metal = Metal.from_case(case)
    added_enthalpy = 0.0
    for wire in wires:
        try:
            temperature = case.scalar(SOURCE, f"wireDroplets/wires/{wire}/temperature")
        except KeyError:
            temperature = DEFAULT_DROPLET_TEMPERATURE
        added_enthalpy += wire_values(case, wire, "addedMass")[-1] * metal.enthalpy(temperature)
    enthalpy_change = end["enthalpy"] - start["enthalpy"]
    energy_error = abs(enthalpy_change - added_enthalpy) / added_enthalpy
    print(f"enthalpy change {enthalpy_change:.4f} J, droplet enthalpy {added_enthalpy:.4f} J: "
          f"{100 * energy_error:.3f} %")
    assert energy_error < ENERGY_TOLERANCE

    # Bounded, finite
    low, high = case.alpha_bounds()
    print(f"alpha within [{low:.3e}, {high:.6f}]")
    assert low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND
    assert finite_fields(case)


def expected_momentum(case: Case, t_end: float, samples: int = 200_000) -> np.ndarray:
    """Integral over [0, t_end] of mass rate times droplet velocity, summed over wires.

    Independent of the solver: the switch of eq. 18 and the velocity of
    eq. 28-33 evaluated on a fine time grid.
    """
    def get(entry: str, default: float | None = None) -> float:
        try:
            return case.scalar(SOURCE, f"wireDroplets/{entry}")
        except KeyError:
            if default is None:
                raise
            return default

    speed = get("speed")
    beta = math.radians(get("transverseAngle", 0.0))
    alpha_max = get("maxLongitudinalAngle", 10.0)
    nu_p = get("parallelityFrequency")
    t = (np.arange(samples) + 0.5) * t_end / samples
    dt = t_end / samples
    alpha = np.radians(0.5 * alpha_max * (np.sin(2 * np.pi * nu_p * (t - 0.25 / nu_p)) + 1))
    v_xz = speed * math.cos(beta)
    total = np.zeros(3)
    for k, wire in enumerate(wire_names(case)):
        nu = case.scalar(SOURCE, f"wireDroplets/wires/{wire}/detachmentFrequency")
        on = np.sin(2 * np.pi * nu * t + math.asin(0.9)) > 0.8
        pulse_rate = wire_mass_rate(case, wire) / DEFAULT_DUTY_FRACTION
        sign = -1.0 if k % 2 == 0 else 1.0
        velocity = np.stack([sign * v_xz * np.sin(alpha),
                             np.full_like(t, speed * math.sin(beta)),
                             -v_xz * np.cos(alpha)])
        total += (pulse_rate * on * velocity).sum(axis=1) * dt
    return total


def test_droplet_momentum_without_gravity(droplet_case: Case) -> None:
    case = droplet_case
    (case / "constant" / "g").write_text(
        (case / "constant" / "g").read_text().replace("(0 0 -9.81)", "(0 0 0)"))
    case.set("constant/thermophysicalProperties", "sigma", "0")
    # Two droplet periods: the first droplet travels about 8 mm, the source
    # is 13 mm above the floor
    t_end = 0.02
    case.set("system/controlDict", "endTime", str(t_end))
    case.set("system/controlDict", "writeInterval", str(t_end))
    case.run("ldnaFoam")
    case.run("postProcess -func 'writeCellVolumes' -latestTime", log_name="writeCellVolumes")
    case.run("postProcess -func 'writeCellCentres' -latestTime", log_name="writeCellCentres")

    last = case.times[-1]
    metal = Metal.from_case(case)
    volume = case.field("V", last)
    alpha = case.field("alpha.metal", last)
    temperature = case.field("T", last)
    liquid = np.broadcast_to(case.field("liquidFraction", last), alpha.shape)
    velocity = case.field("U", last)
    rho_metal = np.array([metal.mass_density(T, g) for T, g in zip(temperature, liquid)])
    metal_momentum = ((alpha * rho_metal * volume)[:, None] * velocity).sum(axis=0)

    expected = expected_momentum(case, t_end)
    error = np.linalg.norm(metal_momentum - expected) / np.linalg.norm(expected)
    print(f"metal momentum {metal_momentum} kg m/s, injected {expected} kg m/s: "
          f"{100 * error:.2f} %")
    assert error < MOMENTUM_TOLERANCE
    # Nothing reached a wall: the lowest metal is more than a cell above the floor
    centres_z = case.field("Cz", last)
    assert centres_z[alpha > 1e-3].min() > 1e-3
    low, high = case.alpha_bounds()
    assert low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND


BAD_INPUTS = [
    ("negative feed speed", "wireDroplets/wires/wire1/feedSpeed", "-0.1", ["feedSpeed", "(0,"]),
    ("droplet larger than the domain", "wireDroplets/wires/wire1/detachmentFrequency", "0.001",
     ["smaller than the domain"]),
    ("source outside the mesh", "wireDroplets/position", "(0.0035 0 0.05)", ["outside the mesh"]),
    ("both radius and frequency", "wireDroplets/wires/wire1/dropletRadius", "0.7e-3",
     ["exactly one of"]),
    ("switch threshold out of range", "wireDroplets/switchThreshold", "1.5",
     ["switchThreshold", "(-1, 1)"]),
]


@pytest.mark.parametrize("description,entry,value,expected", BAD_INPUTS,
                         ids=[b[0] for b in BAD_INPUTS])
def test_bad_droplet_input(droplet_case: Case, description: str, entry: str, value: str,
                           expected: list[str]) -> None:
    droplet_case.set(SOURCE, entry, value, create=True)
    result = droplet_case.run("ldnaFoam", check=False)
    error = result.output[result.output.find("FOAM FATAL"):]
    print(error[:500])
    assert result.returncode != 0
    assert "FOAM FATAL IO ERROR" in result.output
    for text in expected:
        assert text in error
    assert "sigSegv" not in result.output
