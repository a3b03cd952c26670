"""The cluster workflow of the template: its SLURM batch script and Allrun -parallel.

Without a SLURM scheduler the batch script runs as SLURM would start it:
with bash, in the submit directory, with SLURM_NTASKS set, in a clean
environment where only LDNA_DIR points to the checkout.  Both must decompose
the case, run ldnaFoam on the ranks, reconstruct the fields and leave the
bead metrics in postProcessing/; Allclean removes the results.
"""
from __future__ import annotations

import pytest

from ldna.case import Case
from ldna.case import PROJECT_DIR
from ldna.post import read_function_object_metrics
from userpath import run_as_user

pytestmark = pytest.mark.user_path

#: Simulated time of the shortened scene [s] (some 20 steps at level 0)
END_TIME = "0.005"
#: Three ranks: more than the template's two, on a 2-core machine too
#: (the split must follow the number of subdomains)
N_RANKS = 3


def shorten(case: Case) -> None:
    """End the template's scene after END_TIME and write then."""
    for entry in ("endTime", "writeInterval"):
        case.set("system/controlDict", entry, END_TIME)


def check_parallel_run(case: Case) -> None:
    """Decomposed on N_RANKS, run to the end, reconstructed, metrics written."""
    assert (case / f"processor{N_RANKS - 1}").is_dir()
    assert not (case / f"processor{N_RANKS}").exists()
    log = (case / "log.ldnaFoam").read_text()
    assert "Finalising parallel run" in log and "FOAM FATAL" not in log
    assert case.times[-1].name == END_TIME, "reconstructed end time"
    assert len(read_function_object_metrics(case)) > 0


def test_slurm_batch_script(ldna_case: Case) -> None:
    case = ldna_case
    shorten(case)
    outcome = run_as_user("bash ldna.sbatch", cwd=case, SLURM_NTASKS=str(N_RANKS),
                          SLURM_SUBMIT_DIR=str(case), LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output[-3000:]
    check_parallel_run(case)


def test_template_allrun_parallel(ldna_case: Case) -> None:
    case = ldna_case
    shorten(case)
    # As a user edits the file: only the number of subdomains
    case.set("system/decomposeParDict", "numberOfSubdomains", str(N_RANKS))
    outcome = run_as_user("./Allrun -parallel", cwd=case, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output[-3000:]
    check_parallel_run(case)
    outcome = run_as_user("./Allclean", cwd=case, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output
    assert [t.name for t in case.times] == ["0"]
    assert not (case / "processor0").exists()


#: Where the first leg of a carried run stops [s]: half the shortened scene
HALF_TIME = "0.0025"


def test_a_packed_parallel_run_continues_on_its_ranks(ldna_case: Case, tmp_path) -> None:
    """A run stopped on N_RANKS, packed (``ldna pack``: the ranks' latest time
    reconstructed, no processor folders) and unpacked elsewhere continues with
    ``./Allrun -parallel -resume``: its latest time is decomposed again and
    the run goes on from it on the ranks to the end."""
    import sys

    case = ldna_case
    for entry, value in (("endTime", HALF_TIME), ("writeInterval", HALF_TIME)):
        case.set("system/controlDict", entry, value)
    case.set("system/decomposeParDict", "numberOfSubdomains", str(N_RANKS))
    outcome = run_as_user("./Allrun -parallel", cwd=case, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output[-3000:]
    ldna = f"{sys.executable} -m ldna.cli"
    archive = tmp_path / "carried.tar.xz"
    carried = Case(tmp_path / "elsewhere" / "carried")
    for command in (f"{ldna} pack {case.path} {archive}",
                    f"{ldna} unpack {archive} {carried.path}"):
        outcome = run_as_user(command, cwd=tmp_path, LDNA_DIR=str(PROJECT_DIR))
        assert outcome.returncode == 0, outcome.output[-3000:]
    assert not (carried / "processor0").exists()
    assert [t.name for t in carried.times] == ["0", HALF_TIME]
    carried.set("system/controlDict", "endTime", END_TIME)
    outcome = run_as_user("./Allrun -parallel -resume", cwd=carried, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output[-3000:]
    assert (carried / "log.decomposePar.resume").is_file()
    assert (carried / HALF_TIME / "T").is_file()
    check_parallel_run(carried)
    assert "Starting time loop" in (carried / "log.ldnaFoam").read_text()
    first = float(carried.balances()["time"][0])
    assert first < float(HALF_TIME), "the packed run's tables came along"
