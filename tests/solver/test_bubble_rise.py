"""Gas enclosed in the melt rises through it (bubbleRise).

A vertical column of 0.25 mm cells (tests/cases/gasColumn) holds liquid
316L up to 6 mm with 5 % gas in the cell at 1-1.25 mm, argon above; the
column is one cell across, so the mixture cannot move and only the drift
moves gas.  Gas dispersed in a melt rises at the rise velocity u_r: in the
drift's flux u_r [metal above] [gas] [metal beneath] the two metal factors
lie between 1 - g0 and 1 for a dilute gas of at most g0, so the gas's
centroid rises at between (1 - g0)^2 u_r and u_r, whatever the numerical
spreading.  Once it has crossed the melt, no gas is left in it and the
metal's volume is what it was.
"""
from __future__ import annotations

import shutil

import numpy as np
import pytest

from ldna.case import Case
from solver_cases import assert_named_error, tighten_solvers

#: The case's rise velocity [m/s], its gas share, cell size [m] and melt depth [m]
RISE_VELOCITY = 0.05
GAS_SHARE = 0.05
CELL = 0.25e-3
MELT_DEPTH = 6e-3
#: Cell centres of the column [m]
CENTRES = (np.arange(32) + 0.5) * CELL
#: The cells well inside the melt (below its surface by two cells)
IN_MELT = CENTRES < MELT_DEPTH - 2 * CELL
#: Solidus of 316L in the template's data [K]
SOLIDUS = 1675.0
#: Allowed relative change of the metal's mass: the flux form moves metal
#: from cell to cell only; the solver itself changes it by 3e-8 in this
#: column without the drift (its gas compressed under the melt's head),
#: where a drift that lost the metal it moves would change it by 2e-3
MASS_TOLERANCE = 1e-6
#: Largest difference of a cell's metal fraction between the serial run and
#: two ranks, every linear solver converged to 1e-13 (measured 1e-11; with
#: the template's solver tolerances the runs differ by 8e-7)
RANK_TOLERANCE = 1e-10
#: Largest difference of the gas cells under a layer of metal with and
#: without the drift after 10 ms (measured 6e-9, through the column's
#: motion); the drift acting there would fill them at u_r, by 1e-2
UNDERSIDE_TOLERANCE = 1e-7


def gas_in_melt(case: Case, time: str) -> np.ndarray:
    return 1 - case.field("alpha.metal", time)[IN_MELT]


def centroid(gas: np.ndarray) -> float:
    return float((gas * CENTRES[IN_MELT]).sum() / gas.sum())


def test_enclosed_gas_rises_at_the_rise_velocity(gas_column_case: Case) -> None:
    case = gas_column_case
    case.run()
    times = ["0", "0.01", "0.02", "0.03", "0.04"]
    heights = [centroid(gas_in_melt(case, t)) for t in times]
    speed = np.polyfit([float(t) for t in times], heights, 1)[0]
    print(f"centroid {1e3 * np.array(heights)} mm, rise {speed:.5f} m/s")
    assert (1 - GAS_SHARE) ** 2 * RISE_VELOCITY <= speed <= RISE_VELOCITY
    # The table's first step: the melt above the gas cell sinks into it at
    # u_r times its gas share over the column's cross-section
    first_step = case.function_object("gasRise", "drift")[0, 1]
    assert first_step == pytest.approx(RISE_VELOCITY * GAS_SHARE * CELL**2, rel=1e-9)
    low, high = case.alpha_bounds()
    assert low >= -1e-12 and high <= 1 + 1e-12


def test_the_gas_leaves_the_melt_and_the_metal_stays(gas_column_case: Case) -> None:
    case = gas_column_case
    # Twice the time the gas takes to rise through the whole melt
    case.set("system/controlDict", "endTime", f"{2 * MELT_DEPTH / RISE_VELOCITY:g}")
    case.run()
    gas = gas_in_melt(case, case.times[-1].name)
    print(f"largest gas share left in the melt {gas.max():.3g}")
    assert gas.max() < 1e-3
    metal = case.balances()["metal_mass"]
    assert abs(metal[-1] - metal[0]) <= MASS_TOLERANCE * metal[0]


