"""Cost benchmarks of the LDNA template: ratios measured in one run on this machine.

Benchmarks, not tests: nothing is asserted, the figures are printed.  Each
copies ``cases/ldna`` (at a resolution level) into a scratch folder, meshes
it once and runs a fixed number of fixed-size time steps, so that every
variant does the same steps:

- ``laser_cost``: no laser and each laser absorption model, the template's
  other effects on;
- ``solver_costs`` (``ldna bench``): from a developed state of the
  template, ldnaFoam with no effects and with all against OpenFOAM's
  compressibleInterFoam on the same mesh, fields (the temperature
  included) and numerics, its limiter sweeping as often as it needs to
  keep the metal fraction as bounded as ldnaFoam does (and at OpenFOAM's
  default); the cost of each effect of the template alone over the
  no-effect step (and of its laser with Monte-Carlo rays), with whether
  the effect acted in the window (its own table says so); the throughput
  in cell-steps per second per core with the projected core-hours per
  simulated second at the paper's resolution; and the parallel efficiency
  of ``mpirun -np 2`` against a serial run, from wall time.  Every ratio is
  the median over rounds of the ratio within each round, with its spread.
"""
from __future__ import annotations

import contextlib
import math
import re
import shutil
import tempfile
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator

import numpy as np
from foamlib import FoamFieldFile

from ..case import Case
from ..case import PROJECT_DIR
from ..foamdict import block_names, keep_blocks, read_scalars, remove_blocks

TEMPLATE = PROJECT_DIR / "cases" / "ldna"

#: Laser of the benchmark: the paper's power range and oscillation, a 1 mm
#: beam on the substrate surface at mid-length (caseParameters geometry)
LASER_POWER = 1200.0
LASER_BEAM_RADIUS = 1e-3
LASER_MODELS = ("gaussianSurface", "beerLambert", "monteCarlo")
#: OpenFOAM's default MULES limiter sweeps (v1912 MULESTemplates.C:
#: nLimiterIter, default 3)
OPENFOAM_LIMITER_ITERATIONS = 3
#: Limiter sweeps tried for the reference, least first: the least whose
#: metal fraction stays as bounded as ldnaFoam's is the reference (v1912's
#: MULES always does all of them; ldnaFoam's limiter stops at the sweep
#: that changes no face)
REFERENCE_LIMITER_CANDIDATES = (3, 5, 10, 20, 50, 100)


@dataclass
class StepCost:
    """CPU time per step of one variant, and its ratio to the reference."""

    variant: str
    seconds_per_step: float
    ratio: float


def laser_entry(model: str, length_mm: float) -> str:
    """An fvOptions entry for the benchmark laser with ``model``."""
    return f"""
laser
{{
    type            laserHeatSource;
    absorptionModel {model};
    power           constant {LASER_POWER};
    beamRadius      {LASER_BEAM_RADIUS};
    position        ({0.5 * length_mm * 1e-3} 0 0);
    absorptivity    constant 0.36;
    log             false;
}}
"""


def laser_cost(level: int = 1, steps: int = 20, delta_t: float = 1e-4,
               work_dir: Path | None = None) -> list[StepCost]:
    """Time per step of the template with no laser and with each laser model.

    The template's other effects (droplets, Marangoni, evaporation, losses,
    porosity) stay on in every variant; its own laser is replaced by the
    benchmark laser; the ratios show what the laser adds.
    """
    scratch = Path(work_dir or tempfile.mkdtemp(prefix="ldna-bench-"))
    case = Case.copy_of(TEMPLATE, scratch / "ldna")
    case.set("system/caseParameters", "level", str(level))
    _fixed_steps(case, steps, delta_t)
    case.mesh()
    case.run("setFields")

    length = read_scalars(case / "system/caseParameters")["length"]
    remove_blocks(case / "constant/fvOptions", ["laser"])
    base_options = (case / "constant/fvOptions").read_text()
    costs: list[StepCost] = []
    for variant in ("none", *LASER_MODELS):
        options = base_options + ("" if variant == "none" else laser_entry(variant, length))
        (case / "constant/fvOptions").write_text(options)
        case.run(log_name=f"ldnaFoam.{variant}")
        costs.append(StepCost(variant, case.seconds_per_step(), 0.0))

    reference = costs[0].seconds_per_step
    for cost in costs:
        cost.ratio = cost.seconds_per_step / reference
    return costs


def print_costs(costs: list[StepCost], level: int) -> None:
    """Print the table of step costs."""
    print(f"LDNA template, level {level}: CPU time per step")
    print(f"{'laser':<16} {'s/step':>10} {'ratio':>8}")
    for cost in costs:
        print(f"{cost.variant:<16} {cost.seconds_per_step:>10.4f} {cost.ratio:>8.3f}")


