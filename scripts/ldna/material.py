"""Metal properties of an ldnaFoam case, evaluated in Python.

An independent implementation of what ``metalGasMixture`` computes from
``constant/thermophysicalProperties`` (solid and liquid Function1s of T, a
mushy range with linear liquid fraction and linear Cp), used by the tests
to check the solver's balances and by post-processing.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .foamcase import dictionary_value

#: Reference temperature of the sensible enthalpies [K] (metalGasMixture::Tref)
T_REF = 298.15


@dataclass(frozen=True)
class Function1:
    """A scalar OpenFOAM Function1 of temperature: constant, polynomial or table."""

    kind: str
    data: tuple[tuple[float, float], ...]

    @classmethod
    def parse(cls, text: str) -> "Function1":
        """Parse ``constant 790``, ``polynomial ((a0 0) (a1 1))`` or ``table ((T v) ...)``."""
        text = " ".join(text.split())
        kind, _, rest = text.partition(" ")
        if kind == "constant":
            return cls("constant", ((float(rest), 0.0),))
        if kind not in ("polynomial", "table"):
            raise ValueError(f"unsupported Function1 '{text}'")
        pairs = re.findall(r"\(\s*(\S+)\s+(\S+)\s*\)", rest)
        return cls(kind, tuple((float(a), float(b)) for a, b in pairs))

    def value(self, x: float) -> float:
        """f(x)."""
        if self.kind == "constant":
            return self.data[0][0]
        if self.kind == "polynomial":
            return sum(c * x**e for c, e in self.data)
        xs, ys = zip(*self.data)
        return float(np.interp(x, xs, ys))

    def integral(self, x0: float, x1: float) -> float:
        """Integral of f from x0 to x1."""
        if self.kind == "constant":
            return self.data[0][0] * (x1 - x0)
        if self.kind == "polynomial":
            return sum(c * (x1 ** (e + 1) - x0 ** (e + 1)) / (e + 1) for c, e in self.data)
        xs = np.linspace(x0, x1, 2001)
        return float(np.trapz([self.value(x) for x in xs], xs))


@dataclass(frozen=True)
class Metal:
    """The metal of a case: solidus, liquidus, latent heat and property functions."""

    solidus: float
    liquidus: float
    latent_heat: float
    rho_solid: Function1
    rho_liquid: Function1
    #: "Boussinesq" or "variable" (metalGasMixture's densityModel)
    density_model: str
    #: Density of mass and inertia with the Boussinesq model [kg/m3]
    reference_density: float
    cp_solid: Function1
    cp_liquid: Function1

    @classmethod
    def from_case(cls, case: Path) -> "Metal":
        """Read the metal of ``case/constant/thermophysicalProperties``."""
        props = "constant/thermophysicalProperties"

        def entry(name: str) -> str:
            return dictionary_value(case, props, f"metal/{name}")

        try:
            model = entry("densityModel")
        except KeyError:
            model = "Boussinesq"
        reference = float(entry("referenceDensity")) if model == "Boussinesq" else float("nan")
        return cls(
            density_model=model,
            reference_density=reference,
            solidus=float(entry("solidus")),
            liquidus=float(entry("liquidus")),
            latent_heat=float(entry("latentHeat")),
            rho_solid=Function1.parse(entry("rho/solid")),
            rho_liquid=Function1.parse(entry("rho/liquid")),
            cp_solid=Function1.parse(entry("Cp/solid")),
            cp_liquid=Function1.parse(entry("Cp/liquid")),
        )

    def liquid_fraction(self, T: float) -> float:
        """Equilibrium liquid fraction, linear between solidus and liquidus."""
        return min(max((T - self.solidus) / (self.liquidus - self.solidus), 0.0), 1.0)

    def sensible_enthalpy(self, T: float) -> float:
        """Integral of Cp from T_REF; Cp is linear in T across the mushy range."""
        ts, tl = self.solidus, self.liquidus
        if T <= ts:
            return self.cp_solid.integral(T_REF, T)
        cps, cpl = self.cp_solid.value(ts), self.cp_liquid.value(tl)
        dt = min(T, tl) - ts
        h = self.cp_solid.integral(T_REF, ts) + cps * dt + 0.5 * (cpl - cps) * dt**2 / (tl - ts)
        return h if T < tl else h + self.cp_liquid.integral(tl, T)

    def enthalpy(self, T: float) -> float:
        """Sensible plus latent enthalpy at equilibrium [J/kg]."""
        return self.sensible_enthalpy(T) + self.liquid_fraction(T) * self.latent_heat

    def mass_density(self, T: float, liquid_fraction: float) -> float:
        """Density of mass and inertia: the reference (Boussinesq) or rho(T, gl)."""
        if self.density_model == "Boussinesq":
            return self.reference_density
        return self.density(T, liquid_fraction)

    def density(self, T: float, liquid_fraction: float) -> float:
        """rho(T, gl): the liquid fraction blends each phase's function on its range."""
        return ((1 - liquid_fraction) * self.rho_solid.value(min(T, self.solidus))
                + liquid_fraction * self.rho_liquid.value(max(T, self.liquidus)))
