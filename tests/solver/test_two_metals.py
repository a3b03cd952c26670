"""Two metals: the substrate's own metal under the filler, and the filler
fraction the metal carries.

With a ``substrate`` dictionary in constant/thermophysicalProperties the
metal of a cell is a mixture of the filler (droplets, fillerFraction 1) and
the base metal (substrate, 0), and its properties follow the mixture
(metalComposition).  Checked against quantities computed here:

- heat conduction through the two metals: a bar of base metal under filler,
  each with its own constant conductivity, held at 400 K below and 1200 K
  above, reaches the steady composite-wall solution (the interface at
  (k_b T_b/L_b + k_f T_t/L_f)/(k_b/L_b + k_f/L_f), linear on either side)
  within 0.01 K;
- the filler is conserved and bounded: droplets of filler fall into a box
  onto a layer of base metal; the filler's mass in the box differs from
  the droplets' and the base metal's from the layer's by no more than the
  metal's own mass differs from layer plus droplets (5e-6 of the droplets'
  mass), the filler fraction stays in [0, 1] with no clipping beyond
  round-off, and the box's enthalpy grows by the droplets' mass times the
  filler's enthalpy at their temperature within 1 %;
- bad input of the second metal is a named FatalIOError.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from solver_cases import CRASHES, TEMPLATE, assert_named_error, prepare_test_case
from ldna.balance import wire_table
from ldna.case import Case
from ldna.material import Metal

THERMO = "constant/thermophysicalProperties"
#: Conductivities of the bar's two metals [W/m/K] and its ends [K]
K_FILLER = 15.0
K_BASE = 45.0
T_BOTTOM = 400.0
T_TOP = 1200.0
BAR_LENGTH = 10e-3
#: The steady profile after about 20 diffusion times is exact to far below this [K]
STEADY_TOLERANCE = 0.01
#: Cells of the bar (blockMeshDict) and its run [s] (controlDict)
BAR_CELLS = 40
BAR_RUN_TIME = 60.0
#: The metal's own mass budget in the droplet box (test_droplets: 1 %)
METAL_BUDGET = 0.01
#: Round-off of sums over the cells
ROUND_OFF = 1e-9
#: A cell the droplets filled holds filler only, but for what mixed in
PURE_FILLER = 0.99
#: The enthalpy of the droplet box against the droplets' (as test_droplets)
ENERGY_TOLERANCE = 0.01
#: dropletSource's default droplet temperature [K]
DEFAULT_DROPLET_TEMPERATURE = 2100.0


def with_two_metals(case: Case) -> None:
    """The template's thermophysicalProperties in full: 316L filler, AISI 1024 substrate."""
    (case / "constant").mkdir(exist_ok=True)
    (case / THERMO).write_text((TEMPLATE / THERMO).read_text())


@pytest.fixture
def composite_bar(tmp_path: Path) -> Case:
    case = prepare_test_case("compositeBar", tmp_path, material_from_template=False)
    with_two_metals(case)
    for metal, k in (("metal", K_FILLER), ("substrate", K_BASE)):
        case.run(f"foamDictionary -entry {metal}/kappa "
                 f"-set '{{ solid constant {k}; liquid constant {k}; }}' {THERMO}",
                 log_name="foamDictionary")
    case.run("blockMesh")
    case.run("setFields")
    return case


def test_heat_flows_through_the_two_metals_as_through_a_composite_wall(
        composite_bar: Case) -> None:
    case = composite_bar
    case.run("ldnaFoam")
    case.run("postProcess -func writeCellCentres -latestTime", log_name="writeCellCentres")
    z = case.field("C")[:, 2]
    T = case.field("T")
    half = BAR_LENGTH / 2
    interface = ((K_BASE * T_BOTTOM / half + K_FILLER * T_TOP / half)
                 / (K_BASE / half + K_FILLER / half))
    exact = np.where(z < half, T_BOTTOM + (interface - T_BOTTOM) * z / half,
                     interface + (T_TOP - interface) * (z - half) / half)
    error = np.abs(T - exact).max()
    print(f"interface {interface:.3f} K; largest error {error:.2e} K")
    assert error < STEADY_TOLERANCE
    # Nothing moves but the pressure solution's residual flow: the
    # composition is what it was
    change = np.abs(case.field("fillerFraction") - np.where(z < half, 0.0, 1.0)).max()
    # The residual flow of the pressure solution (about 1e-9 m/s) moves the
    # metal at most its speed times the run's time: upwind transport cannot
    # change a cell's composition by more than that share of the cell
    speed = np.abs(case.field("U")).max()
    drift = speed * BAR_RUN_TIME / (BAR_LENGTH / BAR_CELLS)
    print(f"largest change of the filler fraction {change:.2e} (flow {speed:.1e} m/s: "
          f"{drift:.1e} of a cell)")
    assert change <= drift


@pytest.fixture
def droplets_on_base_metal(tmp_path: Path) -> Case:
    """The closed box of argon under two wires, with 3 mm of base metal at its bottom."""
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=False)
    with_two_metals(case)
    (case / "0" / "fillerFraction").write_text(
        (case / "0" / "alpha.metal").read_text().replace("alpha.metal", "fillerFraction"))
    (case / "system" / "setFieldsDict").write_text("""FoamFile
{ version 2.0; format ascii; class dictionary; object setFieldsDict; }
defaultFieldValues ( volScalarFieldValue alpha.metal 0 volScalarFieldValue fillerFraction 0 );
regions ( boxToCell { box (-1 -1 -1) (1 1 0.003); fieldValues ( volScalarFieldValue alpha.metal 1 ); } );
""")
    case.run("blockMesh")
    case.run("setFields")
    return case


