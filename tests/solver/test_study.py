"""``ldna study``: a 3 x 1 parameter grid of the LDNA template, run for real.

Two droplet temperatures at one welding speed, at resolution level 0 for a
few milliseconds: the study must produce one CSV row per member with its
parameter values and bead metrics, each member's case must carry its
values, and the hotter droplets must show in the peak metal temperature
(the droplets, not the laser, set it in the first milliseconds).  A third
member with a droplet temperature of -5 K fails: the study goes on, marks
it failed with its error line and exits non-zero.  The members run two at
a time (``--jobs 2``).
"""
from __future__ import annotations

import csv
import json
import re
import sys
from pathlib import Path

import pytest

from solver_cases import TEMPLATE
from ldna.case import Case
from ldna.foamdict import read_scalars
from ldna.study import Parameter, make_members

#: Simulated time of each member [s]: the first droplets detach at 9.7 ms, so
#: the run has some 100 steps and the function object writes its rows (every
#: 10 steps) well into it
END_TIME = 0.02
DROPLET_TEMPERATURES = ("2000", "2100")
BAD_DROPLET_TEMPERATURE = "-5"
WELDING_SPEED = "0.0075"


def test_study_of_a_three_by_one_grid(tmp_path: Path) -> None:
    study_dir = tmp_path / "study"
    ldna = Path(sys.executable).parent / "ldna"
    temperatures = ",".join(DROPLET_TEMPERATURES + (BAD_DROPLET_TEMPERATURE,))
    result = Case(tmp_path).run(f"{ldna} study {TEMPLATE} {study_dir} "
                                f"--set dropletTemperature={temperatures} "
                                f"--set weldingSpeed={WELDING_SPEED} --end-time {END_TIME} "
                                f"--jobs 2",
                                log_name="study", check=False)
    print(result.output[-500:])
    assert result.returncode != 0, "a failed member fails the study"

    with open(study_dir / "results.csv", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(rows) == 3
    failed = rows.pop()
    print(f"failed member: {failed['error']}")
    assert failed["status"] == "failed"
    assert "'temperature'" in failed["error"] and "-5" in failed["error"]
    assert [row["dropletTemperature"] for row in rows] == list(DROPLET_TEMPERATURES)
    assert all(row["weldingSpeed"] == WELDING_SPEED for row in rows)
    assert all(row["status"] == "done" and row["error"] == "" for row in rows)
    for row in rows:
        member = study_dir / row["member"]
        parameters = read_scalars(member / "system" / "caseParameters")
        assert parameters["dropletTemperature"] == float(row["dropletTemperature"])
        assert float(row["time"]) > 0.5 * END_TIME
        assert float(row["peak_temperature"]) > parameters["ambientTemperature"]
        assert float(row["wall_time_s"]) > 0
    peak = [float(row["peak_temperature"]) for row in rows]
    print(f"peak metal temperature with droplets at {DROPLET_TEMPERATURES} K: {peak} K")
    assert peak[1] > peak[0], "hotter droplets make hotter metal"
    # The finished members' sections side by side, on one temperature scale
    assert (study_dir / "sections.png").stat().st_size > 0
    assert (study_dir / "bead-sections.png").stat().st_size > 0


#: The resumed study: the first leg's end and the raised end time [s]
FIRST_LEG_END = 0.01
RESUMED_END = 0.02
SECOND_LEG_END = 0.025
#: The template's largest time step [s]: a run ends within half a step of its end time
MAX_DELTA_T = 1e-3


def test_study_resumes_from_the_latest_written_time(tmp_path: Path) -> None:
    """A member run to 10 ms continues to 20 ms with --resume, not from time 0."""
    study_dir = tmp_path / "study"
    ldna = Path(sys.executable).parent / "ldna"
    command = f"{ldna} study {TEMPLATE} {study_dir} --set dropletTemperature=2100"
    Case(tmp_path).run(f"{command} --end-time {FIRST_LEG_END}", log_name="study")
    member = study_dir / "member000"
    first_leg_log = (member / "log.ldnaFoam").read_text()
    Case(tmp_path).run(f"{command} --end-time {RESUMED_END} --resume", log_name="study.resume")

    log = (member / "log.ldnaFoam").read_text()
    assert log.startswith(first_leg_log), "the second leg appends to the first's log"
    assert "Starting time loop" in log[len(first_leg_log):]
    # The second leg's tables start where the first ended
    legs = sorted(float(p.name) for p in (member / "postProcessing" / "balances").iterdir())
    print(f"balance tables from {legs} s")
    assert len(legs) == 2 and legs[0] == 0.0
    assert abs(legs[1] - FIRST_LEG_END) < MAX_DELTA_T

    results = json.loads((study_dir / "results.json").read_text())["runs"]
    assert len(results) == 1
    run_ = results[0]
    print({k: run_[k] for k in ("status", "end_time_s", "steady", "bead_width_mm")})
    assert run_["status"] == "done"
    assert abs(run_["end_time_s"] - RESUMED_END) < MAX_DELTA_T
    assert run_["steady"] is False, "20 ms of welding is no steady bead"
    assert run_["dropletTemperature"] == "2100"
    # Every run records its process parameters, swept or not
    template = read_scalars(TEMPLATE / "system" / "caseParameters")
    assert run_["laser_power_W"] == template["laserPower"]
    assert run_["oscillation_amplitude_mm"] == 1e3 * template["oscillationAmplitude"]
    assert (member / "pictures" / "transverse.png").is_file()


def test_study_members_start_from_a_run(tmp_path: Path) -> None:
    """``--start-from RUN``: every member starts at RUN's latest time from its
    fields (a steady neighbour in a real study), not from the flat substrate."""
    ldna = Path(sys.executable).parent / "ldna"
    source_study = tmp_path / "source"
    Case(tmp_path).run(f"{ldna} study {TEMPLATE} {source_study} --set dropletTemperature=2100 "
                       f"--end-time {FIRST_LEG_END}", log_name="source")
    source = source_study / "member000"
    study_dir = tmp_path / "study"
    Case(tmp_path).run(f"{ldna} study {TEMPLATE} {study_dir} --set laserPower=1000 "
                       f"--start-from {source} --end-time {RESUMED_END}", log_name="study")
    member = study_dir / "member000"
    log = (member / "log.ldnaFoam").read_text()
    latest = max((p for p in source.iterdir() if p.name[0].isdigit() and p.name != "0"),
                 key=lambda p: float(p.name))
    assert abs(float(latest.name) - FIRST_LEG_END) < MAX_DELTA_T
    assert f"Create mesh for time = {latest.name}" in log
    results = json.loads((study_dir / "results.json").read_text())["runs"]
    assert results[0]["status"] == "done" and results[0]["laser_power_W"] == 1000
    assert abs(results[0]["end_time_s"] - RESUMED_END) < MAX_DELTA_T

    # Resumed, such a member continues from its latest written time, not
    # from the time it started from
    Case(tmp_path).run(f"{ldna} study {TEMPLATE} {study_dir} --set laserPower=1000 "
                       f"--start-from {source} --end-time {SECOND_LEG_END} --resume",
                       log_name="study.resume")
    last_start = re.findall(r"Create mesh for time = (\S+)",
                            (member / "log.ldnaFoam").read_text())[-1]
    assert abs(float(last_start) - RESUMED_END) < MAX_DELTA_T, last_start
    results = json.loads((study_dir / "results.json").read_text())["runs"]
    assert abs(results[0]["end_time_s"] - SECOND_LEG_END) < MAX_DELTA_T


def test_a_failed_parallel_member_reports_its_foam_error(tmp_path: Path) -> None:
    """On 2 ranks the solver's FatalIOError comes with a rank prefix and is
    followed by MPI's abort notice: results.csv must hold the error."""
    study_dir = tmp_path / "study"
    ldna = Path(sys.executable).parent / "ldna"
    result = Case(tmp_path).run(f"{ldna} study {TEMPLATE} {study_dir} "
                                f"--set dropletTemperature={BAD_DROPLET_TEMPERATURE} "
                                f"--end-time {END_TIME} --np 2", log_name="study", check=False)
    assert result.returncode != 0
    with open(study_dir / "results.csv", encoding="utf-8") as stream:
        (row,) = list(csv.DictReader(stream))
    print(f"failed parallel member: {row['error']}")
    assert row["status"] == "failed"
    assert "'temperature'" in row["error"] and BAD_DROPLET_TEMPERATURE in row["error"]


def test_paired_axes_make_one_member_per_position(tmp_path: Path) -> None:
    """``--paired``: member i takes the i-th value of every axis (a laser off,
    and a narrower sweep at another power), not their 2 x 2 grid."""
    powers = Parameter.parse("laserPower=0,1500")
    amplitudes = Parameter.parse("oscillationAmplitude=6.6e-3,3.3e-3")
    members = make_members(TEMPLATE, tmp_path / "study", [powers, amplitudes], paired=True)
    assert [m.values for m in members] == [
        {"laserPower": "0", "oscillationAmplitude": "6.6e-3"},
        {"laserPower": "1500", "oscillationAmplitude": "3.3e-3"}]
    for member in members:
        parameters = read_scalars(member.path / "system" / "caseParameters")
        assert parameters["laserPower"] == float(member.values["laserPower"])
        assert parameters["oscillationAmplitude"] == float(member.values["oscillationAmplitude"])
    with pytest.raises(ValueError, match="laserPower has 2"):
        make_members(TEMPLATE, tmp_path / "other", [powers, Parameter.parse("level=0")],
                     paired=True)
