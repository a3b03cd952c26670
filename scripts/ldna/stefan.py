"""The two-phase Stefan problem of ``cases/stefanMelting`` and its Neumann solution.

A bar of metal at Ti below the melting point is heated from x = 0 held at
Tw above it.  The melting front advances as s(t) = 2 lambda sqrt(alpha_l t)
where lambda solves the Stefan condition (Carslaw & Jaeger, 1959, 11.2):

    lambda = St_l e^{-lambda^2} / (sqrt(pi) erf(lambda))
           - St_s sqrt(alpha_s/alpha_l) e^{-lambda^2 alpha_l/alpha_s}
             / (sqrt(pi) erfc(lambda sqrt(alpha_l/alpha_s)))

with St = cp dT / L.  The front of a simulation is where the liquid fraction
crosses 0.5 (the melting point of the case's 2 K mushy range).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .case import Case


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


@dataclass(frozen=True)
class NeumannSolution:
    """The exact melting front of a Stefan case."""

    lam: float
    diffusivity: float

    @classmethod
    def from_case(cls, case: Path) -> "NeumannSolution":
        """Material and boundary data as the case states them."""
        props = "constant/thermophysicalProperties"
        t_melt = 0.5 * (Case(case).scalar(props, "metal/solidus")
                        + Case(case).scalar(props, "metal/liquidus"))
        latent = Case(case).scalar(props, "metal/latentHeat")
        rho = Case(case).scalar(props, "metal/rho/solid")
        cp = Case(case).scalar(props, "metal/Cp/solid")
        kappa = Case(case).scalar(props, "metal/kappa/solid")
        for phase in ("rho", "Cp", "kappa"):
            if Case(case).value(props, f"metal/{phase}/liquid") != \
                    Case(case).value(props, f"metal/{phase}/solid"):
                raise ValueError(f"{case}: the Neumann solution used here needs equal solid "
                                 f"and liquid {phase}")
        t_initial = Case(case).scalar("0/T", "internalField")
        t_wall = Case(case).scalar("0/T", "boundaryField/hotWall/value")
        lam = neumann_lambda(cp * (t_wall - t_melt) / latent,
                             cp * (t_melt - t_initial) / latent, 1.0)
        return cls(lam=lam, diffusivity=kappa / (rho * cp))

    def front(self, time: float) -> float:
        """Exact front position [m] at ``time`` [s]."""
        return 2 * self.lam * math.sqrt(self.diffusivity * time)


def front_position(case: Path, time: str) -> float:
    """x where the liquid fraction first falls through 0.5 (linear interpolation).

    Writes the cell centres of ``time`` with ``postProcess`` if they are missing.
    """
    case = Path(case)
    if not (case / time / "Cx").exists():
        Case(case).run(f"postProcess -func writeCellCentres -time '{time}'",
                       log_name="writeCellCentres")
    liquid = Case(case).field("liquidFraction", time)
    x = Case(case).field("Cx", time)
    i = int(np.argmax(liquid < 0.5))
    if i == 0:
        raise ValueError(f"{case}/{time}: no melting front inside the bar")
    return float(x[i - 1] + (0.5 - liquid[i - 1]) * (x[i] - x[i - 1])
                 / (liquid[i] - liquid[i - 1]))