#: The paper's configuration: about 690,000 cells with 0.15 mm at the free
#: surface (the template's level 3 has 665,000)
PAPER_CELLS = 690_000
#: Time step of the template's solution at a level, from its capillary limit
#: sqrt(rho dx^3 / (2 pi sigma)), which scales as dx^1.5 [s]
CAPILLARY_EXPONENT = 1.5

#: Argon's density for mass and inertia in the template: p/(R T) at its
#: initial pressure 1e5 Pa, R 208.13 J/kg/K and referenceTemperature 300 K
#: (constant/thermophysicalProperties, gas: Boussinesq).  The reference's
#: gas has it everywhere (rhoConst): as a perfect gas, the 1800 K its cells
#: take from the droplets' metal expands it into jets that raised the
#: Courant number from 0.9 to 29 in seven steps and ended the run with a
#: negative temperature (measured from the template's state at 0.02 s)
ARGON_DENSITY = 1e5 / (208.13 * 300)

#: The companion case of compressibleInterFoam: the template's metal and gas
#: as OpenFOAM thermophysical models (316L at its reference density, argon
#: at its reference density), its constant surface tension, laminar flow
COMPRESSIBLE_INTER_FOAM_FILES = {
    "constant/thermophysicalProperties": """FoamFile { version 2.0; format ascii;
    class dictionary; object thermophysicalProperties; }
phases (metal gas);
pMin 1e4;
sigma { type constant; sigma 1.8; }
""",
    "constant/thermophysicalProperties.metal": """FoamFile { version 2.0; format ascii;
    class dictionary; object thermophysicalProperties.metal; }
thermoType { type heRhoThermo; mixture pureMixture; transport const; thermo hConst;
    equationOfState rhoConst; specie specie; energy sensibleInternalEnergy; }
mixture { specie { molWeight 55.85; } equationOfState { rho 7950; }
    thermodynamics { Cp 500; Hf 0; } transport { mu 5e-3; Pr 0.15; } }
""",
    "constant/thermophysicalProperties.gas": """FoamFile { version 2.0; format ascii;
    class dictionary; object thermophysicalProperties.gas; }
thermoType { type heRhoThermo; mixture pureMixture; transport const; thermo hConst;
    equationOfState rhoConst; specie specie; energy sensibleInternalEnergy; }
mixture { specie { molWeight 39.948; } equationOfState { rho %.6g; }
    thermodynamics { Cp 520.3; Hf 0; } transport { mu 2.27e-5; Pr 0.667; } }
""" % ARGON_DENSITY,
    "constant/turbulenceProperties": """FoamFile { version 2.0; format ascii;
    class dictionary; object turbulenceProperties; }
simulationType laminar;
""",
}
#: Schemes compressibleInterFoam asks for beyond the template's
COMPRESSIBLE_INTER_FOAM_SCHEMES = {
    "divSchemes/div(rhoPhi,T)": "Gauss upwind",
    "divSchemes/div(rhoPhi,K)": "Gauss upwind",
    "divSchemes/div(phi,p)": "Gauss upwind",
    "divSchemes/div(((rho*nuEff)*dev2(T(grad(U)))))": "Gauss linear",
}


