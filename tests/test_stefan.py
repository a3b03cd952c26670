"""1D melting against the two-phase Neumann solution (Stefan problem).

A bar of metal at Ti below the melting point is heated from x = 0 held at
Tw above it.  The melting front advances as s(t) = 2 lambda sqrt(alpha_l t)
where lambda solves the Stefan condition (Carslaw & Jaeger, 1959, 11.2):

    lambda = St_l e^{-lambda^2} / (sqrt(pi) erf(lambda))
           - St_s sqrt(alpha_s/alpha_l) e^{-lambda^2 alpha_l/alpha_s}
             / (sqrt(pi) erfc(lambda sqrt(alpha_l/alpha_s)))

with St = cp dT / L.  The front of the simulation is where the liquid
fraction crosses 0.5 (T = Tm for the 2 K mushy range of the case).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ldna.foamcase import dictionary_scalar, dictionary_value, read_internal_field, run

#: Allowed relative error of the front position (issue: 3 %)
FRONT_TOLERANCE = 0.03


def neumann_lambda(st_liquid: float, st_solid: float, diffusivity_ratio: float) -> float:
    """Root lambda of the two-phase Neumann melting problem.

    ``diffusivity_ratio`` is alpha_l/alpha_s.  The residual falls
    monotonically from +inf at 0 to -inf, so bisection finds the root.
    """
    nu = math.sqrt(diffusivity_ratio)

    def residual(lam: float) -> float:
        liquid = st_liquid * math.exp(-lam**2) / (math.sqrt(math.pi) * math.erf(lam))
        solid = (st_solid / nu) * math.exp(-(lam * nu) ** 2) / (
            math.sqrt(math.pi) * math.erfc(lam * nu))
        return liquid - solid - lam

    low, high = 1e-9, 10.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if residual(mid) > 0 else (low, mid)
    return 0.5 * (low + high)


def front_position(case: Path, time: str) -> float:
    """x where the liquid fraction first falls through 0.5 (linear interpolation)."""
    liquid = read_internal_field(case / time / "liquidFraction")
    x = read_internal_field(case / time / "Cx")
    i = int(np.argmax(liquid < 0.5))
    assert i > 0, "no melting front inside the bar"
    return float(x[i - 1] + (0.5 - liquid[i - 1]) * (x[i] - x[i - 1]) / (liquid[i] - liquid[i - 1]))


def test_melting_front_follows_neumann_solution(stefan_case: Path) -> None:
    run(stefan_case, "ldnaFoam")
    run(stefan_case, "postProcess -func writeCellCentres -time '1,2'", log_name="writeCellCentres")

    # Material and boundary data as the case states them
    props = "constant/thermophysicalProperties"
    t_melt = 0.5 * (dictionary_scalar(stefan_case, props, "metal/solidus")
                    + dictionary_scalar(stefan_case, props, "metal/liquidus"))
    latent = dictionary_scalar(stefan_case, props, "metal/latentHeat")
    rho = dictionary_scalar(stefan_case, props, "metal/rho/solid")
    cp = dictionary_scalar(stefan_case, props, "metal/Cp/solid")
    kappa = dictionary_scalar(stefan_case, props, "metal/kappa/solid")
    for phase in ("rho", "Cp", "kappa"):
        assert dictionary_value(stefan_case, props, f"metal/{phase}/liquid") == \
            dictionary_value(stefan_case, props, f"metal/{phase}/solid"), \
            "the Neumann solution used here needs equal solid and liquid properties"
    t_initial = dictionary_scalar(stefan_case, "0/T", "internalField")
    t_wall = dictionary_scalar(stefan_case, "0/T", "boundaryField/hotWall/value")

    diffusivity = kappa / (rho * cp)
    lam = neumann_lambda(cp * (t_wall - t_melt) / latent, cp * (t_melt - t_initial) / latent, 1.0)

    for time in ("1", "2"):
        exact = 2 * lam * math.sqrt(diffusivity * float(time))
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
