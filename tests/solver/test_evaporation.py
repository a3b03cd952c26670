"""Evaporation of a flat metal surface held above the boiling point.

The laser slab (8 x 8 mm of 316L surface, 0.25 mm cells, no gravity) starts
at a uniform temperature above the boiling point and runs one time step, so
that the rates follow from that temperature alone; the tests compare the
logged rates with the models' formulas, the metal mass the solver reports
with the evaporated mass, and the enthalpy change with the mass times the
vapour's enthalpy.  A last test drives the surface to 4000 K with
evaporation, recoil pressure and Marangoni flow and checks that the run
stays bounded.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from ldna.balance import evaporation_table
from ldna.case import Case
from ldna.material import Metal

#: Evaporation data of iron (docs/physics-data.md): boiling point at 1 atm,
#: latent heat, molar mass; recondensation share of the Hertz-Knudsen flux
BOILING_TEMPERATURE = 3090.0
LATENT_HEAT = 6.5e6
MOLAR_MASS = 0.05585
BOILING_PRESSURE = 101325.0
RECONDENSATION = 0.18
#: Anisimov's recoil pressure over the saturation pressure
RECOIL_FACTOR = 0.54
GAS_CONSTANT = 8.314462618
#: Surface temperature of the rate tests [K] and the slab's surface [m2]
SURFACE_TEMPERATURE = 3500.0
SURFACE_AREA = 8e-3 * 8e-3

#: Allowed relative error of the evaporation rate
RATE_TOLERANCE = 0.02

def evaporation_entry(model: str, extra: str = "") -> str:
    """An fvOptions entry of the evaporation model with iron's data."""
    hertz_knudsen = (f"molarMass {MOLAR_MASS}; boilingPressure {BOILING_PRESSURE}; "
                     f"recondensation {RECONDENSATION};" if model == "hertzKnudsen" else "")
    return f"""
evaporation
{{
    type                evaporation;
    model               {model};
    boilingTemperature  {BOILING_TEMPERATURE};
    latentHeat          {LATENT_HEAT};
    {hertz_knudsen}
    {extra}
}}
"""


def write_fv_options(case: Case, entries: str) -> None:
    """Replace the case's fvOptions by ``entries``."""
    header = (case / "constant" / "fvOptions").read_text().split("// The test writes")[0]
    (case / "constant" / "fvOptions").write_text(header + entries + "\n")


def saturation_pressure(temperature: float) -> float:
    """Clausius-Clapeyron from the boiling point [Pa]."""
    return BOILING_PRESSURE * math.exp(
        LATENT_HEAT * MOLAR_MASS / GAS_CONSTANT * (1 / BOILING_TEMPERATURE - 1 / temperature))


def run_one_hot_step(case: Case, entries: str) -> tuple[np.ndarray, tuple[float, ...]]:
    """Run one step from a uniform SURFACE_TEMPERATURE; the balances and evaporation's last row."""
    case.set("0/T", "internalField", f"uniform {SURFACE_TEMPERATURE}")
    write_fv_options(case, entries)
    case.run("ldnaFoam")
    return case.balances(), tuple(evaporation_table(case)[-1])[1:]


def check_rate_mass_and_vapour(balances: np.ndarray, rate: float, expected: float,
                               latent: float, vapour_enthalpy: float) -> None:
    """The logged rate against the expected one; the metal lost, the latent heat and the
    enthalpy lost in the step against that rate, the vapour leaving with vapour_enthalpy [J/kg]."""
    dt = balances["time"][-1] - balances["time"][0]
    lost = balances["metal_mass"][0] - balances["metal_mass"][-1]
    print(f"mass rate {rate:.6e} kg/s, expected {expected:.6e} kg/s; metal lost "
          f"{lost:.6e} kg, rate x dt {rate * dt:.6e} kg")
    assert abs(rate - expected) / expected < RATE_TOLERANCE
    assert abs(lost - rate * dt) / (rate * dt) < RATE_TOLERANCE
    assert latent == pytest.approx(rate * LATENT_HEAT, rel=1e-9)

    energy_lost = balances["enthalpy"][0] - balances["enthalpy"][-1]
    vapour = lost * vapour_enthalpy
    print(f"enthalpy lost {energy_lost:.5f} J, vapour enthalpy {vapour:.5f} J")
    assert abs(energy_lost - vapour) / vapour < RATE_TOLERANCE


