"""Fixtures of the solver tests: real cases run by the real solver.

Each fixture copies a small case into a temporary directory (an
``ldna.case.Case``), completes it with the numerics (and, where the test
does not set its own, the material data) of the LDNA template so that the
tests exercise what users run, and runs OpenFOAM's applications on it
(``solver_cases.meshed_test_case``).
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

import pytest

from ldna.case import Case
from solver_cases import PROJECT_DIR, TEMPLATE, meshed_test_case


@pytest.fixture
def stefan_case(tmp_path: Path) -> Case:
    """The meshed 1D melting bar of cases/stefanMelting (not yet run)."""
    case = Case.copy_of(PROJECT_DIR / "cases" / "stefanMelting", tmp_path / "stefanMelting")
    case.run("blockMesh")
    return case


def meshed_case_fixture(name: str, description: str) -> Callable[[Path], Case]:
    """A fixture giving tests/cases/<name>, prepared and meshed (not yet run)."""
    @pytest.fixture
    def fixture(tmp_path: Path) -> Case:
        return meshed_test_case(name, tmp_path)
    fixture.__doc__ = description
    return fixture


energy_box_case = meshed_case_fixture(
    "energyBox", "The closed box, metal below argon, with its heater zone.")
laser_slab_case = meshed_case_fixture(
    "laserSlab", "The box with a flat 316L slab under argon, for the laser tests.")
marangoni_layer_case = meshed_case_fixture(
    "marangoniLayer", "The 2D liquid layer between a hot and a cold wall, no gravity.")
gas_column_case = meshed_case_fixture(
    "gasColumn", "The 1D column of liquid 316L under argon with 5 % gas in one cell.")
static_droplet_case = meshed_case_fixture(
    "staticDroplet", "The 2D box with a liquid cylinder of exact cut-cell fractions.")


@pytest.fixture
def ldna_case(tmp_path: Path) -> Case:
    """A copy of the LDNA template at resolution level 0, ASCII output (not yet meshed)."""
    case = Case.copy_of(TEMPLATE, tmp_path / "ldna")
    case.set("system/caseParameters", "level", "0")
    case.set("system/controlDict", "writeFormat", "ascii")
    return case
