"""1D melting against the two-phase Neumann solution (Stefan problem).

The case is the template ``cases/stefanMelting``; the exact front and the
reading of the simulated one are in ``ldna.stefan`` (also used by
``ldna accuracy``).
"""
from __future__ import annotations

import math

import pytest

from ldna.case import Case
from ldna.stefan import NeumannSolution, front_position, neumann_lambda

#: Allowed relative error of the front position (required: 3 %)
FRONT_TOLERANCE = 0.03


def test_melting_front_follows_neumann_solution(stefan_case: Case) -> None:
    stefan_case.run("ldnaFoam")
    exact_solution = NeumannSolution.from_case(stefan_case)

    for time in ("1", "2"):
        exact = exact_solution.front(float(time))
        simulated = front_position(stefan_case, time)
        error = abs(simulated - exact) / exact
        print(f"t = {time} s: front {simulated * 1e3:.4f} mm, Neumann {exact * 1e3:.4f} mm, "
              f"error {100 * error:.2f} %")
        assert error < FRONT_TOLERANCE


def test_neumann_lambda_reduces_to_one_phase_solution() -> None:
    """With the solid at the melting point the classic one-phase root is found."""
    st = 0.5
    lam = neumann_lambda(st, 0.0, 1.0)
    assert lam * math.exp(lam**2) * math.erf(lam) == pytest.approx(st / math.sqrt(math.pi), rel=1e-9)