@dataclass
class SolverCosts:
    """What ``solver_costs`` measured (times per step [s]; ratios are medians
    over the rounds of each round's own ratio)."""

    level: int
    cells: int
    steps: int
    delta_t: float
    start_time: float
    #: Median CPU time per step: ldnaFoam without effects, the reference at
    #: the bounding limiter sweeps and at OpenFOAM's default, all effects
    ldna_no_effects: float
    compressible_inter_foam: float
    effects: list[StepCost]
    all_effects: float
    template_delta_t: float
    #: Wall time per step of the template serial and on ``n_procs`` ranks
    serial_all_effects: float
    parallel_all_effects: float
    n_procs: int
    repeats: int
    #: The reference's MULES limiter sweeps (bounding as ldnaFoam) and the
    #: reference at OpenFOAM's default sweeps
    reference_limiter_iterations: int = OPENFOAM_LIMITER_ITERATIONS
    default_reference: float = float("nan")
    #: Largest excursion of the metal fraction outside [0, 1] over the window:
    #: ldnaFoam's and the reference's at each sweep count tried
    ldna_alpha_excursion: float = 0.0
    reference_alpha_excursions: dict[int, float] = field(default_factory=dict)
    #: Whether each effect acted in the window, and what says so
    effect_active: dict[str, bool] = field(default_factory=dict)
    effect_evidence: dict[str, str] = field(default_factory=dict)
    #: Spread of each ratio over the rounds: (largest - least) / median
    spreads: dict[str, float] = field(default_factory=dict)
    #: Counted instructions (``instruction_steps`` > 0): per step of each
    #: serial variant over ``instruction_steps`` steps from
    #: ``instruction_start`` (the state before the window's first droplet
    #: insertion), the same in every run of a build on the same input
    instruction_steps: int = 0
    instruction_start: float = float("nan")
    instructions: dict[str, float] = field(default_factory=dict)

    @property
    def throughput(self) -> float:
        """Cell-steps per second per core of the full template (serial)."""
        return self.cells / self.all_effects

    def projected_core_hours(self, cells: int = PAPER_CELLS) -> float:
        """Core-hours per simulated second of the full template at ``cells``.

        Cost per step grows with the cells at this throughput; the step
        shrinks with the cell size as the capillary limit does (dx^1.5), the
        cell size falling as cells^(-1/3).
        """
        refinement = (cells / self.cells) ** (1 / 3)
        delta_t = self.template_delta_t / refinement ** CAPILLARY_EXPONENT
        return cells / self.throughput / delta_t / 3600

    def instruction_ratios(self) -> dict[str, float]:
        """Ratios of counted instructions per step: each effect against no
        effects, no effects and all effects against the reference (and all
        against the reference at its default sweeps)."""
        counts = self.instructions
        if not counts:
            return {}
        ratios = {cost.variant: counts[cost.variant] / counts["none"]
                  for cost in self.effects if cost.variant in counts}
        ratios["no_effects"] = counts["none"] / counts[REFERENCE_VARIANT]
        ratios["all_effects"] = counts["all"] / counts[REFERENCE_VARIANT]
        default = counts.get(DEFAULT_REFERENCE_VARIANT, counts[REFERENCE_VARIANT])
        ratios["all_effects_default_reference"] = counts["all"] / default
        return ratios

    @property
    def parallel_efficiency(self) -> float:
        """Serial wall time over (ranks x parallel wall time), per step."""
        return self.serial_all_effects / (self.n_procs * self.parallel_all_effects)

    def summary(self) -> dict[str, object]:
        """The figures as one JSON-ready object (``ldna bench --json``)."""
        return {
            "level": self.level,
            "cells": self.cells,
            "steps": self.steps,
            "delta_t_s": self.delta_t,
            "start_time_s": self.start_time,
            "repeats": self.repeats,
            "reference_limiter_iterations": self.reference_limiter_iterations,
            "reference_s_per_step": self.compressible_inter_foam,
            "default_limiter_iterations": OPENFOAM_LIMITER_ITERATIONS,
            "default_reference_s_per_step": self.default_reference,
            "ldna_alpha_excursion": self.ldna_alpha_excursion,
            "reference_alpha_excursions": {str(n): e for n, e in
                                           self.reference_alpha_excursions.items()},
            "no_effects_s_per_step": self.ldna_no_effects,
            "all_effects_s_per_step": self.all_effects,
            "no_effects_ratio": self.ldna_no_effects / self.compressible_inter_foam,
            "all_effects_ratio": self.all_effects / self.compressible_inter_foam,
            "all_effects_ratio_default_reference": self.all_effects / self.default_reference,
            "effect_ratios": {cost.variant: cost.ratio for cost in self.effects},
            "effect_active": dict(self.effect_active),
            "effect_evidence": dict(self.effect_evidence),
            "ratio_spreads": dict(self.spreads),
            f"np{self.n_procs}_efficiency": self.parallel_efficiency,
            "serial_wall_s_per_step": self.serial_all_effects,
            "parallel_wall_s_per_step": self.parallel_all_effects,
            "throughput_cell_steps_per_core_s": self.throughput,
            "template_delta_t_s": self.template_delta_t,
            "projected_core_hours_per_simulated_s": self.projected_core_hours(),
            "instruction_steps": self.instruction_steps,
            "instruction_start_s": self.instruction_start,
            "instructions_per_step": dict(self.instructions),
            "instruction_ratios": self.instruction_ratios(),
        }


def _fixed_steps(case: Case, steps: int, delta_t: float, start_time: float = 0.0) -> None:
    control = "system/controlDict"
    case.set(control, "adjustTimeStep", "no")
    case.set(control, "deltaT", f"{delta_t:.6g}")
    case.set(control, "startTime", f"{start_time:g}")
    case.set(control, "endTime", f"{start_time + steps * delta_t:.9g}")
    case.set(control, "startFrom", "startTime")
    # No write: every variant starts from the same initial fields
    case.set(control, "writeInterval", "1e3")


#: The only function object of the timed runs: the CPU time of each step
TIME_INFO_FUNCTIONS = """
functions
{
    timeInfo
    {
        type            timeInfo;
        libs            ("libutilityFunctionObjects.so");
        writeControl    timeStep;
        writeInterval   1;
    }
}
"""


def _only_time_info(case: Case) -> None:
    control = case / "system/controlDict"
    remove_blocks(control, ["functions"])
    control.write_text(control.read_text() + TIME_INFO_FUNCTIONS)