def test_hertz_knudsen_rate_heat_and_recoil(laser_slab_case: Case) -> None:
    case = laser_slab_case
    balances, (rate, evaporated, latent, sink, *recoil) = run_one_hot_step(
        case, evaporation_entry("hertzKnudsen", "recoilPressure yes;"))

    p_sat = saturation_pressure(SURFACE_TEMPERATURE)
    flux = (1 - RECONDENSATION) * p_sat * math.sqrt(
        MOLAR_MASS / (2 * math.pi * GAS_CONSTANT * SURFACE_TEMPERATURE))
    assert sink == pytest.approx(rate * LATENT_HEAT, rel=1e-9)
    # The vapour leaves at the surface temperature with the latent heat
    metal = Metal.from_case(case)
    check_rate_mass_and_vapour(balances, rate, flux * SURFACE_AREA, latent,
                               metal.enthalpy(SURFACE_TEMPERATURE) + LATENT_HEAT)

    # Recoil 0.54 p_sat on the surface, pushing down into the metal: the
    # logged force, and the pressure step it makes across the surface
    expected_recoil = RECOIL_FACTOR * p_sat * SURFACE_AREA
    print(f"recoil force {recoil[2]:.5f} N, 0.54 p_sat A = {expected_recoil:.5f} N")
    assert abs(-recoil[2] - expected_recoil) / expected_recoil < RATE_TOLERANCE
    last = case.times[-1]
    p = case.field("p_rgh", last)
    alpha = case.field("alpha.metal", last)
    step = p[alpha > 1 - 1e-6].mean() - p[alpha < 1e-6].mean()
    print(f"pressure step across the surface {step:.1f} Pa, 0.54 p_sat = "
          f"{RECOIL_FACTOR * p_sat:.1f} Pa")
    assert abs(step - RECOIL_FACTOR * p_sat) / (RECOIL_FACTOR * p_sat) < RATE_TOLERANCE


def test_recoil_pressure_step_on_processor_faces(laser_slab_case: Case) -> None:
    """The recoil joins the capillary face force on processor faces too.

    The box is cut at the slab surface z = 2 mm, so that every surface face
    is a processor face; the pressure step across the evaporating surface
    must still be 0.54 p_sat.
    """
    case = laser_slab_case
    case.set("0/T", "internalField", f"uniform {SURFACE_TEMPERATURE}")
    write_fv_options(case, evaporation_entry("hertzKnudsen", "recoilPressure yes;"))
    case.set("system/decomposeParDict", "coeffs/n", "(1 1 2)")
    case.run("decomposePar")
    case.run("ldnaFoam", n_procs=2)
    case.run("reconstructPar -latestTime")

    last = case.times[-1]
    p = case.field("p_rgh", last)
    alpha = case.field("alpha.metal", last)
    expected = RECOIL_FACTOR * saturation_pressure(SURFACE_TEMPERATURE)
    steps = p[alpha > 1 - 1e-6].max() - p[alpha < 1e-6].min(), \
        p[alpha > 1 - 1e-6].min() - p[alpha < 1e-6].max()
    print(f"pressure step across the surface {steps[1]:.1f} .. {steps[0]:.1f} Pa, "
          f"0.54 p_sat = {expected:.1f} Pa")
    for step in steps:
        assert abs(step - expected) / expected < RATE_TOLERANCE


