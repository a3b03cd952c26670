"""Cost benchmarks of the LDNA template: ratios measured in one run on this machine.

Benchmarks, not tests: nothing is asserted, the figures are printed.  Each
copies ``cases/ldna`` (at a resolution level) into a scratch folder, meshes
it once and runs a fixed number of fixed-size time steps, so that every
variant does the same steps:

- ``laser_cost``: no laser and each laser absorption model, the template's
  other effects on;
- ``solver_costs`` (``ldna bench``): from a developed state of the
  template, ldnaFoam with no effects against OpenFOAM's
  compressibleInterFoam on the same mesh, fields and numerics; the cost of
  each effect of the template alone over the no-effect step (and of its
  laser with Monte-Carlo rays); the throughput in cell-steps per second per
  core with the projected core-hours per simulated second at the paper's
  resolution; and the parallel efficiency of ``mpirun -np 2`` against a
  serial run.
"""
from __future__ import annotations

import re
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from foamlib import FoamFieldFile

from ..case import Case
from ..foamcase import PROJECT_DIR
from ..foamdict import block_names, keep_blocks, read_scalars, remove_blocks

TEMPLATE = PROJECT_DIR / "cases" / "ldna"

#: Laser of the benchmark: the paper's power range and oscillation, a 1 mm
#: beam on the substrate surface at mid-length (caseParameters geometry)
LASER_POWER = 1200.0
LASER_BEAM_RADIUS = 1e-3
LASER_MODELS = ("gaussianSurface", "beerLambert", "monteCarlo")



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

#: The companion case of compressibleInterFoam: the template's metal and gas
#: as OpenFOAM thermophysical models (316L at its reference density, argon),
#: its constant surface tension, laminar flow
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
    equationOfState perfectGas; specie specie; energy sensibleInternalEnergy; }
mixture { specie { molWeight 39.948; } thermodynamics { Cp 520.3; Hf 0; }
    transport { mu 2.27e-5; Pr 0.667; } }
