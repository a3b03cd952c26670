"""The ldnaFoam test suite's two tiers, by folder.

- ``tests/unit``: the Python tools alone on synthetic tables and fields, in
  seconds, on a machine without a build (``pytest -m unit``);
- ``tests/solver``: the real solver on small real cases (its fixtures are in
  tests/solver/conftest.py, the shared helpers in solver_cases.py and
  userpath.py).

Tests skip nothing: without a built ldnaFoam a session that selects solver
tests fails at once.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from solver_cases import PROJECT_DIR

#: The unit tier's folder
UNIT_DIR = Path(__file__).resolve().parent / "unit"


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The tier of each test is its folder's (``-m unit``, ``-m solver``)."""
    for item in items:
        unit = UNIT_DIR in Path(item.path).resolve().parents
        item.add_marker(pytest.mark.unit if unit else pytest.mark.solver)


def pytest_collection_finish(session: pytest.Session) -> None:
    """Fail early and clearly when a selected test needs the solver and it
    has not been built; the unit tier (pytest -m unit) needs no build."""
    needs_solver = any(item.get_closest_marker("solver") for item in session.items)
    if needs_solver and not (PROJECT_DIR / "build" / "bin" / "ldnaFoam").exists():
        raise pytest.UsageError("ldnaFoam is not built: run ./Allwmake (or bin/ldna-test)")
