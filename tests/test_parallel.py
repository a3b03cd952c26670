"""Serial and MPI runs of the LDNA template agree within solver tolerance.

The template scene (level 0) runs once serially and once on two ranks
(decomposePar, mpirun -np 2, reconstructPar), with every linear solver
converged to 1e-13 so that the decomposition can change the answer only at
that level; the fields must then agree to well below any physical scale.

Compared at 0.05 s: the template with its laser, Marangoni flow,
evaporation, surface losses and porosity.  With the droplets as well the
runs differ by more (strict known failure below): T by 6e-7 of its scale
after one step, 9e-3 at 5 ms and 3.5e-4 at 0.05 s; whether that is a
decomposition error of the droplet source or round-off amplified by the
droplets' impact (the fixed-source scene of earlier versions grew U
differences from 1.6e-8 after five steps to 3e-3 at 0.1 s) is not yet known.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from ldna.foamcase import read_internal_field, run, run_parallel, time_directories
from ldna.foamdict import keep_blocks, set_entry

#: Time of the comparison [s]
END_TIME = "0.05"
#: Temperature [K] the laser brings the metal above by END_TIME (ambient 300 K;
#: measured 498 K)
HEATED = 400
#: Linear-solver tolerance of both runs
SOLVER_TOLERANCE = "1e-13"
#: Allowed difference relative to each field's scale; measured about 1e-6
#: for T and U with the tolerance above (1e-4 with the template's own)
FIELD_TOLERANCE = 1e-5


def tighten_solvers(case: Path) -> None:
    """Converge every linear solver of the case to SOLVER_TOLERANCE."""
    fv_solution = "system/fvSolution"
    run(case, f"foamDictionary -entry solvers/p_rgh/relTol -set 0 {fv_solution}",
        log_name="foamDictionary.relTol")
    for solver in ("p_rgh", '"(U|T)"', '"alpha.metal.*"'):
        run(case, f"foamDictionary -entry 'solvers/{solver}/tolerance' -set {SOLVER_TOLERANCE} "
                  f"{fv_solution}", log_name="foamDictionary.tolerance")


#: Effects of the template compared; droplets are the known failure
EFFECTS = ["laser", "marangoni", "evaporation", "surfaceLosses", "enthalpyPorosity"]
KNOWN_FAILURE_DROPLETS = (
    "with droplets T differs by 3.5e-4 of its scale at 0.05 s (6e-7 after one step)")


@pytest.mark.parametrize("with_droplets", [
    False,
    pytest.param(True, marks=pytest.mark.xfail(strict=True, reason=KNOWN_FAILURE_DROPLETS)),
], ids=["without_droplets", "with_droplets"])
def test_serial_and_parallel_runs_agree(ldna_case: Path, tmp_path: Path,
                                        with_droplets: bool) -> None:
    serial = ldna_case
    keep_blocks(serial / "constant" / "fvOptions",
                EFFECTS + (["wireDroplets"] if with_droplets else []))
    set_entry(serial / "system" / "controlDict", "endTime", END_TIME)
    set_entry(serial / "system" / "controlDict", "writeInterval", END_TIME)
    set_entry(serial / "system" / "controlDict", "writePrecision", "14")
    tighten_solvers(serial)
    for tool in ("blockMesh", "setFields"):
        run(serial, tool)
    parallel = Path(shutil.copytree(serial, tmp_path / "parallel"))

    run(serial, "ldnaFoam")
    run(parallel, "decomposePar")
    run_parallel(parallel, "ldnaFoam", 2)
    run(parallel, "reconstructPar -latestTime")

    end_serial, end_parallel = time_directories(serial)[-1], time_directories(parallel)[-1]
    assert end_serial.name == end_parallel.name == END_TIME
    for field in ("T", "U", "alpha.metal", "p_rgh"):
        a = read_internal_field(end_serial / field)
        b = read_internal_field(end_parallel / field)
        scale = np.abs(a).max()
        difference = np.abs(a - b).max() / scale
        print(f"{field}: largest difference {difference:.2e} of its scale {scale:.6g}")
        assert difference < FIELD_TOLERANCE
    # The scene is not trivial: the laser has heated the metal
    assert read_internal_field(end_serial / "T").max() > HEATED