#: The name of the effect variant with the template's laser tracing
#: Monte-Carlo rays (the model's default, 10 000 a step)
MONTE_CARLO_VARIANT = "laserMonteCarlo"

#: The names of the reference variants: OpenFOAM's own solver at the
#: limiter sweeps that bound as ldnaFoam, and at OpenFOAM's default sweeps
REFERENCE_VARIANT = "compressibleInterFoam"
DEFAULT_REFERENCE_VARIANT = "compressibleInterFoamDefault"


def _monte_carlo_laser(options: str) -> str:
    """The fvOptions text with the Beer-Lambert laser's absorption model
    replaced by monteCarlo at its defaults (unchanged without one)."""
    text = re.sub(r"beerLambertCoeffs\s*\{[^}]*\}", "", options)
    return re.sub(r"(absorptionModel\s+)beerLambert\s*;", r"\1monteCarlo;", text)


def _compressible_inter_foam_case(scene: Case, destination: Path, start: Path,
                                  limiter_iterations: int) -> Case:
    """The scene's mesh, fields (at the ``start`` time directory, the
    temperature included) and numerics set up for compressibleInterFoam,
    with ``limiter_iterations`` MULES limiter sweeps."""
    case = Case.copy_of(scene, destination)
    shutil.copytree(scene / "constant/polyMesh", case / "constant/polyMesh")
    shutil.copytree(start, case / start.name)
    for name, text in COMPRESSIBLE_INTER_FOAM_FILES.items():
        (case / name).write_text(text)
    (case / "constant/fvOptions").unlink(missing_ok=True)
    for entry, value in COMPRESSIBLE_INTER_FOAM_SCHEMES.items():
        case.set("system/fvSchemes", entry, value, create=True)
    case.set("system/fvSolution", 'solvers/"alpha.metal.*"/nLimiterIter',
             str(limiter_iterations))
    case.set("system/controlDict", "application", "compressibleInterFoam")
    return case


#: The function object that records the metal fraction's range each step
#: (bound probes only: the timed runs have timeInfo alone)
ALPHA_RANGE_FUNCTION = ("{ type fieldMinMax; libs (\"libfieldFunctionObjects.so\"); "
                        "fields (alpha.metal); mode component; location no; "
                        "writeControl timeStep; writeInterval 1; }")


def _alpha_excursion_of_reference(case: Case) -> float:
    """Run ``case`` (compressibleInterFoam) once with the metal fraction's
    range recorded; its largest excursion outside [0, 1]."""
    control = case / "system/controlDict"
    timed = control.read_text()
    case.set("system/controlDict", "functions/alphaRange", ALPHA_RANGE_FUNCTION, create=True)
    try:
        case.run("compressibleInterFoam", log_name="compressibleInterFoam.bounds")
        table = case.latest_table("alphaRange", "fieldMinMax")
    finally:
        control.write_text(timed)
    lowest = min(float(table[c].min()) for c in table.dtype.names if c.startswith("min"))
    highest = max(float(table[c].max()) for c in table.dtype.names if c.startswith("max"))
    return max(0.0, -lowest, highest - 1.0)


@dataclass
class _Variant:
    """One timed run: the case, the solver, its ranks and, for ldnaFoam, the
    fvOptions it runs with."""

    case: Case
    command: str
    log_name: str
    n_procs: int = 1
    options: str | None = None

    def run(self) -> float:
        """Run once; the wall time [s] of the whole run."""
        if self.options is not None:
            (self.case / "constant/fvOptions").write_text(self.options)
        began = time.perf_counter()
        self.case.run(self.command, self.n_procs, log_name=self.log_name)
        return time.perf_counter() - began


@contextlib.contextmanager
def _control_entries(case: Case, **entries: str) -> Iterator[None]:
    """Set entries of the case's controlDict for one run, and put the
    written values back after it."""
    control = "system/controlDict"
    saved = {entry: case.written(control, entry) for entry in entries}
    for entry, value in entries.items():
        case.set(control, entry, value)
    try:
        yield
    finally:
        for entry, value in saved.items():
            case.set(control, entry, value)


#: Counted instructions: valgrind's callgrind writes its counts before each
#: time step (Time::operator++), so that every step's count is its own and
#: the start-up's stays out
CALLGRIND_STEP_DUMP = "*Time::operator++*"