""",
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
    """What ``solver_costs`` measured."""

    level: int
    cells: int
    steps: int
    delta_t: float
    start_time: float
    ldna_no_effects: float
    compressible_inter_foam: float
    effects: list[StepCost]
    all_effects: float
    template_delta_t: float
    serial_all_effects: float
    parallel_all_effects: float
    n_procs: int
    repeats: int

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

    @property
    def parallel_efficiency(self) -> float:
        """Serial time over (ranks x parallel time), per step."""
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
            "reference_s_per_step": self.compressible_inter_foam,
            "no_effects_s_per_step": self.ldna_no_effects,
            "all_effects_s_per_step": self.all_effects,
            "no_effects_ratio": self.ldna_no_effects / self.compressible_inter_foam,
            "all_effects_ratio": self.all_effects / self.compressible_inter_foam,
            "effect_ratios": {cost.variant: cost.ratio for cost in self.effects},
            f"np{self.n_procs}_efficiency": self.parallel_efficiency,
            "throughput_cell_steps_per_core_s": self.throughput,
            "template_delta_t_s": self.template_delta_t,
            "projected_core_hours_per_simulated_s": self.projected_core_hours(),
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

#: The name of the reference variant: OpenFOAM's own solver
REFERENCE_VARIANT = "compressibleInterFoam"


def _monte_carlo_laser(options: str) -> str:
    """The fvOptions text with the Beer-Lambert laser's absorption model
    replaced by monteCarlo at its defaults (unchanged without one)."""
    text = re.sub(r"beerLambertCoeffs\s*\{[^}]*\}", "", options)
    return re.sub(r"(absorptionModel\s+)beerLambert\s*;", r"\1monteCarlo;", text)


def _compressible_inter_foam_case(scene: Case, destination: Path, start: Path) -> Case:
    """The scene's mesh, fields (at the ``start`` time directory) and
    numerics set up for compressibleInterFoam."""
    case = Case.copy_of(scene, destination)
    shutil.copytree(scene / "constant/polyMesh", case / "constant/polyMesh")
    shutil.copytree(start, case / start.name)
    # The same metal and flow at the ambient temperature: compressibleInterFoam
    # has no melting, and its temperature equation fails on the 2100 K
    # droplets landing on cold metal within ten steps (negative temperature);
    # its step costs one temperature solve whatever the temperatures are
    ambient = read_scalars(scene / "system/caseParameters")["ambientTemperature"]
    FoamFieldFile(case / f"{start.name}/T").internal_field = ambient
    for name, text in COMPRESSIBLE_INTER_FOAM_FILES.items():
        (case / name).write_text(text)
    (case / "constant/fvOptions").unlink(missing_ok=True)
    for entry, value in COMPRESSIBLE_INTER_FOAM_SCHEMES.items():
        case.set("system/fvSchemes", entry, value)
    case.set("system/controlDict", "application", "compressibleInterFoam")
    return case


@dataclass
class _Variant:
    """One timed run: the case, the solver, its ranks and, for ldnaFoam, the
    fvOptions it runs with."""

    case: Case
    command: str
    log_name: str
    n_procs: int = 1
    options: str | None = None


def _least_times_per_step(variants: dict[str, _Variant], repeats: int) -> dict[str, float]:
    """Least time per step of each variant over ``repeats`` rounds.

    Each round runs every variant once, so that a slow spell of the shared
    virtual machine falls on all variants of a round rather than on the
    repeats of one variant.  The least, because that scatter (measured:
    0.062 and 0.084 s per step for the same compressibleInterFoam run) only
    ever adds time.
    """
    for variant in variants.values():
        if variant.n_procs > 1:
            variant.case.decompose()
    times: dict[str, list[float]] = {name: [] for name in variants}
    for _ in range(repeats):
        for name, variant in variants.items():
            if variant.options is not None:
                (variant.case / "constant/fvOptions").write_text(variant.options)
            variant.case.run(variant.command, variant.n_procs, log_name=variant.log_name)
            times[name].append(variant.case.seconds_per_step())
    return {name: min(values) for name, values in times.items()}


def solver_costs(level: int = 0, steps: int = 40, start_time: float = 0.1, n_procs: int = 2,
                 repeats: int = 3, work_dir: Path | None = None) -> SolverCosts:
    """Run every variant of the benchmark ``repeats`` times; see the module's description.

    The template first runs with its adaptive step from the flat substrate
    to ``start_time`` (0.1 s: droplets in flight and landing on a first
    deposit, heated by the laser); every variant then does ``steps`` steps of
    the template's mean step over the second half of that run from its state.
    """
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

    _fixed_steps(scene, steps, delta_t, float(start.name))

    fv_options = scene / "constant/fvOptions"

    def ldna_with(names: list[str], log_name: str, n: int = 1,
                  options: str = full_options) -> _Variant:
        fv_options.write_text(options)
        keep_blocks(fv_options, names)
        return _Variant(scene, "ldnaFoam", log_name, n, fv_options.read_text())

    variants = {"none": ldna_with([], "ldnaFoam.none")}
    inter = _compressible_inter_foam_case(scene, scratch / "compressibleInterFoam", start)
    variants[REFERENCE_VARIANT] = _Variant(inter, "compressibleInterFoam",
                                           "compressibleInterFoam")
    for name in effects:
        variants[name] = ldna_with([name], f"ldnaFoam.{name}")
    monte_carlo = _monte_carlo_laser(full_options)
    if "laser" in effects and monte_carlo != full_options:
        variants[MONTE_CARLO_VARIANT] = ldna_with(["laser"], "ldnaFoam.laserMonteCarlo",
                                                  options=monte_carlo)
    variants["all"] = ldna_with(effects, "ldnaFoam.all")
    variants["parallel"] = ldna_with(effects, "ldnaFoam.parallel", n_procs)

    least = _least_times_per_step(variants, repeats)
    no_effects = least["none"]
    costs = [StepCost(name, least[name], least[name] / no_effects)
             for name in variants if name in effects or name == MONTE_CARLO_VARIANT]
    return SolverCosts(level=level, cells=scene.cells, steps=steps, delta_t=delta_t,
                       start_time=float(start.name), ldna_no_effects=no_effects,
                       compressible_inter_foam=least[REFERENCE_VARIANT],
                       effects=costs, all_effects=least["all"],
                       template_delta_t=template_delta_t,
                       serial_all_effects=least["all"], parallel_all_effects=least["parallel"],
                       n_procs=n_procs, repeats=repeats)


def print_solver_costs(c: SolverCosts) -> None:
    """Print the benchmark's figures and ratios."""
    print(f"LDNA template, level {c.level}: {c.cells} cells, {c.steps} fixed steps of "
          f"{c.delta_t:g} s from the state at {c.start_time:g} s, CPU time per step "
          f"(least of {c.repeats} runs)")
    print(f"  compressibleInterFoam          {c.compressible_inter_foam:9.4f} s")
    print(f"  ldnaFoam, no effects           {c.ldna_no_effects:9.4f} s   ratio to "
          f"compressibleInterFoam {c.ldna_no_effects / c.compressible_inter_foam:.3f}")
    for cost in c.effects:
        print(f"  ldnaFoam + {cost.variant:<20} {cost.seconds_per_step:9.4f} s   ratio to "
              f"no effects {cost.ratio:.3f}")
    print(f"  ldnaFoam, all effects          {c.all_effects:9.4f} s   ratio to "
          f"no effects {c.all_effects / c.ldna_no_effects:.3f}")
    print(f"Throughput (all effects, serial): {c.throughput:.4g} cell-steps per second per core")
    print(f"Template's adaptive time step at this level: {c.template_delta_t:.3g} s")
    print(f"Projected for the paper's {PAPER_CELLS} cells (0.15 mm at the surface): "
          f"{c.projected_core_hours():.4g} core-hours per simulated second")
    print(f"mpirun -np {c.n_procs}: {c.parallel_all_effects:.4f} s per step, speed-up "
          f"{c.serial_all_effects / c.parallel_all_effects:.3f}, parallel efficiency "
          f"{c.parallel_efficiency:.3f}")
