"""Stopping a run and restarting it from its last written time changes nothing.

The LDNA template (level 0, every effect on) runs once straight to
END_TIME, and once to STOP_TIME, where it stops and is started again
(``startFrom latestTime``, as a resubmitted cluster job does) to END_TIME.
Fields are written with 17 significant digits, so the restart reads back
exactly the state the first leg wrote; the two runs must then agree at
END_TIME to within the linear solvers' tolerance.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ldna.case import Case

#: Where the interrupted run stops, and where both runs end [s]
#: The first droplets are inserted at 9.7 ms, before the stop, the next ones
#: (every 10 ms) after it; the end is a write time (a multiple of the stop)
STOP_TIME = "0.015"
END_TIME = "0.03"
#: Allowed difference relative to each field's scale.  The template's
#: solvers stop at an absolute residual of 1e-8 to 1e-9 (fvSolution);
#: the same sequence of operations must reproduce that to round-off
FIELD_TOLERANCE = 1e-9
FIELDS = ("alpha.metal", "T", "U", "p_rgh")


def prepare(case: Case) -> None:
    """Mesh and initialise the case; exact (17 digit) ASCII output every STOP_TIME."""
    case.set("system/controlDict", "writePrecision", "17")
    case.set("system/controlDict", "writeInterval", STOP_TIME)
    case.mesh()
    case.run("setFields")


def test_restart_equals_uninterrupted_run(ldna_case: Case, tmp_path: Path) -> None:
    straight = ldna_case
    prepare(straight)
    interrupted = Case.copy_of(straight, tmp_path / "interrupted")
    # The copy leaves out the mesh: mesh the copy the same way
    interrupted.mesh()
    interrupted.run("setFields")

    straight.set("system/controlDict", "endTime", END_TIME)
    straight.run("ldnaFoam")

    interrupted.set("system/controlDict", "endTime", STOP_TIME)
    interrupted.run("ldnaFoam", log_name="ldnaFoam.first")
    interrupted.set("system/controlDict", "endTime", END_TIME)
    interrupted.run("ldnaFoam", log_name="ldnaFoam.restart")
    assert f"Create mesh for time = {STOP_TIME}" in \
        (interrupted / "log.ldnaFoam.restart").read_text(), "the second leg did not restart"

    for field in FIELDS:
        a = straight.field(field, END_TIME)
        b = interrupted.field(field, END_TIME)
        scale = np.abs(a).max()
        difference = np.abs(a - b).max() / scale
        print(f"{field}: largest difference {difference:.3e} of its scale {scale:.4g}")
        assert difference < FIELD_TOLERANCE
