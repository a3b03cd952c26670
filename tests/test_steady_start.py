"""The estimate of the steady weld that ``ldna steady-start`` writes (unit
tests of its geometry and its heat balance; the run from it is in
docs/validation/steady-start.md)."""
from __future__ import annotations

import json
import math
import subprocess
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from ldna.case import Case
from ldna.steady_start import GRID, Process, TransverseMarch, cap_height, cap_top

#: A metal of constant properties [SI]: no melting, so that h = cp (T - T0)
DENSITY = 7950.0
HEAT_CAPACITY = 600.0
CONDUCTIVITY = 25.0
AMBIENT = 300.0


def constant_metal() -> SimpleNamespace:
    T = np.linspace(200.0, 6000.0, 2000)
    table = {"T": T, "enthalpy": HEAT_CAPACITY * (T - AMBIENT),
             "kappa": np.full_like(T, CONDUCTIVITY)}
    return SimpleNamespace(table=table, reference_density=DENSITY)


def process(**changes: float) -> Process:
    values = dict(speed=0.0075, ambient=AMBIENT, droplet_temperature=2100.0,
                  first_wire=7e-3, second_wire=11e-3, laser_x=9e-3, absorbed_power=432.0,
                  beam_radius=1e-3, amplitude=6.6e-3, bead_area=35e-6, width=28e-3,
                  substrate_depth=7.2e-3, length=20e-3)
    values.update(changes)
    return Process(**values)


@pytest.mark.unit
@pytest.mark.parametrize("area,half_width", [(35e-6, 7.6e-3), (10e-6, 3e-3), (25e-6, 4e-3)])
def test_the_cap_has_the_mass_balance_area(area: float, half_width: float) -> None:
    """The circular cap of the computed height holds the area (integrated here)."""
    y = np.linspace(-half_width, half_width, 200_001)
    top = cap_top(y, area, half_width)
    assert np.trapezoid(top, y) == pytest.approx(area, rel=1e-6)
    assert top.max() == pytest.approx(cap_height(area, half_width), rel=1e-9)
    assert cap_top(np.array([1.01 * half_width]), area, half_width)[0] == 0


@pytest.mark.unit
def test_a_section_beyond_the_half_disc_is_refused() -> None:
    with pytest.raises(ValueError, match="half disc"):
        cap_height(40e-6, 4e-3)


@pytest.mark.unit
def test_the_march_conserves_energy() -> None:
    """Adiabatic section: its enthalpy gain per unit length of weld is the
    deposit's enthalpy at the droplets' temperature plus the laser energy the
    section took as it passed under the beam, P_a / v (the beam well inside
    the march)."""
    p = process()
    march = TransverseMarch(p, constant_metal())
    positions, fields = march.run(p.length)
    cell = GRID * GRID
    # Metal at the end: substrate and the whole cap
    metal = march.substrate | march.in_cap_at(1.0)
    gained = DENSITY * HEAT_CAPACITY * float(((fields[-1] - AMBIENT) * metal).sum()) * cell
    deposit = DENSITY * HEAT_CAPACITY * (p.droplet_temperature - AMBIENT) * march.in_cap_at(1.0).sum() * cell
    laser = p.absorbed_power / p.speed
    print(f"gained {gained:.1f} J/m, deposit {deposit:.1f} + laser {laser:.1f} J/m")
    assert gained == pytest.approx(deposit + laser, rel=5e-3)


@pytest.mark.unit
def test_the_march_cools_the_deposit_into_the_substrate() -> None:
    """Without the laser the deposit's heat only spreads: the section's peak
    falls from the droplets' temperature and the substrate under it warms."""
    p = process(absorbed_power=0.0)
    march = TransverseMarch(p, constant_metal())
    positions, fields = march.run(p.length)
    first_full = int(np.searchsorted(positions, p.second_wire))
    assert fields[first_full].max() == pytest.approx(p.droplet_temperature, rel=1e-3)
    assert fields[-1].max() < 0.9 * p.droplet_temperature
    under = (np.abs(march.y) < 1e-3)[:, None] & (march.z > -0.5e-3)[None, :] & march.substrate
    assert fields[-1][under].min() > AMBIENT + 100
    assert math.isfinite(fields[-1].sum())


def test_the_template_starts_from_the_estimate(ldna_case: Case) -> None:
    """The template, meshed and set, then ``ldna steady-start``: the deposit on
    the surface holds the mass balance's section behind the second wire and
    half of it between the wires (sampled in the cells within 1 %), the
    metal over it moves with the substrate, the solver runs on from it, and
    ``ldna post`` says the section holds the estimate."""
    case = ldna_case
    case.mesh()
    case.run("setFields")
    result = subprocess.run([sys.executable, "-m", "ldna.cli", "steady-start", str(case),
                             "--json"], capture_output=True, text=True, check=True)
    figures = json.loads(result.stdout.strip().splitlines()[-1])

    case.run("postProcess -func writeCellCentres -time 0", log_name="centres")
    case.run("postProcess -func writeCellVolumes -time 0", log_name="volumes")
    x, y, z = case.field("C", "0").T
    volume = case.field("V", "0")
    alpha = case.field("alpha.metal", "0")
    parameters = "system/caseParameters"
    mm = 1e-3
    mid = mm * case.scalar(parameters, "processPosition")
    spacing = mm * case.scalar(parameters, "wireSpacing")
    length = mm * case.scalar(parameters, "length")
    # The mass balance from the process numbers: two wires' feed over the
    # metal's density times the welding speed
    wire_density = case.scalar("constant/fvOptions", "wireDroplets/wireDensity")
    metal_density = case.scalar("constant/thermophysicalProperties", "metal/referenceDensity")
    area = (2 * wire_density * case.scalar(parameters, "wireFeedSpeed") * math.pi
            * case.scalar(parameters, "wireRadius") ** 2
            / (metal_density * case.scalar(parameters, "weldingSpeed")))
    expected = area * (length - (mid + spacing / 2)) + 0.5 * area * spacing
    deposit = float((alpha * volume)[z > 0].sum())
    print(f"deposit {1e9 * deposit:.1f} mm3, expected {1e9 * expected:.1f} mm3; {figures}")
    assert deposit == pytest.approx(expected, rel=0.01)
    assert figures["bead_area_mm2"] == pytest.approx(1e6 * area, rel=1e-9)
    velocity = case.field("U", "0")
    metal = alpha >= 0.5
    assert np.allclose(velocity[metal, 0], case.scalar(parameters, "weldingSpeed"))

    case.set("system/controlDict", "endTime", "0.002")
    case.run("ldnaFoam")
    low, high = case.alpha_bounds()
    assert -1e-6 < low and high < 1 + 1e-6
    estimate = post_process_note(case)
    assert "estimate of the start" in estimate


def post_process_note(case: Case) -> str:
    """What ``ldna post`` tells about the section of the short run."""
    result = subprocess.run([sys.executable, "-m", "ldna.cli", "post", str(case)],
                            capture_output=True, text=True, check=True)
    return " ".join(result.stdout.split())