def callgrind_step_counts(prefix: Path, steps: int, first: int = 2) -> list[int]:
    """Instructions of ``steps`` time steps from step ``first`` on, from the
    dumps of ``valgrind --tool=callgrind --dump-before=<each step>
    --callgrind-out-file=prefix``: ``prefix.1`` holds the start-up,
    ``prefix.<k + 1>`` step k.  The first step is left out by default: a
    model may set itself up there (the laser's first step counts 2.3 times
    a later one)."""
    counts = []
    for dump in range(first + 1, first + steps + 1):
        path = Path(f"{prefix}.{dump}")
        if not path.is_file():
            raise RuntimeError(f"callgrind wrote no count of step {dump - 1} ({path} is missing)")
        found = re.search(r"^(?:summary|totals):\s+(\d+)", path.read_text(), re.M)
        if found is None:
            raise RuntimeError(f"{path}: no 'summary:' line of a callgrind dump")
        counts.append(int(found.group(1)))
    return counts


def _counted_instructions(variant: _Variant, start: str, steps: int, delta_t: float) -> float:
    """Mean instructions per step of ``variant`` (serial) over ``steps``
    steps after the first from its time directory ``start``, counted by
    callgrind."""
    if shutil.which("valgrind") is None:
        raise RuntimeError("counted instructions need valgrind (apt-get install valgrind)")
    if variant.options is not None:
        (variant.case / "constant/fvOptions").write_text(variant.options)
    prefix = variant.case.path / "callgrind" / variant.log_name
    shutil.rmtree(prefix.parent, ignore_errors=True)
    prefix.parent.mkdir()
    # The first step, the counted ones and one more: the last dump holds the
    # last step and the end
    with _control_entries(variant.case, startTime=start,
                          endTime=f"{float(start) + (steps + 2) * delta_t:.9g}"):
        variant.case.run(f"valgrind --tool=callgrind --dump-before='{CALLGRIND_STEP_DUMP}' "
                         f"--callgrind-out-file={prefix} {variant.command}",
                         log_name=f"{variant.log_name}.callgrind")
    return statistics.mean(callgrind_step_counts(prefix, steps))


def _insertions(case: Case) -> np.ndarray | None:
    """The droplets inserted in the latest run of ``case``, a row each
    (the wireDroplets table), or None without one."""
    try:
        return np.atleast_1d(case.latest_table("wireDroplets", "insertions"))
    except (FileNotFoundError, ValueError):
        return None


def _insertion_onsets(case: Case) -> list[float]:
    """Times [s] of the droplets inserted in the latest run of ``case``."""
    table = _insertions(case)
    return [] if table is None else sorted(float(row["Time"]) for row in table)


def _start_up_seconds(variant: _Variant, steps: int, delta_t: float) -> float:
    """Wall time [s] of a run of one step of ``variant``: what a run costs
    before its steps (launch, mesh, fields) and one step."""
    end_time = float(variant.case.written("system/controlDict", "endTime"))
    with _control_entries(variant.case, endTime=f"{end_time - (steps - 1) * delta_t:.9g}"):
        return variant.run()


def _rounds(variants: dict[str, _Variant], repeats: int, steps: int
            ) -> tuple[dict[str, list[float]], dict[str, list[float]]]:
    """CPU time per step (timeInfo, the master rank) and wall time of the
    whole run of every variant in each of ``repeats`` rounds.

    Each round runs every variant once, so that a slow spell of the shared
    virtual machine falls on all variants of a round; each round's ratios
    are taken within the round, and their median over the rounds counts.
    """
    for variant in variants.values():
        if variant.n_procs > 1:
            variant.case.decompose(variant.n_procs)
    cpu: dict[str, list[float]] = {name: [] for name in variants}
    wall: dict[str, list[float]] = {name: [] for name in variants}
    for _ in range(repeats):
        for name, variant in variants.items():
            wall[name].append(variant.run())
            cpu[name].append(variant.case.seconds_per_step())
    return cpu, wall


def _median_ratio(numerator: list[float], denominator: list[float]) -> tuple[float, float]:
    """Median over the rounds of each round's ratio, and the ratios' spread
    ((largest - least) / median)."""
    ratios = [a / b for a, b in zip(numerator, denominator)]
    median = statistics.median(ratios)
    return median, (max(ratios) - min(ratios)) / median


#: What says that an effect acted in the window: its own table under
#: postProcessing (function object, file, column) and that some row's value
#: is above zero; the droplets are judged by their insertions (below), the
#: enthalpy porosity by liquid metal in the solver's balances
EFFECT_TABLES = {
    "laser": ("laser", "power", "absorbedMetal"),
    "marangoni": ("marangoni", "force", "maxTangentialStress"),
    "evaporation": ("evaporation", "evaporation", "massRate"),
    "surfaceLosses": ("surfaceLosses", "losses", "radiated"),
    "gasRise": ("gasRise", "drift", "metalDown"),
}
#: Gravity [m/s2] of the droplets' fall (the template's constant/g)
GRAVITY = 9.81


