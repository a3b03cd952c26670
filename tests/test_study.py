"""``ldna study``: a 3 x 1 parameter grid of the LDNA template, run for real.

Two droplet temperatures at one welding speed, at resolution level 0 for a
few milliseconds: the study must produce one CSV row per member with its
parameter values and bead metrics, each member's case must carry its
values, and the hotter droplets must show in the peak metal temperature
(the droplets, not the laser, set it in the first milliseconds).  A third
member with a droplet temperature of -5 K fails: the study goes on, marks
it failed with its error line and exits non-zero.
"""
from __future__ import annotations

import csv
import sys
from pathlib import Path

from conftest import TEMPLATE
from ldna.foamcase import run
from ldna.foamdict import read_scalars

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
    result = run(tmp_path, f"{ldna} study {TEMPLATE} {study_dir} "
                           f"--set dropletTemperature={temperatures} "
                           f"--set weldingSpeed={WELDING_SPEED} --end-time {END_TIME}",
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
