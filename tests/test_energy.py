"""Energy conservation through melting in a closed adiabatic box.

Metal (316L, lower half) under argon in a closed box with adiabatic walls is
heated by a fixed source of known power P in a band at its bottom until the
metal has melted through.  The change of the total enthalpy (sensible plus
latent, both phases) must equal P t.
"""
from __future__ import annotations

import numpy as np
import pytest

from ldna.case import Case


#: Allowed relative error of the enthalpy balance (required: 0.5 %)
ENERGY_TOLERANCE = 0.005
#: Allowed excursion of the metal fraction outside [0, 1]
ALPHA_BOUND_TOLERANCE = 1e-6


@pytest.mark.parametrize("density", ["Boussinesq", "variable", "constant"])
def test_enthalpy_change_equals_heat_input(energy_box_case: Case, density: str) -> None:
    case = energy_box_case
    props = case / "constant" / "thermophysicalProperties"
    if density == "variable":
        case.run(f"foamDictionary -entry metal/densityModel -set variable {props}",
                 log_name="foamDictionary.densityModel")
    if density == "constant":
        case.run(f"foamDictionary -entry metal/densityModel -set variable {props}",
                 log_name="foamDictionary.densityModel")
        for phase in ("solid", "liquid"):
            case.run(f"foamDictionary -entry metal/rho/{phase} -set 'constant 7500' {props}",
                     log_name=f"foamDictionary.{phase}")

    case.run("ldnaFoam")

    power = float(case.value("constant/fvOptions",
                             "heater/injectionRateSuSp/T").strip("()").split()[0])
    balances = case.balances()
    start, end = balances[0], balances[-1]
    heat_in = power * (end["time"] - start["time"])
    change = end["enthalpy"] - start["enthalpy"]
    error = abs(change - heat_in) / heat_in
    print(f"{density} density: enthalpy change {change:.4f} J, heat input {heat_in:.4f} J, "
          f"error {100 * error:.4f} %")
    assert error < ENERGY_TOLERANCE

    # The metal has really gone through melting: half-way a front separates
    # solid from liquid metal, at the end all metal is liquid ...
    def metal_liquid_fraction(time: str) -> np.ndarray:
        metal = case.field("alpha.metal", time) > 0.5
        liquid = np.broadcast_to(case.field("liquidFraction", time), metal.shape)
        return liquid[metal]

    half_way = metal_liquid_fraction("0.6")
    assert half_way.max() > 0.99 and half_way.min() < 0.01
    assert metal_liquid_fraction("1.2").min() > 0.99
    # ... no cell of a heated adiabatic box cools below the start temperature
    assert balances["T_min"].min() >= start["T_min"] - 1e-6 * start["T_min"]
    # ... and the metal fraction stays bounded
    low, high = case.alpha_bounds()
    assert low > -ALPHA_BOUND_TOLERANCE and high < 1 + ALPHA_BOUND_TOLERANCE


#: The solver's enthalpy against the integral of its own Cp, relative to the
#: enthalpy's range: the table's 12 digits and the property tables' 1e-9 leave
#: far less; a missing mushy-range term would be 2 % (33 K of Cp ~ 700 J/kg/K
#: against 1.2 MJ/kg)
TABLE_TOLERANCE = 1e-6


def test_metal_property_table_is_consistent(energy_box_case: Case) -> None:
    """The metal table the solver writes (postProcessing/metalGasMixture):
    its sensible enthalpy is the integral of its Cp from 298.15 K, its
    liquid fraction rises linearly from solidus to liquidus, and its
    enthalpy adds the latent heat of that fraction.  Cp is piecewise linear
    for the template's 316L (linear solid, linear across the mushy range,
    constant liquid), with its kinks on table rows, so the trapezoidal
    integral is exact."""
    case = energy_box_case
    case.set("system/controlDict", "endTime", "1e-3")
    case.run("ldnaFoam")

    table = case.latest_table("metalGasMixture", "metal")
    T, cp, hs = table["T"], table["Cp"], table["sensibleEnthalpy"]
    integral = np.concatenate(([0.0], np.cumsum(0.5 * (cp[1:] + cp[:-1]) * np.diff(T))))
    reference = integral - np.interp(298.15, T, integral)
    scale = hs.max() - hs.min()
    error = np.abs(hs - reference).max() / scale
    print(f"sensible enthalpy against the integral of Cp: {error:.2e} of {scale:.4g} J/kg")
    assert error < TABLE_TOLERANCE

    props = "constant/thermophysicalProperties"
    solidus, liquidus = case.scalar(props, "metal/solidus"), case.scalar(props, "metal/liquidus")
    latent = case.scalar(props, "metal/latentHeat")
    expected_fraction = np.clip((T - solidus) / (liquidus - solidus), 0, 1)
    assert np.abs(table["liquidFraction"] - expected_fraction).max() < 1e-9
    assert np.abs(table["enthalpy"] - hs - latent * expected_fraction).max() < TABLE_TOLERANCE * scale
