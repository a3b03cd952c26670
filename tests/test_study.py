"""``ldna study``: a 2 x 1 parameter grid of the LDNA template, run for real.

Two laser powers at one welding speed, at resolution level 0 for a few
milliseconds: the study must produce one CSV row per member with its
parameter values and bead metrics, each member's case must carry its
values, and the stronger laser must have heated the metal more.
"""
from __future__ import annotations

import csv
import sys
from pathlib import Path

from conftest import TEMPLATE
from ldna.foamdict import read_scalars
from ldna.foamcase import run

#: Simulated time of each member [s]: about 40 steps at level 0
END_TIME = 0.01
LASER_POWERS = ("1000", "1400")
WELDING_SPEED = "0.0075"


def test_study_of_a_two_by_one_grid(tmp_path: Path) -> None:
    study_dir = tmp_path / "study"
    ldna = Path(sys.executable).parent / "ldna"
    result = run(tmp_path, f"{ldna} study {TEMPLATE} {study_dir} "
                           f"--set laserPower={','.join(LASER_POWERS)} "
                           f"--set weldingSpeed={WELDING_SPEED} --end-time {END_TIME}",
                 log_name="study")
    print(result.output[-500:])

    with open(study_dir / "results.csv", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(rows) == 2
    assert [row["laserPower"] for row in rows] == list(LASER_POWERS)
    assert all(row["weldingSpeed"] == WELDING_SPEED for row in rows)
    assert all(row["status"] == "done" for row in rows)
    for row in rows:
        member = study_dir / row["member"]
        parameters = read_scalars(member / "system" / "caseParameters")
        assert parameters["laserPower"] == float(row["laserPower"])
        assert float(row["time"]) > 0.5 * END_TIME
        assert float(row["peak_temperature"]) > parameters["ambientTemperature"]
        assert float(row["wall_time_s"]) > 0
    peak = [float(row["peak_temperature"]) for row in rows]
    print(f"peak metal temperature at {LASER_POWERS} W: {peak} K")
    assert peak[1] > peak[0], "the stronger laser heats the metal more"
