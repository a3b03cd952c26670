"""The metal of an ldnaFoam case, as the solver evaluates it.

``metalGasMixture`` writes the metal's properties at equilibrium against the
temperature (every 5 K from 200 K to 10 000 K, the melting range on a finer
grid) to ``postProcessing/metalGasMixture/<startTime>/metal.dat`` when it
starts.  ``Metal`` interpolates in that table (within 0.4 J/kg of the
solver's enthalpy for 316L, see ``metalGasMixture::propertyTableStep``) and
reads the scalar entries (melting range, latent heat, density model) from
``constant/thermophysicalProperties``; it evaluates no property function of
its own.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from .case import Case

#: The solver's table of the metal's properties (postProcessing/<name>/*/<file>.dat)
PROPERTY_TABLE = ("metalGasMixture", "metal")
#: The dictionary (and table) of the substrate's own metal, with two metals
SUBSTRATE = "substrate"


def two_metals(case: Path | str) -> bool:
    """Whether the substrate has its own metal (a ``substrate`` dictionary)."""
    try:
        Case(case).value("constant/thermophysicalProperties", f"{SUBSTRATE}/solidus")
    except KeyError:
        return False
    return True


@dataclass(frozen=True)
class Metal:
    """The metal of a case: melting range, density model and property table."""

    case: Path
    solidus: float
    liquidus: float
    latent_heat: float
    #: "Boussinesq" or "variable" (metalGasMixture's densityModel)
    density_model: str
    #: Density of mass and inertia with the Boussinesq model [kg/m3]
    reference_density: float
    #: Its dictionary in thermophysicalProperties and its table's name
    name: str = "metal"

    @classmethod
    def from_case(cls, case: Path, name: str = "metal") -> "Metal":
        """The filler metal of ``case/constant/thermophysicalProperties``
        (``name`` "metal"), or the substrate's own (``name`` "substrate")."""
        def entry(key: str) -> str:
            return Case(case).value("constant/thermophysicalProperties", f"{name}/{key}")

        try:
            model = entry("densityModel")
        except KeyError:
            model = "Boussinesq"
        reference = float(entry("referenceDensity")) if model == "Boussinesq" else float("nan")
        return cls(case=Path(case), density_model=model, reference_density=reference,
                   solidus=float(entry("solidus")), liquidus=float(entry("liquidus")),
                   latent_heat=float(entry("latentHeat")), name=name)

    @classmethod
    def substrate_of(cls, case: Path) -> "Metal":
        """The substrate's metal: its own with two metals, else the filler."""
        return cls.from_case(case, SUBSTRATE if two_metals(case) else "metal")

    @cached_property
    def table(self) -> np.ndarray:
        """The solver's property table of its latest run (the solver must have started)."""
        return Case(self.case).latest_table(PROPERTY_TABLE[0], self.name)

    def _at(self, column: str, T: float) -> float:
        return float(np.interp(T, self.table["T"], self.table[column]))

    def liquid_fraction(self, T: float) -> float:
        """Equilibrium liquid fraction."""
        return self._at("liquidFraction", T)

    def sensible_enthalpy(self, T: float) -> float:
        """Sensible enthalpy [J/kg] from the solver's reference temperature."""
        return self._at("sensibleEnthalpy", T)

    def enthalpy(self, T: float) -> float:
        """Sensible plus latent enthalpy at equilibrium [J/kg]."""
        return self._at("enthalpy", T)

    def mass_density(self, T: float, liquid_fraction: float) -> float:
        """Density of mass and inertia: the reference (Boussinesq) or rho(T, gl)."""
        if self.density_model == "Boussinesq":
            return self.reference_density
        return self.density(T, liquid_fraction)

    def density(self, T: float, liquid_fraction: float) -> float:
        """rho(T, gl), linear in the liquid fraction between the solid and the liquid."""
        return ((1 - liquid_fraction) * self._at("rhoSolid", T)
                + liquid_fraction * self._at("rhoLiquid", T))
