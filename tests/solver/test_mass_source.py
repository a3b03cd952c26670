"""Metal mass sources enter continuity, phase fraction and pressure together.

OpenFOAM's own scalarSemiImplicitSource adds metal (kg/s) to alpha.metal in
a band at the bottom of liquid metal in the closed box under argon.  The
added volume must lift the melt and compress the gas: the metal mass grows
at exactly the injected rate, the gas mass stays, the gas pressure rises by
its equation of state, the metal fraction stays in [0, 1], and the
temperature does not change (metal arrives at the local temperature).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ldna.case import Case

#: Injection rate [kg/s]: 10 % of the box's metal in 0.5 s
INJECTION_RATE = 2.7e-5
#: Allowed relative error of the metal mass gain
MASS_TOLERANCE = 0.01

INJECTION = f"""FoamFile {{ version 2.0; format ascii; class dictionary; object fvOptions; }}

metalInjection
{{
    type                scalarSemiImplicitSource;
    selectionMode       cellZone;
    cellZone            heater;
    volumeMode          absolute;
    injectionRateSuSp
    {{
        alpha.metal     ({INJECTION_RATE} 0);
    }}
}}
"""


def test_metal_mass_source_is_conserved(energy_box_case: Case) -> None:
    case = energy_box_case
    (case / "constant" / "fvOptions").write_text(INJECTION)
    # Liquid metal at a uniform temperature above the liquidus
    liquid_temperature = 1800.0
    case.set("0/T", "internalField", f"uniform {liquid_temperature}")
    case.set("system/controlDict", "endTime", "0.5")
    case.set("system/controlDict", "writeInterval", "0.5")

    case.run("ldnaFoam")

    balances = case.balances()
    start, end = balances[0], balances[-1]
    injected = INJECTION_RATE * (end["time"] - start["time"])
    gain = end["metal_mass"] - start["metal_mass"]
    error = abs(gain - injected) / injected
    print(f"metal mass gain {gain:.6e} kg, injected {injected:.6e} kg, error {100 * error:.3f} %")
    assert error < MASS_TOLERANCE

    # Temperature unchanged, metal fraction bounded
    assert abs(balances["T_min"].min() - liquid_temperature) < 1e-6 * liquid_temperature
    assert abs(balances["T_max"].max() - liquid_temperature) < 1e-6 * liquid_temperature
    low, high = case.alpha_bounds()
    assert low > -1e-6 and high < 1 + 1e-6

    # The gas is compressed, not removed: at the end its mass, from the ideal
    # gas law with the computed pressure, equals its initial mass
    case.run("postProcess -func writeCellVolumes -latestTime", log_name="writeCellVolumes")
    last = case.times[-1]
    volume = case.field("V", last)
    gas_constant = case.scalar("constant/thermophysicalProperties", "gas/R")

    def gas_volume(time: Path) -> np.ndarray:
        metal = np.broadcast_to(case.field("alpha.metal", time), volume.shape)
        return (1 - metal) * volume

    initial_pressure = case.scalar("0/p_rgh", "internalField")
    initial_gas_volume = gas_volume(case / "0").sum()
    gas_mass_start = initial_pressure / (gas_constant * liquid_temperature) * initial_gas_volume
    pressure = np.broadcast_to(case.field("p", last), volume.shape)
    gas_mass_end = float(np.sum(gas_volume(last) * pressure / (gas_constant * liquid_temperature)))
    gas_error = abs(gas_mass_end - gas_mass_start) / gas_mass_start
    print(f"gas volume {initial_gas_volume:.4e} -> {gas_volume(last).sum():.4e} m3, "
          f"gas mass error {100 * gas_error:.3f} %")
    assert gas_volume(last).sum() < 0.95 * initial_gas_volume
    assert gas_error < MASS_TOLERANCE
