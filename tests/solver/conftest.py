"""Fixtures of the solver tests: real cases run by the real solver.

Each fixture copies a small case into a temporary directory (an
``ldna.case.Case``), completes it with the numerics (and, where the test
does not set its own, the material data) of the LDNA template so that the
tests exercise what users run, and runs OpenFOAM's applications on it
(``solver_cases.meshed_test_case``).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from ldna.case import Case
from solver_cases import PROJECT_DIR, TEMPLATE, meshed_test_case


@pytest.fixture
def stefan_case(tmp_path: Path) -> Case:
    """The meshed 1D melting bar of cases/stefanMelting (not yet run)."""
    case = Case.copy_of(PROJECT_DIR / "cases" / "stefanMelting", tmp_path / "stefanMelting")
    case.run("blockMesh")
    return case


@pytest.fixture
def energy_box_case(tmp_path: Path) -> Case:
    """The closed box, metal below argon, with its heater zone."""
    return meshed_test_case("energyBox", tmp_path)


@pytest.fixture
def laser_slab_case(tmp_path: Path) -> Case:
    """The box with a flat 316L slab under argon, for the laser tests."""
    return meshed_test_case("laserSlab", tmp_path)


@pytest.fixture
def marangoni_layer_case(tmp_path: Path) -> Case:
    """The 2D liquid layer between a hot and a cold wall, no gravity."""
    return meshed_test_case("marangoniLayer", tmp_path)


@pytest.fixture
def static_droplet_case(tmp_path: Path) -> Case:
    """The 2D box with a liquid cylinder of exact cut-cell fractions."""
    return meshed_test_case("staticDroplet", tmp_path)


@pytest.fixture
def ldna_case(tmp_path: Path) -> Case:
    """A copy of the LDNA template at resolution level 0, ASCII output (not yet meshed)."""
    case = Case.copy_of(TEMPLATE, tmp_path / "ldna")
    case.set("system/caseParameters", "level", "0")
    case.set("system/controlDict", "writeFormat", "ascii")
    return case