def _droplet_landing(case: Case, start: float, end: float) -> tuple[bool, str]:
    """Whether a droplet was inserted in [start, end] and had landed by
    ``end``: its fall from the insertion (the bottom of the sphere) to the
    substrate's surface at the template's droplet speed under gravity, an
    upper bound (a deposit under the wires shortens it)."""
    table = _insertions(case)
    if table is None:
        return False, "no insertions table"
    speed = case.scalar("system/caseParameters", "dropletSpeed")
    for row in table:
        onset = float(row["Time"])
        height = float(row["centreZ"]) - float(row["radius"])
        fall = (-speed + math.sqrt(speed**2 + 2 * GRAVITY * height)) / GRAVITY
        if start <= onset and onset + fall <= end:
            return True, (f"inserted at {onset:.4g} s, {1e3 * height:.2g} mm up, landed by "
                          f"{onset + fall:.4g} s")
    return False, f"no droplet inserted in {start:g}-{end:g} s that landed by its end"


def _effect_activity(name: str, case: Case, start: float, end: float) -> tuple[bool, str]:
    """Whether the effect ``name`` acted in its own variant's run, and why."""
    if name == "wireDroplets":
        return _droplet_landing(case, start, end)
    if name == "enthalpyPorosity":
        liquid = float(case.balances()["liquid_volume"].max())
        return liquid > 0, f"liquid metal up to {1e9 * liquid:.3g} mm3"
    if name not in EFFECT_TABLES:
        return False, "no table says"
    table_name, file, column = EFFECT_TABLES[name]
    try:
        values = np.asarray(case.latest_table(table_name, file)[column], dtype=float)
    except (FileNotFoundError, ValueError):
        return False, f"no {table_name}/{file} table"
    return bool(values.max() > 0), f"{column} up to {values.max():.3g}"


def _template_alpha_excursion(case: Case) -> float:
    """Largest excursion of ldnaFoam's metal fraction outside [0, 1] over
    its latest run (its balances table, one row a step)."""
    balances = case.balances()
    return max(0.0, -float(balances["alpha_min"].min()), float(balances["alpha_max"].max()) - 1)


