"""Second tier: every tutorial runs to its end (smoke test).

Each tutorial is copied to a temporary directory and its Allrun executed;
the solver must finish every run without a fatal error and with bounded
fields.  Physics is asserted by the first-tier tests.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from ldna.foamcase import PROJECT_DIR, alpha_bounds, read_balances, run

#: Known failures, each with what was measured (strict: a fix makes the test
#: fail until the entry is removed); empty while every scene stays in bounds
KNOWN_FAILURES: dict[str, str] = {}

TUTORIALS = [
    pytest.param(path, id=path.name,
                 marks=[pytest.mark.xfail(strict=True, reason=KNOWN_FAILURES[path.name])]
                 if path.name in KNOWN_FAILURES else [])
    for path in sorted(p.parent for p in (PROJECT_DIR / "tutorials").glob("*/Allrun"))
]


@pytest.mark.parametrize("tutorial", TUTORIALS)
def test_tutorial_runs(tutorial: Path, tmp_path: Path) -> None:
    case = Path(shutil.copytree(tutorial, tmp_path / tutorial.name))
    run(case, "./Allrun", log_name="Allrun")
    for log in case.rglob("log.*"):
        assert "FOAM FATAL" not in log.read_text(errors="replace"), log.name
    solver_logs = list(case.rglob("log.ldnaFoam"))
    assert len(solver_logs) == 1, "a tutorial runs ldnaFoam once"
    solver_log = solver_logs[0]
    assert solver_log.read_text().rstrip().endswith("Finalising parallel run") or \
        "\nEnd\n" in solver_log.read_text()
    balances = read_balances(solver_log)
    assert len(balances) > 1
    assert balances["T_min"].min() > 0
    low, high = alpha_bounds(solver_log)
    assert low > -1e-6 and high < 1 + 1e-6
