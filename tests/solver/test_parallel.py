"""Serial and MPI runs of the LDNA template agree.

The template scene (level 0) runs once serially and on 2, 3 and 4 ranks
(decomposePar, mpirun, reconstructPar; 3 and 4 oversubscribe a 2-core
machine), with every linear solver converged to 1e-13 so that the
decomposition can change the answer only at that level.

Compared at 15 ms, after the first droplets have been inserted (9.7 ms)
and before they land (about 18 ms): once droplets splash onto the surface
as bodies, thin splash films amplify round-off (measured at 25 ms: metal
fractions differing by up to 0.24 in single splash cells).  The metal
fraction and the pressure are compared everywhere, temperature and velocity
in the metal: a gas cell's temperature is that of the trace of metal it
holds (one temperature per cell).  The template with its laser, Marangoni
flow, evaporation, surface losses and porosity, once without and once with
the droplets.

With droplets the runs differed by up to 0.08 in a cell's metal fraction
(2 ranks): the upwind predictor's linear solution leaves metal fractions
of 1e-43 to 1e-9, of either sign, in gas and metal cells, which depend on
the decomposition and which the flow and heat of the gas cells amplified.
Set to 0 below traceMetalFraction 1e-8 (metalFractionLimiter), 2 ranks
agree with the serial run to 5.5e-5 in metal fraction here (2.1e-6 with
the energy iteration converged too, liquidFractionTolerance 1e-10); 3 and
4 ranks, whose processor faces pass 1.7 mm from the second wire's
droplets, to 4.8e-5 and 2.3e-4:
there gas cells holding 1e-6 to 1e-4 of the hot droplet's metal (its heat
capacity rivals the gas's) differ by up to 70 K, and the gas's density
and flow carry that back to the metal fraction.
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from ldna.balance import WIRE_COLUMNS, metal_mass_balance, wire_table
from ldna.case import Case
from ldna.foamdict import keep_blocks
from solver_cases import TEMPLATE


#: Time of the comparison [s]
END_TIME = "0.015"
#: Temperature [K] the laser brings the metal above by END_TIME (ambient 300 K)
HEATED = 400
#: Linear-solver tolerance of both runs
SOLVER_TOLERANCE = "1e-13"
#: Allowed difference relative to each field's scale; measured about 1e-6
#: for T and U with the tolerance above (1e-4 with the template's own)
FIELD_TOLERANCE = 1e-5
#: The same with droplets in flight, on any number of ranks: the issue's
#: bound for the template's own tolerances; measured here (2026-11-27):
#: metal fraction 5.5e-5, 4.8e-5, 2.3e-4 and the metal's velocity 4.1e-5,
#: 3.6e-5, 1.9e-4 on 2, 3 and 4 ranks
DROPLET_FIELD_TOLERANCE = 1e-3


def tighten_solvers(case: Case) -> None:
    """Converge every linear solver of the case to SOLVER_TOLERANCE, the
    final corrector's (p_rghFinal, (U|T)Final) too, with no relative
    tolerance."""
    fv_solution = case / "system" / "fvSolution"
    solvers, rest = fv_solution.read_text().split("PIMPLE", 1)
    solvers = re.sub(r"(\n\s*)tolerance\s+[^;]+;", rf"\1tolerance {SOLVER_TOLERANCE};", solvers)
    solvers = re.sub(r"(\n\s*)relTol\s+[^;]+;", r"\1relTol 0;", solvers)
    fv_solution.write_text(solvers + "PIMPLE" + rest)


#: Effects of the template compared, besides the droplets
EFFECTS = ["laser", "marangoni", "evaporation", "surfaceLosses", "enthalpyPorosity"]


#: With droplets: the droplets' masses agree to
#: round-off (the insertion does not depend on the ranks), the metal masses
#: differ by no more than what the runs let through the boundaries
#: differently (trace metal of the droplets leaves through the atmosphere,
#: 5.6e-6 kg/s at 15 ms, and its rate follows the runs' differing traces:
#: 1.6e-9 of the metal mass measured, all of it that flow), and no cell
#: differs by as much as half of it in metal (a droplet lost, doubled or
#: put a cell away moves whole cells of metal)
MASS_AGREEMENT = 1e-9
DROPLET_DISPLACEMENT = 0.5


#: The serial runs, once per set of effects, shared by the rank counts
_SERIAL_RUNS: dict[bool, Case] = {}


def serial_run(directory: Path, with_droplets: bool) -> Case:
    """The template (level 0, ASCII) with the compared effects, run serially
    to END_TIME with tight solvers, once per session and set of effects."""
    name = "droplets" if with_droplets else "none"
    if with_droplets not in _SERIAL_RUNS:
        case = Case.copy_of(TEMPLATE, directory / name)
        case.set("system/caseParameters", "level", "0")
        case.set("system/controlDict", "writeFormat", "ascii")
        keep_blocks(case / "constant" / "fvOptions",
                    EFFECTS + (["wireDroplets"] if with_droplets else []))
        case.set("system/controlDict", "endTime", END_TIME)
        case.set("system/controlDict", "writeInterval", END_TIME)
        case.set("system/controlDict", "writePrecision", "14")
        tighten_solvers(case)
        case.mesh()
        case.run("setFields")
        # The meshed start the parallel runs copy
        shutil.copytree(case, directory / f"{name}-start")
        case.run("ldnaFoam")
        _SERIAL_RUNS[with_droplets] = case
    return _SERIAL_RUNS[with_droplets]


@pytest.mark.parametrize("with_droplets,n_procs", [
    pytest.param(False, 2, id="without_droplets-np2"),
    pytest.param(True, 2, id="with_droplets-np2"),
    pytest.param(True, 3, id="with_droplets-np3"),
    pytest.param(True, 4, id="with_droplets-np4"),
])
def test_serial_and_parallel_runs_agree(tmp_path_factory: pytest.TempPathFactory,
                                        tmp_path: Path, with_droplets: bool,
                                        n_procs: int) -> None:
    serial = serial_run(tmp_path_factory.getbasetemp() / "parallelSerial", with_droplets)
    parallel = Case(Path(shutil.copytree(serial.path.parent / f"{serial.path.name}-start",
                                         tmp_path / "parallel")))
    parallel.decompose(n_procs)
    parallel.run("ldnaFoam", n_procs=n_procs)
    parallel.run("reconstructPar -latestTime")

    end_serial, end_parallel = serial.times[-1], parallel.times[-1]
    assert end_serial.name == end_parallel.name == END_TIME
    alpha_serial = serial.field("alpha.metal", end_serial)
    alpha_parallel = parallel.field("alpha.metal", end_parallel)
    metal = (alpha_serial >= 0.5) & (alpha_parallel >= 0.5)
    masses = [case.balances()["metal_mass"][-1] for case in (serial, parallel)]
    budgets = [metal_mass_balance(case) for case in (serial, parallel)]
    # The metal each run let in minus what it let out (the flow tables)
    net_flows = [budget.inflow - budget.outflow for budget in budgets]
    unexplained = (masses[1] - masses[0]) - (net_flows[1] - net_flows[0])
    print(f"metal mass {masses[0]:.14g} serial, {masses[1]:.14g} parallel; net boundary "
          f"flow {net_flows[0]:.14g}, {net_flows[1]:.14g}; difference not explained by "
          f"the flows {unexplained:.3g} kg")
    assert abs(unexplained) < MASS_AGREEMENT * masses[0]
    if not with_droplets:
        assert masses[1] == pytest.approx(masses[0], rel=MASS_AGREEMENT)
    if with_droplets:
        added = [sum(values[-1, WIRE_COLUMNS.index("addedMass")]
                     for values in wire_table(case).values()) for case in (serial, parallel)]
        assert added[0] > 0 and added[1] == pytest.approx(added[0], rel=MASS_AGREEMENT)
        assert np.abs(alpha_serial - alpha_parallel).max() < DROPLET_DISPLACEMENT
    for field, where in (("alpha.metal", slice(None)), ("p_rgh", slice(None)),
                         ("T", metal), ("U", metal)):
        a = serial.field(field, end_serial)[where]
        b = parallel.field(field, end_parallel)[where]
        scale = np.abs(a).max()
        difference = np.abs(a - b).max() / scale
        print(f"{field}: largest difference {difference:.2e} of its scale {scale:.6g}")
        assert difference < (DROPLET_FIELD_TOLERANCE if with_droplets else FIELD_TOLERANCE)
    # The scene is not trivial: the laser has heated the metal
    assert serial.field("T", end_serial).max() > HEATED