def solver_costs(level: int = 0, steps: int = 140, start_time: float = 0.1, n_procs: int = 2,
                 repeats: int = 5, work_dir: Path | None = None,
                 instruction_steps: int = 0) -> SolverCosts:
    """Run every variant of the benchmark ``repeats`` times; see the module's description.

    The template first runs with its adaptive step from the flat substrate
    to ``start_time`` (0.1 s: droplets in flight and landing on a first
    deposit, heated by the laser); every variant then does ``steps`` steps of
    the template's mean step over the second half of that run from its state
    (140 steps at level 0: 25 ms, in which a droplet of each wire is
    inserted and lands).  The reference, compressibleInterFoam from the same
    fields, temperature included, sweeps its limiter as often as it needs to
    keep the metal fraction as bounded as ldnaFoam's (the least of
    REFERENCE_LIMITER_CANDIDATES whose excursion outside [0, 1] is at most
    ldnaFoam's or the template's traceMetalFraction, the fraction ldnaFoam
    counts as no metal), and at OpenFOAM's default.

    With ``instruction_steps`` > 0 every serial variant also runs under
    callgrind from the template's state two steps before the window's first
    droplet insertion, and that many steps after the first are counted:
    instructions per step, which do not depend on what else the machine
    runs.
    """
    if steps < 2:
        raise ValueError(f"--steps {steps}: at least 2 (a run's start-up is its one-step run)")
    scratch = Path(work_dir or tempfile.mkdtemp(prefix="ldna-bench-"))
    scene = Case.copy_of(TEMPLATE, scratch / "ldna")
    scene.set("system/caseParameters", "level", str(level))
    # compressibleInterFoam has no conductivity field for the substrate
    # walls' heat-loss condition: adiabatic walls in every variant
    scene.set("0/T", "boundaryField/substrateWalls", "{ type zeroGradient; }")
    _only_time_info(scene)
    scene.mesh()
    scene.run("setFields")
    full_options = (scene / "constant/fvOptions").read_text()
    effects = block_names(scene / "constant/fvOptions")

    # The developed state every variant starts from, and the template's own
    # time step on the way there
    adaptive = Case.copy_of(scene, scratch / "adaptive")
    shutil.copytree(scene / "constant/polyMesh", adaptive / "constant/polyMesh")
    adaptive.set("system/controlDict", "endTime", f"{start_time:g}")
    adaptive.set("system/controlDict", "writeInterval", f"{start_time:g}")
    adaptive.run()
    times = adaptive.balances()["time"]
    template_delta_t = float(np.diff(times)[len(times) // 2:].mean())
    start = adaptive.times[-1]
    shutil.copytree(start, scene / start.name)
    delta_t = float(f"{template_delta_t:.3g}")
    begin = float(start.name)
    end = begin + steps * delta_t

    _fixed_steps(scene, steps, delta_t, begin)

    fv_options = scene / "constant/fvOptions"

    def ldna_with(names: list[str], log_name: str, n: int = 1,
                  options: str = full_options) -> _Variant:
        fv_options.write_text(options)
        keep_blocks(fv_options, names)
        return _Variant(scene, "ldnaFoam", log_name, n, fv_options.read_text())

    # How bounded ldnaFoam keeps the metal fraction with every effect, and
    # the reference's sweeps that keep it so
    everything = ldna_with(effects, "ldnaFoam.all")
    everything.run()
    ldna_excursion = _template_alpha_excursion(scene)
    bound = max(ldna_excursion, float(scene.written("system/fvSolution",
                                                    'solvers/"alpha.metal.*"/traceMetalFraction')))
    excursions: dict[int, float] = {}
    reference_sweeps = REFERENCE_LIMITER_CANDIDATES[-1]
    for sweeps in REFERENCE_LIMITER_CANDIDATES:
        probe = _compressible_inter_foam_case(scene, scratch / f"reference{sweeps}", start, sweeps)
        excursions[sweeps] = _alpha_excursion_of_reference(probe)
        if excursions[sweeps] <= bound:
            reference_sweeps = sweeps
            break

    variants = {"none": ldna_with([], "ldnaFoam.none")}
    variants[REFERENCE_VARIANT] = _Variant(
        Case(scratch / f"reference{reference_sweeps}"), "compressibleInterFoam",
        "compressibleInterFoam")
    if reference_sweeps != OPENFOAM_LIMITER_ITERATIONS:
        variants[DEFAULT_REFERENCE_VARIANT] = _Variant(
            Case(scratch / f"reference{OPENFOAM_LIMITER_ITERATIONS}"), "compressibleInterFoam",
            "compressibleInterFoam")
    for name in effects:
        variants[name] = ldna_with([name], f"ldnaFoam.{name}")
    monte_carlo = _monte_carlo_laser(full_options)
    if "laser" in effects and monte_carlo != full_options:
        variants[MONTE_CARLO_VARIANT] = ldna_with(["laser"], "ldnaFoam.laserMonteCarlo",
                                                  options=monte_carlo)
    variants["all"] = everything
    variants["parallel"] = ldna_with(effects, "ldnaFoam.parallel", n_procs)

    cpu, wall = _rounds(variants, repeats, steps)
    # Each effect's activity from its own variant's last run (its tables)
    active, evidence = {}, {}
    onsets: list[float] = []
    for name in effects:
        variants[name].run()
        active[name], evidence[name] = _effect_activity(name, scene, begin, end)
        if name == "wireDroplets":
            onsets = [t for t in _insertion_onsets(scene) if begin <= t <= end]
    instructions: dict[str, float] = {}
    counted_from = float("nan")
    if instruction_steps > 0:
        counted_from, instructions = _instruction_counts(
            variants, everything, scene, begin, delta_t, onsets, instruction_steps)
    # Wall time per step: a run of one step (start-up and a step) taken off
    wall_per_step = {name: (statistics.median(wall[name])
                            - _start_up_seconds(variants[name], steps, delta_t)) / (steps - 1)
                     for name in ("all", "parallel")}

    median = {name: statistics.median(values) for name, values in cpu.items()}
    spreads: dict[str, float] = {}
    costs = []
    for name in variants:
        if name in effects or name == MONTE_CARLO_VARIANT:
            ratio, spreads[name] = _median_ratio(cpu[name], cpu["none"])
            costs.append(StepCost(name, median[name], ratio))
    _, spreads["no_effects"] = _median_ratio(cpu["none"], cpu[REFERENCE_VARIANT])
    _, spreads["all_effects"] = _median_ratio(cpu["all"], cpu[REFERENCE_VARIANT])
    default = median.get(DEFAULT_REFERENCE_VARIANT, median[REFERENCE_VARIANT])
    return SolverCosts(level=level, cells=scene.cells, steps=steps, delta_t=delta_t,
                       start_time=begin, ldna_no_effects=median["none"],
                       compressible_inter_foam=median[REFERENCE_VARIANT],
                       effects=costs, all_effects=median["all"],
                       template_delta_t=template_delta_t,
                       serial_all_effects=wall_per_step["all"],
                       parallel_all_effects=wall_per_step["parallel"],
                       n_procs=n_procs, repeats=repeats,
                       reference_limiter_iterations=reference_sweeps,
                       default_reference=default, ldna_alpha_excursion=ldna_excursion,
                       reference_alpha_excursions=excursions, effect_active=active,
                       effect_evidence=evidence, spreads=spreads,
                       instruction_steps=instruction_steps, instruction_start=counted_from,
                       instructions=instructions)


def _instruction_counts(variants: dict[str, _Variant], everything: _Variant, scene: Case,
                        begin: float, delta_t: float, onsets: list[float], steps: int
                        ) -> tuple[float, dict[str, float]]:
    """Counted instructions per step of every serial variant over ``steps``
    steps from one state: the template's (all effects) two steps before the
    first droplet insertion in ``onsets`` (``begin`` without one), so that
    the counted steps, which follow a first uncounted one, hold the
    insertion."""
    lead = max(0, math.floor((onsets[0] - begin) / delta_t - 1e-6) - 2) if onsets else 0

    def written_at(time: float) -> Path:
        # Each timed run also writes its end: the state is found by its time
        for directory in scene.times:
            if abs(float(directory.name) - time) < 0.5 * delta_t:
                return directory
        raise RuntimeError(f"no time directory at {time:g} s in {scene.path}")

    start = written_at(begin)
    if lead > 0:
        with _control_entries(scene, endTime=f"{begin + lead * delta_t:.9g}",
                              writeControl="timeStep", writeInterval=str(lead)):
            everything.run()
        start = written_at(begin + lead * delta_t)
    counts = {}
    for name, variant in variants.items():
        if variant.n_procs > 1:
            continue
        if variant.case.path != scene.path and not (variant.case / start.name).is_dir():
            shutil.copytree(start, variant.case / start.name)
        counts[name] = _counted_instructions(variant, start.name, steps, delta_t)
    return float(start.name), counts


def print_solver_costs(c: SolverCosts) -> None:
    """Print the benchmark's figures and ratios."""
    print(f"LDNA template, level {c.level}: {c.cells} cells, {c.steps} fixed steps of "
          f"{c.delta_t:g} s from the state at {c.start_time:g} s; CPU time per step, "
          f"median of {c.repeats} rounds (ratios: median of each round's ratio, spread = "
          f"(largest - least) / median)")
    tried = ", ".join(f"{n}: {e:.2g}" for n, e in c.reference_alpha_excursions.items())
    print(f"  metal fraction outside [0, 1]: ldnaFoam {c.ldna_alpha_excursion:.2g}; "
          f"compressibleInterFoam by limiter sweeps {tried}")
    print(f"  compressibleInterFoam, {c.reference_limiter_iterations:>3} sweeps {'':6}"
          f"{c.compressible_inter_foam:9.4f} s")
    print(f"  compressibleInterFoam, {OPENFOAM_LIMITER_ITERATIONS:>3} sweeps (default)"
          f"{c.default_reference:9.4f} s")
    print(f"  ldnaFoam, no effects           {c.ldna_no_effects:9.4f} s   ratio to "
          f"compressibleInterFoam {c.ldna_no_effects / c.compressible_inter_foam:.3f} "
          f"(spread {c.spreads.get('no_effects', float('nan')):.1%})")
    for cost in c.effects:
        acted = c.effect_active.get(cost.variant)
        note = "" if acted is None else ("acted: " if acted else "DID NOT ACT: ") + \
            c.effect_evidence.get(cost.variant, "")
        print(f"  ldnaFoam + {cost.variant:<20} {cost.seconds_per_step:9.4f} s   ratio to "
              f"no effects {cost.ratio:.3f} (spread {c.spreads.get(cost.variant, 0):.1%})  {note}")
    print(f"  ldnaFoam, all effects          {c.all_effects:9.4f} s   ratio to "
          f"compressibleInterFoam {c.all_effects / c.compressible_inter_foam:.3f} "
          f"(spread {c.spreads.get('all_effects', float('nan')):.1%}; "
          f"{c.all_effects / c.default_reference:.3f} at its default sweeps)")
    print(f"Throughput (all effects, serial): {c.throughput:.4g} cell-steps per second per core")
    print(f"Template's adaptive time step at this level: {c.template_delta_t:.3g} s")
    print(f"Projected for the paper's {PAPER_CELLS} cells (0.15 mm at the surface): "
          f"{c.projected_core_hours():.4g} core-hours per simulated second")
    print(f"mpirun -np {c.n_procs}: wall {c.parallel_all_effects:.4f} s per step against "
          f"{c.serial_all_effects:.4f} serial, parallel efficiency {c.parallel_efficiency:.3f}")
    if c.instructions:
        print(f"Counted instructions (callgrind) per step over {c.instruction_steps} steps after "
              f"the first from {c.instruction_start:g} s:")
        ratios = c.instruction_ratios()
        for name, count in c.instructions.items():
            ratio = ratios.get(name)
            against = "" if ratio is None else f"   ratio to no effects {ratio:.4f}"
            print(f"  {name:<30} {count:14.4g}{against}")
        print(f"  no effects / compressibleInterFoam {ratios['no_effects']:.4f}; all effects "
              f"{ratios['all_effects']:.4f} ({ratios['all_effects_default_reference']:.4f} at "
              f"its default sweeps)")
