"""Every tutorial's Allrun as a user runs it, shortened to a few time steps.

Each tutorial is copied to a temporary directory, its end time set to a few
initial time steps (the OpenFOAM way: in the copy's system/controlDict), and
its Allrun executed from a plain shell with nothing sourced (marker
``user_path``); the solver must finish without a fatal error and with bounded
fields, and Allclean must remove what it made.  The main LDNA scene also runs
its Allrun-parallel.  Physics is asserted by the first-tier tests.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from ldna.case import Case
from ldna.case import PROJECT_DIR
from userpath import run_as_user

pytestmark = pytest.mark.user_path

#: Time steps of a shortened tutorial (at the initial step size)
SMOKE_STEPS = 10

#: Known failures, each with what was measured (strict: a fix makes the test
#: fail until the entry is removed); empty while every scene stays in bounds
KNOWN_FAILURES: dict[str, str] = {}

TUTORIAL_DIRS = sorted(p.parent for p in (PROJECT_DIR / "tutorials").glob("*/Allrun"))


def tutorial_params(script: str, names: list[str] | None = None) -> list:
    """pytest parameters: the tutorials (optionally only ``names``) that have ``script``."""
    return [
        pytest.param(path, id=path.name,
                     marks=[pytest.mark.xfail(strict=True, reason=KNOWN_FAILURES[path.name])]
                     if path.name in KNOWN_FAILURES else [])
        for path in TUTORIAL_DIRS
        if (path / script).exists() and (names is None or path.name in names)
    ]


def shorten(tutorial: Path, steps: int) -> None:
    """End the tutorial after ``steps`` initial time steps and write then.

    A tutorial without its own controlDict takes the template's, so the
    shortened copy of that (and the caseParameters it includes) is put in
    its system/ folder.
    """
    control = tutorial / "system" / "controlDict"
    if not control.exists():
        control.parent.mkdir(exist_ok=True)
        # with the caseParameters it includes, unless the tutorial has its own
        for name in ("controlDict", "caseParameters"):
            if not (tutorial / "system" / name).exists():
                shutil.copy(PROJECT_DIR / "cases" / "ldna" / "system" / name,
                            tutorial / "system" / name)
    case = Case(tutorial)
    delta_t = case.scalar("system/controlDict", "deltaT")
    end_time = f"{steps * delta_t:g}"
    for entry in ("endTime", "writeInterval"):
        case.set("system/controlDict", entry, end_time)


def run_shortened(tutorial: Path, tmp_path: Path, script: str) -> None:
    """Run the shortened copy of ``tutorial`` with ``script`` and check its logs."""
    case = Path(shutil.copytree(tutorial, tmp_path / tutorial.name,
                                ignore=shutil.ignore_patterns("run")))
    shorten(case, SMOKE_STEPS)
    # A copy outside the checkout finds it through LDNA_DIR, as a user's would
    outcome = run_as_user(f"./{script}", cwd=case, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output[-3000:]
    for log in case.rglob("log.*"):
        assert "FOAM FATAL" not in log.read_text(errors="replace"), log.name
    solver_logs = list(case.rglob("log.ldnaFoam"))
    assert len(solver_logs) == 1, "a tutorial runs ldnaFoam once"
    solver_log = solver_logs[0]
    text = solver_log.read_text()
    assert text.rstrip().endswith("Finalising parallel run") or "\nEnd\n" in text
    run_dir = Case(solver_log.parent)
    balances = run_dir.balances()
    assert len(balances) > 1
    assert balances["T_min"].min() > 0
    low, high = run_dir.alpha_bounds()
    assert low > -1e-6 and high < 1 + 1e-6


@pytest.mark.parametrize("tutorial", tutorial_params("Allrun"))
def test_tutorial_runs(tutorial: Path, tmp_path: Path) -> None:
    run_shortened(tutorial, tmp_path, "Allrun")
    case = tmp_path / tutorial.name
    outcome = run_as_user("./Allclean", cwd=case, LDNA_DIR=str(PROJECT_DIR))
    assert outcome.returncode == 0, outcome.output
    assert not (case / "run").exists()


@pytest.mark.parametrize("tutorial", tutorial_params("Allrun-parallel", ["ldna"]))
def test_tutorial_runs_in_parallel(tutorial: Path, tmp_path: Path) -> None:
    run_shortened(tutorial, tmp_path, "Allrun-parallel")
    assert (tmp_path / tutorial.name / "run" / "processor1").is_dir()


def test_every_tutorial_has_its_scripts() -> None:
    for tutorial in TUTORIAL_DIRS:
        for script in ("Allrun", "Allrun-parallel", "Allclean"):
            assert (tutorial / script).exists(), f"{tutorial.name}/{script}"