def test_paper_model_rate_and_boiling_point(laser_slab_case: Case) -> None:
    """Eq. 38-40: the superheat evaporates w_e of the metal; the rest is left at T_b."""
    case = laser_slab_case
    balances, (rate, evaporated, latent, sink, *_) = run_one_hot_step(
        case, evaporation_entry("paper"))

    metal = Metal.from_case(case)
    share = (metal.sensible_enthalpy(SURFACE_TEMPERATURE)
             - metal.sensible_enthalpy(BOILING_TEMPERATURE)) / LATENT_HEAT
    dt = balances["time"][-1] - balances["time"][0]
    print(f"w_e {share:.5f} (eq. 39)")
    # The vapour leaves at the boiling point with the latent heat
    check_rate_mass_and_vapour(balances, rate, share * balances["metal_mass"][0] / dt, latent,
                               metal.enthalpy(BOILING_TEMPERATURE) + LATENT_HEAT)

    last = case.times[-1]
    temperature = case.field("T", last)
    alpha = case.field("alpha.metal", last)
    metal_cells = alpha > 0.5
    print(f"metal after the step: {temperature[metal_cells].min():.4f} .. "
          f"{temperature[metal_cells].max():.4f} K")
    assert np.abs(temperature[metal_cells] - BOILING_TEMPERATURE).max() < 0.1


def test_surface_at_4000_k_stays_bounded(laser_slab_case: Case) -> None:
    """Hertz-Knudsen with recoil, Marangoni with the sulphur sigma(T), a 4000 K surface."""
    case = laser_slab_case
    hot = 4000.0
    case.set("system/controlDict", "endTime", "2e-3")
    case.set("system/controlDict", "adjustTimeStep", "yes")
    case.set("system/controlDict", "writeInterval", "1000")
    # The top 0.5 mm of the slab at 4000 K over a 2000 K liquid
    case.set("0/T", "internalField", "uniform 2000")
    case.run("setFields")
    (case / "system" / "setFieldsDict.hot").write_text(
        (case / "system" / "setFieldsDict").read_text().replace(
            "defaultFieldValues (volScalarFieldValue alpha.metal 0);",
            "defaultFieldValues ();").replace(
            "box (-1 -1 -1) (1 1 0.002);", "box (-1 -1 0.0015) (1 1 0.002);").replace(
            "volScalarFieldValue alpha.metal 1", f"volScalarFieldValue T {hot}"))
    case.run("setFields -dict system/setFieldsDict.hot", log_name="setFields.hot")
    properties = case / "constant" / "thermophysicalProperties"
    text = properties.read_text()
    text, count = re.subn(r"^sigma\s*(\{[^}]*\}|[^;{]+;)",
                          "sigma { type sahooDebRoy; activity 0.03; }", text, flags=re.M)
    assert count == 1, "the template's sigma entry changed: update this test"
    properties.write_text(text)
    write_fv_options(case, evaporation_entry("hertzKnudsen", "recoilPressure yes;") + """
marangoni
{
    type marangoniForce;
}
""")
    case.run("ldnaFoam")

    low, high = case.alpha_bounds()
    balances = case.balances()
    last = case.times[-1]
    temperature = case.field("T", last)
    print(f"{len(balances)} steps to t = {balances['time'][-1]:.4g} s: alpha within "
          f"[{low:.3e}, {high:.9f}], T within [{balances['T_min'].min():.1f}, "
          f"{balances['T_max'].max():.1f}] K, evaporated "
          f"{evaporation_table(case)['evaporatedMass'][-1]:.4e} kg")
    # Ran to the end time: OpenFOAM ends a run when less than half a step is left
    last_step = balances["time"][-1] - balances["time"][-2]
    assert balances["time"][-1] >= 2e-3 - 0.5 * last_step
    assert low > -1e-6 and high < 1 + 1e-6
    assert np.all(np.isfinite(temperature))
    assert balances["T_min"].min() > 200 and balances["T_max"].max() <= hot + 1e-6
