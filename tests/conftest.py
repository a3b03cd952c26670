"""Fixtures of the ldnaFoam test suite: real cases run by the real solver.

Each fixture copies a small case into a temporary directory (an
``ldna.case.Case``), completes it
with the numerics (and, where the test does not set its own, the material
data) of the LDNA template so that the tests exercise what users run, and
runs OpenFOAM's applications on it.  Tests skip nothing: without a built
ldnaFoam the session fails.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from foamlib import FoamFile

from ldna.case import Case

PROJECT_DIR = Path(__file__).resolve().parents[1]

TEST_CASES = Path(__file__).resolve().parent / "cases"
TEMPLATE = PROJECT_DIR / "cases" / "ldna"


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The two tiers: a test not marked ``unit`` runs the solver."""
    for item in items:
        if item.get_closest_marker("unit") is None:
            item.add_marker(pytest.mark.solver)


def pytest_sessionstart(session: pytest.Session) -> None:
    """Fail early and clearly when the solver has not been built."""
    if not (PROJECT_DIR / "build" / "bin" / "ldnaFoam").exists():
        raise pytest.UsageError("ldnaFoam is not built: run ./Allwmake (or bin/ldna-test)")


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


@pytest.fixture
def stefan_case(tmp_path: Path) -> Case:
    """The meshed 1D melting bar of cases/stefanMelting (not yet run)."""
    case = Case.copy_of(PROJECT_DIR / "cases" / "stefanMelting", tmp_path / "stefanMelting")
    case.run("blockMesh")
    return case


@pytest.fixture
def energy_box_case(tmp_path: Path) -> Case:
    """The meshed closed box, metal below argon, with its heater zone (not yet run)."""
    case = prepare_test_case("energyBox", tmp_path, material_from_template=True)
    case.run("blockMesh")
    case.run("topoSet")
    case.run("setFields")
    return case


@pytest.fixture
def laser_slab_case(tmp_path: Path) -> Case:
    """The meshed box with a flat 316L slab under argon, for the laser tests (not yet run)."""
    case = prepare_test_case("laserSlab", tmp_path, material_from_template=True)
    case.run("blockMesh")
    case.run("setFields")
    return case


@pytest.fixture
def marangoni_layer_case(tmp_path: Path) -> Case:
    """The meshed 2D liquid layer between a hot and a cold wall, no gravity (not yet run)."""
    case = prepare_test_case("marangoniLayer", tmp_path, material_from_template=False)
    case.run("blockMesh")
    case.run("setFields")
    return case


@pytest.fixture
def static_droplet_case(tmp_path: Path) -> Case:
    """The meshed 2D box with a liquid cylinder of exact cut-cell fractions (not yet run)."""
    case = prepare_test_case("staticDroplet", tmp_path, material_from_template=False)
    case.run("blockMesh")
    case.run("setAlphaField")
    return case


@pytest.fixture
def ldna_case(tmp_path: Path) -> Case:
    """A copy of the LDNA template at resolution level 0, ASCII output (not yet meshed)."""
    case = Case.copy_of(TEMPLATE, tmp_path / "ldna")
    case.set("system/caseParameters", "level", "0")
    case.set("system/controlDict", "writeFormat", "ascii")
    return case
