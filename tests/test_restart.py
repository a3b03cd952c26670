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

from ldna.foamcase import copy_case, read_internal_field, run
from ldna.foamdict import set_entry
from ldna.meshing import mesh_case

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


def prepare(case: Path) -> None:
    """Mesh and initialise the case; exact (17 digit) ASCII output every STOP_TIME."""
    control = case / "system" / "controlDict"
    set_entry(control, "writePrecision", "17")
    set_entry(control, "writeInterval", STOP_TIME)
    mesh_case(case)
    run(case, "setFields")


def test_restart_equals_uninterrupted_run(ldna_case: Path, tmp_path: Path) -> None:
    straight = ldna_case
    prepare(straight)
    interrupted = copy_case(straight, tmp_path / "interrupted")
    # copy_case leaves out the mesh: mesh the copy the same way
    mesh_case(interrupted)
    run(interrupted, "setFields")

    set_entry(straight / "system" / "controlDict", "endTime", END_TIME)
    run(straight, "ldnaFoam")

    set_entry(interrupted / "system" / "controlDict", "endTime", STOP_TIME)
    run(interrupted, "ldnaFoam", log_name="ldnaFoam.first")
    set_entry(interrupted / "system" / "controlDict", "endTime", END_TIME)
    run(interrupted, "ldnaFoam", log_name="ldnaFoam.restart")
    assert f"Create mesh for time = {STOP_TIME}" in \
        (interrupted / "log.ldnaFoam.restart").read_text(), "the second leg did not restart"

    for field in FIELDS:
        a = read_internal_field(straight / END_TIME / field)
        b = read_internal_field(interrupted / END_TIME / field)
        scale = np.abs(a).max()
        difference = np.abs(a - b).max() / scale
        print(f"{field}: largest difference {difference:.3e} of its scale {scale:.4g}")
        assert difference < FIELD_TOLERANCE