def test_gas_stays_in_frozen_metal(gas_column_case: Case) -> None:
    """Below the solidus nothing is molten: the gas is shut in."""
    case = gas_column_case
    case.set("0/T", "internalField", f"uniform {SOLIDUS - 175:g}")
    case.run()
    rise = centroid(gas_in_melt(case, "0.04")) - centroid(gas_in_melt(case, "0"))
    print(f"centroid moved {1e3 * rise:.3g} mm")
    assert abs(rise) < 0.01 * RISE_VELOCITY * 0.04


def test_gas_under_metal_with_nothing_beneath_stays(gas_column_case: Case) -> None:
    """A layer of metal over gas (a droplet's underside) is no melt holding
    gas: the gas under it stays as in the run without the drift.  Inside
    the layer the drift lifts the gas traces of its smeared underside
    (changes of 1e-6), which moves the compressible column a little."""
    case = gas_column_case
    layer = np.where((CENTRES > 4e-3) & (CENTRES < MELT_DEPTH), 1.0, 0.0)
    case.write_field("alpha.metal", layer)
    case.set("system/controlDict", "endTime", "0.01")
    case.run()
    with_drift = case.field("alpha.metal", "0.01")
    (case / "constant" / "fvOptions").write_text("FoamFile { version 2.0; format ascii;"
                                                 " class dictionary; object fvOptions; }\n")
    case.run()
    under = CENTRES < 4e-3
    without_drift = case.field("alpha.metal", "0.01")
    difference = np.abs(with_drift - without_drift)[under].max()
    print(f"largest difference from the run without the drift under the layer {difference:.3g},"
          f" in it {np.abs(with_drift - without_drift).max():.3g}")
    assert difference < UNDERSIDE_TOLERANCE


@pytest.mark.parametrize("n_procs", [2])
def test_the_drift_crosses_processor_boundaries(gas_column_case: Case, n_procs: int) -> None:
    """Decomposed one rank above the other, the gas rises through the
    processor boundary as it does in the serial run."""
    case = gas_column_case
    tighten_solvers(case)
    case.set("system/controlDict", "endTime", "0.08")
    case.run()
    serial = case.field("alpha.metal", case.times[-1].name)
    serial_rate = case.function_object("gasRise", "drift")[:, 1]
    shutil.rmtree(case / "postProcessing")
    for time in case.times[1:]:
        shutil.rmtree(time)
    case.decompose()
    case.run(n_procs=n_procs)
    case.reconstruct()
    parallel = case.field("alpha.metal", case.times[-1].name)
    print(f"largest difference {np.abs(parallel - serial).max():.3g}")
    # The table counts the drift through the processor face once
    parallel_rate = case.function_object("gasRise", "drift")[:, 1]
    steps = min(len(serial_rate), len(parallel_rate))
    assert parallel_rate[:steps] == pytest.approx(serial_rate[:steps], rel=1e-6)
    assert np.abs(parallel - serial).max() < RANK_TOLERANCE


@pytest.mark.parametrize("entry,value,expected", [
    ("constant/fvOptions:gasRise/riseVelocity", "0", ["riseVelocity", "is 0", "(0, 10]"]),
    ("constant/fvOptions:gasRise/riseVelocity", "1e300", ["riseVelocity", "(0, 10]"]),
    ("constant/fvOptions:gasRise/riseVelocity", None, ["riseVelocity"]),
    ("constant/fvOptions:gasRise/riseVelocty", "0.05", ["riseVelocty", "riseVelocity"]),
    ("constant/g:value", "(0 0 0)", ["gasRise", "'value'", "constant/g", "(0, inf)"]),
], ids=["zero", "huge", "missing", "misspelt", "no gravity"])
def test_bad_input_is_a_named_error(gas_column_case: Case, entry: str, value: str | None,
                                    expected: list[str]) -> None:
    file, key = entry.split(":")
    edit = "-remove" if value is None else f"-set '{value}'"
    gas_column_case.run(f"foamDictionary -entry '{key}' {edit} {file}", log_name="foamDictionary")
    assert_named_error(gas_column_case, expected)
