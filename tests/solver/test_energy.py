"""Energy conservation through melting in a closed adiabatic box.

Metal (316L, lower half) under argon in a closed box with adiabatic walls is
heated by a fixed source of known power P in a band at its bottom until the
metal has melted through.  The change of the total enthalpy (sensible plus
latent, both phases) must equal P t.
"""
from __future__ import annotations

import shutil

import numpy as np
import pytest

from solver_cases import TEMPLATE
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
        case.set(props, "metal/densityModel", "variable")
    if density == "constant":
        case.set(props, "metal/densityModel", "variable")
        for phase in ("solid", "liquid"):
            case.set(props, f"metal/rho/{phase}", "constant 7500")

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


#: The literature data of docs/physics-data.md, typed here from their
#: sources (not read from the case): 316L (Kim, ANL-75-55, 1975) and the
#: AISI 1024 substrate (Incropera & DeWitt Table A.1 for the solid, liquid
#: iron of Assael et al. 2006/2017).  Each: solidus, liquidus [K], latent
#: heat [J/kg], Cp solid (polynomial in T), Cp liquid, density solid and
#: liquid (polynomials), conductivity solid ((T, k) table or polynomial)
#: and liquid (polynomial)
LITERATURE = {
    "metal": {
        "solidus": 1675.0, "liquidus": 1708.0, "latent": 2.68e5,
        "cp_solid": (459.29, 0.1329), "cp_liquid": (790.0,),
        "rho_solid": (8084.2, -0.42086, -3.8942e-5), "rho_liquid": (7432.7, 0.039338, -1.8007e-4),
        "k_solid": (9.248, 0.01571), "k_liquid": (12.41, 0.003279),
    },
    "substrate": {
        "solidus": 1760.0, "liquidus": 1785.0, "latent": 2.70e5,
        "cp_solid": (520.94, 0.15942), "cp_liquid": (820.0,),
        "rho_solid": (7950.0, -0.34), "rho_liquid": (8712.0, -0.926),
        "k_solid": ((200, 41.0), (300, 41.0), (400, 42.2), (600, 39.7), (800, 35.0),
                    (1000, 27.6), (1760, 33.0)),
        "k_liquid": (35.0,),
    },
}
#: Where the table is compared [K]: rows of it (every 5 K), solid and liquid
SOLID_TEMPERATURES = (300.0, 800.0, 1200.0, 1500.0)
LIQUID_TEMPERATURES = (1900.0, 2100.0, 2500.0)
#: The table's digits (writePrecision 6 of the function objects' tables)
DIGITS = 2e-6
#: The enthalpy's reference temperature [K] (metalGasMixture)
ENTHALPY_REFERENCE = 298.15


def polynomial(coefficients: tuple[float, ...], T: float) -> float:
    return sum(c * T**i for i, c in enumerate(coefficients))


def conductivity(data: tuple, T: float) -> float:
    """A polynomial, or linear in a (T, k) table."""
    if isinstance(data[0], tuple):
        return float(np.interp(T, *zip(*data)))
    return polynomial(data, T)


def cp_integral(coefficients: tuple[float, ...], T0: float, T1: float) -> float:
    return sum(c * (T1 ** (i + 1) - T0 ** (i + 1)) / (i + 1) for i, c in enumerate(coefficients))


@pytest.mark.parametrize("name", list(LITERATURE))
def test_metal_properties_are_the_literature_data(energy_box_case: Case, name: str) -> None:
    """The properties the solver evaluates (its table, postProcessing/
    metalGasMixture/<time>/<metal>.dat) are the literature's at solid and
    liquid temperatures: heat capacity, density, conductivity, and the
    enthalpy from 298.15 K, analytic below the solidus, rising by the
    liquid Cp above the liquidus, and by the latent heat plus a heat
    capacity between the two metals' across the melting range."""
    case = energy_box_case
    # The template's materials in full: the substrate's metal too
    properties = "constant/thermophysicalProperties"
    shutil.copy(TEMPLATE / properties, case / properties)
    (case / "0" / "fillerFraction").write_text(
        (case / "0" / "alpha.metal").read_text().replace("alpha.metal", "fillerFraction"))
    case.set("system/controlDict", "endTime", "1e-3")
    case.run("ldnaFoam")
    table = case.latest_table("metalGasMixture", name)
    data = LITERATURE[name]

    def at(column: str, T: float) -> float:
        row = np.nonzero(np.isclose(table["T"], T))[0]
        assert len(row) == 1, f"no table row at {T} K"
        return float(table[column][row[0]])

    def literature(T: float, phase: str) -> dict[str, float]:
        values = {
            "Cp": polynomial(data[f"cp_{phase}"], T),
            f"rho{phase.capitalize()}": polynomial(data[f"rho_{phase}"], T),
            "kappa": conductivity(data[f"k_{phase}"], T),
            "liquidFraction": 0.0 if phase == "solid" else 1.0,
        }
        if phase == "solid":
            values["enthalpy"] = cp_integral(data["cp_solid"], ENTHALPY_REFERENCE, T)
        return values

    for phase, temperatures in (("solid", SOLID_TEMPERATURES), ("liquid", LIQUID_TEMPERATURES)):
        for T in temperatures:
            for column, value in literature(T, phase).items():
                print(f"{name} {T:.0f} K {column}: table {at(column, T):.6g}, "
                      f"literature {value:.6g}")
                assert at(column, T) == pytest.approx(value, rel=DIGITS, abs=1e-9)
    low, high = LIQUID_TEMPERATURES[0], LIQUID_TEMPERATURES[-1]
    rise = at("enthalpy", high) - at("enthalpy", low)
    assert rise == pytest.approx(cp_integral(data["cp_liquid"], low, high), rel=DIGITS)
    # Solidus to liquidus: the latent heat, plus a heat capacity between the
    # solid's at the solidus and the liquid's over the melting range
    solid = cp_integral(data["cp_solid"], ENTHALPY_REFERENCE, data["solidus"])
    melt = (at("enthalpy", low) - cp_integral(data["cp_liquid"], data["liquidus"], low)
            - solid - data["latent"])
    span = data["liquidus"] - data["solidus"]
    bounds = sorted((polynomial(data["cp_solid"], data["solidus"]) * span,
                     polynomial(data["cp_liquid"], data["liquidus"]) * span))
    print(f"{name}: sensible heat across the melting range {melt:.1f} J/kg, bounds {bounds}")
    assert bounds[0] * (1 - DIGITS) - 1 <= melt <= bounds[1] * (1 + DIGITS) + 1
