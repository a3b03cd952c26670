"""Bad input stops with an OpenFOAM FatalIOError naming the entry and range.

Each case changes one entry of a valid small case (the 1D melting bar with
the enthalpy-porosity effect listed) and runs ldnaFoam: the run must stop
with a non-zero exit, a FOAM FATAL IO ERROR, the entry's name and the
allowed range, and no crash.  The unchanged case must run.
"""
from __future__ import annotations

import pytest

from solver_cases import PROJECT_DIR, assert_named_error
from ldna.case import Case


FV_OPTIONS = "constant/fvOptions"
THERMO = "constant/thermophysicalProperties"
FV_SOLUTION = "system/fvSolution"
FV_SCHEMES = "system/fvSchemes"
ALPHA_CONTROLS = 'solvers/"alpha.metal.*"'

#: The valid fvOptions: the example of enthalpyPorosity's header (its Usage),
#: so that the documented dictionary is the one that must run
ENTHALPY_POROSITY_HEADER = (PROJECT_DIR / "src" / "ldnaModels" / "enthalpyPorosity"
                            / "enthalpyPorosity.H")
VALID_FV_OPTIONS = (
    "FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n\n"
    + ENTHALPY_POROSITY_HEADER.read_text().split("\\verbatim\n", 1)[1]
    .split("\\endverbatim", 1)[0]
)

