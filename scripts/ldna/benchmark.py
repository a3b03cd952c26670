"""Cost benchmarks: what an effect adds to a time step of the LDNA template.

``laser_cost`` copies ``cases/ldna`` (at a resolution level) into a scratch
folder, meshes it once and runs a fixed number of fixed-size time steps
without a laser and with each laser absorption model.  It prints the wall
time per step and its ratio to the step without a laser, measured in one
run on this machine (a benchmark, not a test: nothing is asserted).
"""
from __future__ import annotations

import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .foamcase import PROJECT_DIR, copy_case, run
from .foamdict import read_scalars, remove_blocks, set_entry

TEMPLATE = PROJECT_DIR / "cases" / "ldna"

#: Laser of the benchmark: the paper's power range and oscillation, a 1 mm
#: beam on the substrate surface at mid-length (caseParameters geometry)
LASER_POWER = 1200.0
LASER_BEAM_RADIUS = 1e-3
LASER_MODELS = ("gaussianSurface", "beerLambert", "monteCarlo")

EXECUTION_TIME = re.compile(r"^ExecutionTime = (\S+) s", re.M)


@dataclass
class StepCost:
    """Wall time per step of one variant, and its ratio to the reference."""

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


def seconds_per_step(log: Path) -> float:
    """Mean wall time per step from a solver log, leaving out the first step (start-up)."""
    times = np.array([float(t) for t in EXECUTION_TIME.findall(log.read_text())])
    if len(times) < 3:
        raise RuntimeError(f"too few steps in {log}")
    return float(np.diff(times)[1:].mean())


def laser_cost(level: int = 1, steps: int = 20, delta_t: float = 1e-4,
               work_dir: Path | None = None) -> list[StepCost]:
    """Time per step of the template with no laser and with each laser model.

    The template's other effects (droplets, Marangoni, evaporation, losses,
    porosity) stay on in every variant; its own laser is replaced by the
    benchmark laser; the ratios show what the laser adds.
    """
    scratch = Path(work_dir or tempfile.mkdtemp(prefix="ldna-bench-"))
    case = copy_case(TEMPLATE, scratch / "ldna")
    set_entry(case / "system" / "caseParameters", "level", str(level))
    control = case / "system" / "controlDict"
    set_entry(control, "adjustTimeStep", "no")
    set_entry(control, "deltaT", f"{delta_t:g}")
    set_entry(control, "endTime", f"{steps * delta_t:g}")
    set_entry(control, "writeInterval", "1")
    run(case, "blockMesh")
    run(case, "setFields")

    length = read_scalars(case / "system" / "caseParameters")["length"]
    remove_blocks(case / "constant" / "fvOptions", ["laser"])
    base_options = (case / "constant" / "fvOptions").read_text()
    costs: list[StepCost] = []
    for variant in ("none", *LASER_MODELS):
        options = base_options + ("" if variant == "none" else laser_entry(variant, length))
        (case / "constant" / "fvOptions").write_text(options)
        run(case, "ldnaFoam", log_name=f"ldnaFoam.{variant}")
        costs.append(StepCost(variant, seconds_per_step(case / f"log.ldnaFoam.{variant}"), 0.0))

    reference = costs[0].seconds_per_step
    for cost in costs:
        cost.ratio = cost.seconds_per_step / reference
    return costs


def print_costs(costs: list[StepCost], level: int) -> None:
    """Print the table of step costs."""
    print(f"LDNA template, level {level}: wall time per step")
    print(f"{'laser':<16} {'s/step':>10} {'ratio':>8}")
    for cost in costs:
        print(f"{cost.variant:<16} {cost.seconds_per_step:>10.4f} {cost.ratio:>8.3f}")