def test_the_filler_is_conserved_and_bounded(droplets_on_base_metal: Case) -> None:
    case = droplets_on_base_metal
    case.run("ldnaFoam")
    balances = case.balances()
    filler = case.latest_table("balances", "filler")
    filler_metal = Metal.from_case(case.path)
    wires = wire_table(case)
    added_mass = sum(values[-1, 0] for values in wires.values())
    assert added_mass > 0

    # The droplets are filler, the layer base metal: each is conserved as
    # well as the metal is (its own budget in this box: the metal gained
    # against the droplets' mass; 5e-6 of it when measured)
    filler_mass = float(filler["fillerVolume"][-1]) * filler_metal.reference_density
    start = float(balances["metal_mass"][0])
    end = float(balances["metal_mass"][-1])
    metal_error = abs(end - start - added_mass)
    filler_error = abs(filler_mass - added_mass)
    base_error = abs(end - filler_mass - start)
    clipped = float(np.abs(filler["clippedVolume"]).max()) * filler_metal.reference_density
    print(f"droplets {added_mass:.9e} kg: metal gained {end - start:.9e}, filler "
          f"{filler_mass:.9e}; base metal {start:.9e} -> {end - filler_mass:.9e} kg; "
          f"clipped {clipped:.2e} kg")
    assert metal_error <= METAL_BUDGET * added_mass
    assert filler_error <= metal_error
    assert base_error <= metal_error
    assert clipped <= ROUND_OFF * added_mass
    assert filler["fillerMin"].min() >= 0 and filler["fillerMax"].max() <= 1
    # The layer was base metal and the droplets reached it pure
    base = Metal.from_case(case.path, "substrate")
    assert start == pytest.approx(base.reference_density * 10e-3 * 8e-3 * 3e-3, rel=ROUND_OFF)
    assert filler["fillerMax"][-1] > PURE_FILLER

    # The closed adiabatic box gains the droplets' enthalpy
    added_enthalpy = 0.0
    for wire, values in wires.items():
        try:
            temperature = case.scalar("constant/fvOptions",
                                      f"wireDroplets/wires/{wire}/temperature")
        except KeyError:
            temperature = DEFAULT_DROPLET_TEMPERATURE
        added_enthalpy += values[-1, 0] * filler_metal.enthalpy(temperature)
    gained = float(balances["enthalpy"][-1] - balances["enthalpy"][0])
    print(f"enthalpy gained {gained:.4f} J, droplets {added_enthalpy:.4f} J")
    assert gained == pytest.approx(added_enthalpy, rel=ENERGY_TOLERANCE)


BAD_SECOND_METAL = [
    ("liquidus below the solidus", "substrate/liquidus", "1700",
     ["liquidus", "above the solidus", "must lie in (1760, "]),
    ("negative conductivity", "substrate/kappa/solid", "constant -5",
     ["kappa", "solid", "is -5", "must lie in (0, "]),
    ("missing heat capacity", "substrate/Cp", None, ["Cp", "substrate"]),
    ("unknown entry", "substrate/emisivity", "0.8", ["emisivity"]),
]


@pytest.mark.parametrize("description,entry,value,expected", BAD_SECOND_METAL,
                         ids=[b[0] for b in BAD_SECOND_METAL])
def test_bad_second_metal_stops_with_named_error(composite_bar: Case, description: str,
                                                 entry: str, value: str | None,
                                                 expected: list[str]) -> None:
    edit = "-remove" if value is None else f"-set '{value}'"
    composite_bar.run(f"foamDictionary -entry '{entry}' {edit} {THERMO}",
                      log_name="foamDictionary")
    assert_named_error(composite_bar, expected)


def test_a_mapped_filler_fractions_round_off_is_clipped(composite_bar: Case) -> None:
    """A start mapped volume-weighted onto a mesh that does not nest in its
    source's leaves fractions 1 + 2e-16 (measured: 156 cells of the band's
    level 0.5 from the saved weld); those within 1e-12 of [0, 1] are set to
    the bound and the run goes on."""
    z = np.linspace(0, 1, BAR_CELLS)
    composite_bar.write_field("fillerFraction",
                              values=np.where(z > 0.5, 1 + 1e-13, -1e-13))
    composite_bar.set("system/controlDict", "endTime",
                      composite_bar.value("system/controlDict", "deltaT"))
    composite_bar.run("ldnaFoam")
    log = (composite_bar / "log.ldnaFoam").read_text()
    assert f"{BAR_CELLS} values within 1e-12 of [0, 1] set to its bounds" in log
    filler = composite_bar.field("fillerFraction")
    assert filler.min() >= 0 and filler.max() <= 1


@pytest.mark.parametrize("value,expected", [
    ("1.5", ["fillerFraction", "1.5", "must lie in [0, 1]"]),
    ("-0.2", ["fillerFraction", "-0.2", "must lie in [0, 1]"]),
    # Beyond a volume-weighted mapping's round-off (1e-12)
    ("1.000001", ["fillerFraction", "1.000001", "must lie in [0, 1]"]),
    # OpenFOAM's reader refuses it first, naming the file and the token
    ("nan", ["fillerFraction", "nan"]),
])
def test_a_filler_fraction_outside_0_1_is_refused(composite_bar: Case, value: str,
                                                  expected: list[str]) -> None:
    z = np.linspace(0, 1, BAR_CELLS)
    composite_bar.write_field("fillerFraction", values=np.where(z > 0.5, float(value), 0.0))
    # The refused value itself may be "nan"
    assert_named_error(composite_bar, expected,
                       crashes=tuple(c for c in CRASHES if c != "nan"))

