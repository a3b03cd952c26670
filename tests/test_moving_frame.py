"""The LDNA template's moving frame without heat input.

The substrate enters at the welding speed; with no heat it stays solid and
the enthalpy-porosity sink must carry it through the domain as a rigid body
at (v_w, 0, 0), and metal must leave through the outlet at the rate it
enters.  The template's own files run with every effect but the porosity removed.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ldna.foamcase import (alpha_bounds, dictionary_scalar, read_balances,
                           read_function_object, read_internal_field, run, time_directories)
from ldna.foamdict import keep_blocks, set_entry

#: Allowed relative velocity error of the solid substrate (issue: 1 %)
VELOCITY_TOLERANCE = 0.01
#: Allowed relative imbalance of metal inflow and outflow (issue: metal
#: leaves at the rate it enters)
FLOW_BALANCE_TOLERANCE = 0.01
#: Largest gas speed over the welding speed in the cold scene
GAS_SPEED_LIMIT = 1.5


def keep_only_porosity(case: Path) -> None:
    """List only the enthalpy-porosity effect in constant/fvOptions."""
    keep_blocks(case / "constant" / "fvOptions", ["enthalpyPorosity"])


def test_cold_substrate_moves_at_welding_speed(ldna_case: Path) -> None:
    case = ldna_case
    keep_only_porosity(case)
    set_entry(case / "system" / "controlDict", "endTime", "0.4")
    set_entry(case / "system" / "controlDict", "writeInterval", "0.2")
    run(case, "blockMesh")
    run(case, "setFields")
    run(case, "ldnaFoam")

    welding_speed = dictionary_scalar(case, "system/caseParameters", "weldingSpeed")
    last = time_directories(case)[-1]
    alpha = read_internal_field(last / "alpha.metal")
    velocity = read_internal_field(last / "U")
    substrate = alpha > 0.99
    assert substrate.sum() > 0.3 * alpha.size
    error = np.abs(velocity[substrate] - np.array([welding_speed, 0, 0])).max() / welding_speed
    print(f"largest substrate velocity error: {100 * error:.4f} % of v_w = {welding_speed} m/s")
    assert error < VELOCITY_TOLERANCE

    # Nothing but the substrate's drag moves the gas: no spurious currents
    # from the open boundaries (a boundary fixing p instead of p_rgh along
    # the vertical faces drives 0.26 m/s here)
    gas_speed = np.linalg.norm(velocity[alpha < 0.01], axis=1).max()
    print(f"largest gas speed {gas_speed:.3e} m/s")
    assert gas_speed < GAS_SPEED_LIMIT * welding_speed

    inflow = read_function_object(case, "metalFlowIn", "surfaceFieldValue.dat")
    outflow = read_function_object(case, "metalFlowOut", "surfaceFieldValue.dat")
    to_atmosphere = read_function_object(case, "metalFlowAtmosphere", "surfaceFieldValue.dat")
    q_in, q_out = -inflow[-1, 1], outflow[-1, 1]
    imbalance = abs(q_out - q_in) / q_in
    print(f"metal in {q_in:.6e} m3/s, out {q_out:.6e} m3/s, to atmosphere "
          f"{to_atmosphere[-1, 1]:.3e} m3/s: imbalance {100 * imbalance:.4f} %")
    assert q_in > 0
    assert imbalance < FLOW_BALANCE_TOLERANCE
    assert abs(to_atmosphere[-1, 1]) < FLOW_BALANCE_TOLERANCE * q_in

    # The inflow is the substrate cross-section at the welding speed
    width = dictionary_scalar(case, "system/caseParameters", "width") * 1e-3
    depth = dictionary_scalar(case, "system/caseParameters", "substrateDepth") * 1e-3
    assert abs(q_in - welding_speed * width * depth) < 1e-3 * q_in

    # The metal in the domain stays the same and bounded
    balances = read_balances(case / "log.ldnaFoam")
    drift = abs(balances["metal_mass"][-1] - balances["metal_mass"][0]) / balances["metal_mass"][0]
    assert drift < 1e-4
    low, high = alpha_bounds(case / "log.ldnaFoam")
    assert low > -1e-6 and high < 1 + 1e-6
