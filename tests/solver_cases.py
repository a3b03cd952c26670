"""The small cases the solver tests run, and the check they share.

``prepare_test_case`` copies one of tests/cases and completes it with the
LDNA template's numerics (and, if asked, its material data);
``meshed_test_case`` also meshes it as the case needs; ``assert_named_error``
checks that a bad input stops with a named FatalIOError and no crash.
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from foamlib import FoamFile

from ldna.case import Case

PROJECT_DIR = Path(__file__).resolve().parents[1]

TEST_CASES = Path(__file__).resolve().parent / "cases"
TEMPLATE = PROJECT_DIR / "cases" / "ldna"
#: The template's saved quasi-steady weld (12 s of welding), which runs and
#: band meshes start from
STEADY_WELD = PROJECT_DIR / "cases" / "steadyWeld"


def prepare_test_case(name: str, destination: Path, material_from_template: bool) -> Case:
    """Copy tests/cases/<name> and add the template's fvSchemes and fvSolution.

    With ``material_from_template`` the template's thermophysicalProperties
    are used as well, with one metal: its filler, 316L (the template's
    substrate metal left out), and argon.
    """
    case = Case.copy_of(TEST_CASES / name, destination / name)
    for file in ("fvSchemes", "fvSolution"):
        shutil.copy(TEMPLATE / "system" / file, case / "system" / file)
    if material_from_template:
        # A case whose constant/ would hold nothing else has none in git
        (case / "constant").mkdir(exist_ok=True)
        properties = case / "constant" / "thermophysicalProperties"
        shutil.copy(TEMPLATE / "constant" / "thermophysicalProperties", properties)
        del FoamFile(properties)["substrate"]
    return case


#: Per test case: whether it takes the template's material data, and the
#: applications that set it up after blockMesh
MESHING: dict[str, tuple[bool, tuple[str, ...]]] = {
    "energyBox": (True, ("topoSet", "setFields")),
    "laserSlab": (True, ("setFields",)),
    "marangoniLayer": (False, ("setFields",)),
    "staticDroplet": (False, ("setAlphaField",)),
    "gasColumn": (True, ("setFields",)),
}


def meshed_test_case(name: str, destination: Path) -> Case:
    """tests/cases/<name>, prepared and meshed (not yet run)."""
    material_from_template, setup = MESHING[name]
    case = prepare_test_case(name, destination, material_from_template)
    case.run("blockMesh")
    for application in setup:
        case.run(application)
    return case


#: What a crash, not a named error, leaves in the output
CRASHES = ("sigSegv", "Segmentation fault", "sigFpe", "nan")


def assert_named_error(case: Case, expected: list[str],
                       crashes: tuple[str, ...] = CRASHES) -> None:
    """ldnaFoam stops on the case with a FOAM FATAL IO ERROR whose message
    holds every text of ``expected``, and does not crash."""
    result = case.run("ldnaFoam", check=False)
    output = result.output
    error = output[output.find("FOAM FATAL"):]
    print(error[:600])
    assert result.returncode != 0
    assert "FOAM FATAL IO ERROR" in output
    for text in expected:
        assert text in error, f"'{text}' missing from the error message"
    for crash in crashes:
        assert crash not in output


#: Linear-solver tolerance and energy iteration stop of the tight runs
SOLVER_TOLERANCE = "1e-13"
LIQUID_FRACTION_TOLERANCE = "1e-10"


def tighten_solvers(case: Case) -> None:
    """Converge every linear solver of the case to SOLVER_TOLERANCE, the
    final corrector's (p_rghFinal, (U|T)Final) too, with no relative
    tolerance, and the energy iteration to LIQUID_FRACTION_TOLERANCE."""
    fv_solution = case / "system" / "fvSolution"
    solvers, rest = fv_solution.read_text().split("PIMPLE", 1)
    solvers = re.sub(r"(\n\s*)tolerance\s+[^;]+;", rf"\1tolerance {SOLVER_TOLERANCE};", solvers)
    solvers = re.sub(r"(\n\s*)relTol\s+[^;]+;", r"\1relTol 0;", solvers)
    fv_solution.write_text(solvers + "PIMPLE" + rest)
    case.set("system/fvSolution", "PIMPLE/liquidFractionTolerance", LIQUID_FRACTION_TOLERANCE)
