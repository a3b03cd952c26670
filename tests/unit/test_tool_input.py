"""The ``ldna`` commands refuse a bad argument or case in one line that says
what is wrong (no traceback); no solver run (the solver's own bad-input
campaign is tests/solver/test_input_campaign.py)."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from ldna.case import Case
from solver_cases import PROJECT_DIR, TEMPLATE

#: ldna commands with a bad argument or case: (arguments, text of the one-line error)
BAD_TOOL_CALLS = [
    (["post", "/nonexistent"], "not an OpenFOAM case"),
    (["post", str(TEMPLATE)], "has no mesh"),
    (["post", str(TEMPLATE), "--time", "nan"], "finite"),
    (["study", "/nonexistent", "study", "--set", "level=0"], "not an OpenFOAM case"),
    (["study", str(TEMPLATE), "study", "--set", "laserPower"], "NAME=value1,value2"),
    (["study", str(TEMPLATE), "study", "--set", "level=0", "--np", "0"], "at least 1"),
    (["mesh-levels", "/nonexistent"], "not an OpenFOAM case"),
    (["gmsh-mesh", str(TEMPLATE), "--level", "7"], "0..3"),
    (["accuracy", str(TEMPLATE), "out", "--levels", "0,x"], "comma-separated list"),
    (["accuracy", str(TEMPLATE), "out", "--end-time", "-1"], "positive"),
    (["accuracy", str(TEMPLATE), "out", "--min-window", "nan"], "positive"),
    (["accuracy", str(TEMPLATE), "out", "--min-window", "1"], "--scene bead"),
    (["accuracy", str(TEMPLATE), "out", "--sequence"], "--start-from"),
    (["accuracy", str(TEMPLATE), "out", "--set", "length=30,40"], "one value per entry"),
    (["accuracy", str(TEMPLATE), "out", "--set", "length"], "NAME=value1,value2"),
    (["bead-report", "/nonexistent", "out"], "not an OpenFOAM case"),
]


@pytest.mark.parametrize("arguments,expected", BAD_TOOL_CALLS,
                         ids=[" ".join(c[0][:2]) + " " + c[1] for c in BAD_TOOL_CALLS])
def test_ldna_tools_reject_bad_input_in_one_line(tmp_path: Path, arguments: list[str],
                                                 expected: str) -> None:
    ldna = PROJECT_DIR / "build" / "venv" / "bin" / "ldna"
    result = subprocess.run([str(ldna), *arguments], cwd=tmp_path, capture_output=True,
                            text=True, timeout=60, check=False)
    print(result.stderr)
    assert result.returncode != 0
    assert "Traceback" not in result.stderr + result.stdout
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith(f"ldna {arguments[0]}: error:") and expected in last


def test_mesh_levels_rejects_a_domain_that_cannot_be_meshed(tmp_path: Path) -> None:
    ldna = PROJECT_DIR / "build" / "venv" / "bin" / "ldna"
    for entry, value in [("length", "0"), ("width", "-28"), ("claddingHeight", "1e300")]:
        case = Case.copy_of(TEMPLATE, tmp_path / f"{entry}{value}")
        case.set("system/caseParameters", entry, value)
        result = subprocess.run([str(ldna), "mesh-levels", str(case)], capture_output=True,
                                text=True, timeout=60, check=False)
        assert result.returncode != 0 and "Traceback" not in result.stderr
        assert f"{entry} must be in (0, 1e4) mm" in result.stderr
