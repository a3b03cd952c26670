"""The cost of a run read from OpenFOAM's timeInfo table: the per-step and
the per-simulated-second figures leave out the same start-up steps, so that
a benchmark and a cost window of the same run agree."""
from __future__ import annotations

from pathlib import Path

import pytest

from ldna.case import START_UP_STEPS, Case

#: A run of constant time step whose first steps read the fields and set
#: up the solvers (the costs a short window must not count)
DELTA_T = 1e-4
START_UP_COSTS = (5.0, 1.5)
STEP_COST = 0.2
STEPS = 40


def _write_time_info(case: Path, start_time: float) -> None:
    directory = case / "postProcessing" / "timeInfo" / f"{start_time:g}"
    directory.mkdir(parents=True)
    costs = [*START_UP_COSTS, *[STEP_COST] * (STEPS - len(START_UP_COSTS))]
    rows, cpu = ["# Time          \tcpuTime         \tclockTime       "], 0.0
    for step, cost in enumerate(costs, start=1):
        cpu += cost
        rows.append(f"{start_time + step * DELTA_T:.6f}\t{cpu:.8e}\t{round(cpu):.8e}")
    (directory / "timeInfo.dat").write_text("\n".join(rows) + "\n")


def test_both_cost_figures_leave_out_the_start_up(tmp_path: Path) -> None:
    assert START_UP_STEPS == len(START_UP_COSTS)
    _write_time_info(tmp_path, 12.0)
    case = Case(tmp_path)
    assert case.seconds_per_step() == pytest.approx(STEP_COST, rel=1e-9)
    rate, steps = case.latest_run_cpu_rate()
    assert rate == pytest.approx(STEP_COST / DELTA_T, rel=1e-6)
    assert steps == STEPS - START_UP_STEPS


def test_a_run_shorter_than_its_start_up_is_refused(tmp_path: Path) -> None:
    directory = tmp_path / "postProcessing" / "timeInfo" / "0"
    directory.mkdir(parents=True)
    (directory / "timeInfo.dat").write_text(
        "# Time\tcpuTime\tclockTime\n0.0001\t5.0\t5\n0.0002\t6.5\t7\n")
    with pytest.raises(RuntimeError, match="run a few more"):
        Case(tmp_path).seconds_per_step()


def test_a_run_stopped_before_its_first_step_costs_nothing(tmp_path: Path) -> None:
    """A study's leg killed while it started (its ranks stopped to change
    the study's options) leaves an empty timeInfo table where the leg that
    replaced it writes ``timeInfo_<time>.dat``: the case's CPU, clock and
    simulated times are those of the runs that stepped."""
    _write_time_info(tmp_path, 12.0)
    stopped = tmp_path / "postProcessing" / "timeInfo" / "12.004"
    stopped.mkdir()
    (stopped / "timeInfo.dat").write_text("")
    # timeInfo_12.004.dat: the replacing leg, one step of STEP_COST
    (stopped / "timeInfo_12.004.dat").write_text(
        f"# Time\tcpuTime\tclockTime\n{12.004 + DELTA_T:.6f}\t{STEP_COST}\t1\n")
    case = Case(tmp_path)
    cpu = sum(START_UP_COSTS) + STEP_COST * (STEPS - len(START_UP_COSTS))
    assert case.cpu_seconds() == pytest.approx(cpu + STEP_COST, rel=1e-9)
    assert case.simulated_seconds() == pytest.approx((STEPS + 1) * DELTA_T, rel=1e-6)