# (description, file, entry, new value or None to remove, expected texts)
BAD_INPUTS = [
    ("negative welding speed", FV_OPTIONS, "enthalpyPorosity/weldingSpeed", "constant -0.0075",
     ["weldingSpeed", "must lie in [0, 100)"]),
    ("zero mushy-zone constant", FV_OPTIONS, "enthalpyPorosity/mushyZoneConstant", "0",
     ["mushyZoneConstant", "must lie in (0, 1e+13]"]),
    ("porosity epsilon above 1", FV_OPTIONS, "enthalpyPorosity/porosityEpsilon", "2",
     ["porosityEpsilon", "(0, 1)"]),
    ("zero welding direction", FV_OPTIONS, "enthalpyPorosity/weldingDirection", "(0 0 0)",
     ["weldingDirection", "non-zero"]),
    ("unknown effect", FV_OPTIONS, "enthalpyPorosity/type", "laserBeem",
     ["laserBeem", "enthalpyPorosity"]),
    ("solidus above liquidus", THERMO, "metal/solidus", "1200",
     ["liquidus", "above the solidus", "must lie in (1200, "]),
    ("negative conductivity", THERMO, "metal/kappa/solid", "constant -5",
     ["kappa", "solid", "is -5", "must lie in (0, "]),
    ("negative latent heat", THERMO, "metal/latentHeat", "-1", ["latentHeat", "is -1", "must lie in [0, "]),
    ("zero gas constant", THERMO, "gas/R", "0", ["'R'", "is 0", "must lie in (0, "]),
    ("missing solidus", THERMO, "metal/solidus", None, ["solidus"]),
    ("unknown gas density model", THERMO, "gas/densityModel", "perfectGas",
     ["densityModel", "perfectGas", "Boussinesq", "idealGas"]),
    ("unknown metal density model", THERMO, "metal/densityModel", "incompressible",
     ["densityModel", "incompressible", "Boussinesq", "variable"]),
    ("zero gas reference temperature", THERMO, "gas",
     "{ R 208.13; densityModel Boussinesq; referenceTemperature 0; Cp constant 520.3; "
     "kappa constant 0.0177; mu constant 2.27e-5; }",
     ["referenceTemperature", "is 0", "must lie in (0, "]),
    ("surface tension negative below 3200 K", THERMO, "sigma",
     "{ type linear; sigma0 0.3; dSigmadT -4.3e-4; Tref 1950; }",
     ["surface tension", "3200", "must lie in (0, 100]"]),
    ("negative sulphur activity", THERMO, "sigma", "{ type sahooDebRoy; activity -0.01; }",
     ["activity", "must lie in [0, 100]"]),
    ("recondensation of 1", FV_OPTIONS, "evaporation",
     "{ type evaporation; model hertzKnudsen; boilingTemperature 3090; latentHeat 6.5e6; "
     "molarMass 0.05585; recondensation 1; }",
     ["recondensation", "[0, 1)"]),
    ("unknown evaporation model", FV_OPTIONS, "evaporation",
     "{ type evaporation; model boiling; boilingTemperature 3090; latentHeat 6.5e6; }",
     ["'model'", "is boiling", "must be one of (paper hertzKnudsen)"]),
    ("unknown laser profile", FV_OPTIONS, "laser",
     "{ type laserHeatSource; absorptionModel gaussianSurface; power constant 100; "
     "beamRadius 1e-3; position (0 0 0); profile flat; }",
     ["'profile'", "is flat", "must be one of (gaussian topHat)"]),
    ("explicit metal fraction", FV_SOLUTION, f"{ALPHA_CONTROLS}/MULESCorr", "no",
     ["MULESCorr", "semi-implicitly", "(MULESCorr yes) only"]),
    ("zero limiter sweeps", FV_SOLUTION, f"{ALPHA_CONTROLS}/nLimiterIter", "0",
     ["nLimiterIter", "is 0", "must lie in [1, 1000]"]),
    ("negative limiter tolerance", FV_SOLUTION, f"{ALPHA_CONTROLS}/limiterTolerance", "-1",
     ["limiterTolerance", "is -1", "must lie in [0, 1]"]),
    ("zero linear-solver tolerance", FV_SOLUTION, 'solvers/"(U|T)"/tolerance', "0",
     ["tolerance", "is 0", "must lie in (0, 1)"]),
    ("negative linear-solver tolerance", FV_SOLUTION, "solvers/p_rgh/tolerance", "-1",
     ["tolerance", "is -1", "must lie in (0, 1)"]),
    ("linear-solver tolerance of 1e300", FV_SOLUTION, 'solvers/"fillerFraction.*"/tolerance',
     "1e300", ["tolerance", "is 1e+300", "must lie in (0, 1)"]),
    ("relative tolerance of 1", FV_SOLUTION, "solvers/p_rgh/relTol", "1",
     ["relTol", "is 1", "must lie in [0, 1)"]),
    ("negative relative tolerance", FV_SOLUTION, 'solvers/"(U|T)"/relTol', "-0.1",
     ["relTol", "is -0.1", "must lie in [0, 1)"]),
    ("Crank-Nicolson metal fraction", FV_SCHEMES, "ddtSchemes/ddt(alpha)", "CrankNicolson 0.9",
     ["ddt(alpha) is CrankNicolson", "Euler only"]),
]


@pytest.fixture
def valid_case(stefan_case: Case) -> Case:
    """The meshed melting bar, short, with the enthalpy-porosity effect."""
    (stefan_case / FV_OPTIONS).write_text(VALID_FV_OPTIONS)
    control = stefan_case / "system" / "controlDict"
    stefan_case.set("system/controlDict", "endTime", "0.01")
    control.write_text(control.read_text() + '\nlibs ("libldnaModels.so");\n')
    return stefan_case


def test_valid_case_runs(valid_case: Case) -> None:
    result = valid_case.run("ldnaFoam", check=False)
    assert result.returncode == 0, result.output[-2000:]
    assert "End" in result.output


@pytest.mark.parametrize("description,file,entry,value,expected", BAD_INPUTS,
                         ids=[b[0] for b in BAD_INPUTS])
def test_bad_input_stops_with_named_error(valid_case: Case, description: str, file: str,
                                          entry: str, value: str | None,
                                          expected: list[str]) -> None:
    edit = "-remove" if value is None else f"-set '{value}'"
    valid_case.run(f"foamDictionary -entry '{entry}' {edit} {file}", log_name="foamDictionary")
    assert_named_error(valid_case, expected)
