"""The estimate of the steady weld that ``ldna steady-start`` writes (unit
tests of its geometry and its heat balance; the run from it is in
docs/validation/steady-start.md)."""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

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


@pytest.mark.parametrize("area,half_width", [(35e-6, 7.6e-3), (10e-6, 3e-3), (25e-6, 4e-3)])
def test_the_cap_has_the_mass_balance_area(area: float, half_width: float) -> None:
    """The circular cap of the computed height holds the area (integrated here)."""
    y = np.linspace(-half_width, half_width, 200_001)
    top = cap_top(y, area, half_width)
    assert np.trapezoid(top, y) == pytest.approx(area, rel=1e-6)
    assert top.max() == pytest.approx(cap_height(area, half_width), rel=1e-9)
    assert cap_top(np.array([1.01 * half_width]), area, half_width)[0] == 0


def test_a_section_beyond_the_half_disc_is_refused() -> None:
    with pytest.raises(ValueError, match="half disc"):
        cap_height(40e-6, 4e-3)


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
