"""Metal mass balance and solver health of an ldnaFoam run, read from its outputs.

The metal in the domain changes by what the droplet sources add, what
evaporation removes and what the flow carries through the boundaries:

    m(t1) - m(t0) = added - evaporated - rho_ref * sum_n Q_n dt_n

``Q_n`` is the metal volume flow out of the domain (``alphaPhi0.metal``
summed over the substrate inlet, outlet and atmosphere patches by the
template's ``metalFlow*`` function objects, written every step) and
``rho_ref`` the Boussinesq reference density with which the solver carries
metal mass.  The residual is judged against the metal *turnover* (what
entered plus what the wires fed), not against the mass of the whole
substrate, which would hide any error in the deposit.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .case import Case
from .material import Metal

#: The template's function objects of metal volume flow through its patches
FLOW_FUNCTION_OBJECTS = ("metalFlowIn", "metalFlowOut", "metalFlowAtmosphere")
#: The same as metal mass flows [kg/s] (the template's, weighted by rho.metal)
MASS_FLOW_FUNCTION_OBJECTS = ("metalMassFlowIn", "metalMassFlowOut", "metalMassFlowAtmosphere")

#: OpenFOAM's default maximum number of linear-solver iterations (lduMatrix)
DEFAULT_MAX_ITER = 1000


@dataclass(frozen=True)
class MassBalance:
    """Metal mass budget of one run [kg]."""

    start: float
    end: float
    added: float
    evaporated: float
    inflow: float
    outflow: float

    @property
    def residual(self) -> float:
        """Mass change not explained by sources, sinks and boundary flows."""
        return (self.end - self.start) - (self.added - self.evaporated
                                          + self.inflow - self.outflow)

    @property
    def turnover(self) -> float:
        """Metal that entered the domain: boundary inflow plus droplets."""
        return self.inflow + self.added

    @property
    def relative_residual(self) -> float:
        """Residual relative to the turnover."""
        return abs(self.residual) / self.turnover


#: Columns of each wire's rows in :func:`wire_table`
WIRE_COLUMNS = ("addedMass", "onTime", "dutyFraction")


def wire_table(case: Case | Path) -> dict[str, np.ndarray]:
    """Per wire of every droplet source, per step: metal added [kg] and time
    switched on [s] since the start of the run, and the duty fraction, from
    the sources' tables (postProcessing/<source>/<startTime>/droplets.dat)."""
    case = Case(case)
    wires: dict[str, np.ndarray] = {}
    for source in case.tables_named("droplets"):
        table = case.table(source, "droplets")
        names = [column.rsplit("_", 1)[0] for column in table.dtype.names[1::len(WIRE_COLUMNS)]]
        for wire in names:
            wires[wire] = np.column_stack([table[f"{wire}_{column}"] for column in WIRE_COLUMNS])
    return wires


def evaporation_table(case: Case | Path) -> np.ndarray | None:
    """Evaporation's rows per step (``massRate`` [kg/s], ``evaporatedMass`` [kg]
    since the start of the run, ``latentHeat`` and ``heatSink`` [W],
    ``recoilForce_x/y/z`` [N]), or None without an evaporation source."""
    case = Case(case)
    sources = case.tables_named("evaporation")
    if len(sources) > 1:
        raise ValueError(f"{case}: more than one evaporation source: {sources}")
    return case.table(sources[0], "evaporation") if sources else None


def metal_mass_balance(case: Case | Path) -> MassBalance:
    """Mass budget of the run of ``case``, from its tables."""
    case = Case(case)
    balances = case.balances()
    metal = Metal.from_case(case.path)
    if metal.density_model != "Boussinesq":
        raise ValueError(f"{case}: the flow balance needs the Boussinesq metal "
                         f"(constant mass density), not {metal.density_model}")

    inflow = outflow = 0.0
    for name, mass_name in zip(FLOW_FUNCTION_OBJECTS, MASS_FLOW_FUNCTION_OBJECTS):
        # The mass flows where the case has them (two metals of different
        # density), otherwise the volume flows at the metal's density
        _, mass = step_flows(case, mass_name, float(balances["time"][0]))
        if mass.size == 0:
            _, volume = step_flows(case, name, float(balances["time"][0]))
            mass = metal.reference_density * volume
        inflow -= mass[mass < 0].sum()
        outflow += mass[mass > 0].sum()

    evaporation = evaporation_table(case)
    return MassBalance(
        start=float(balances["metal_mass"][0]),
        end=float(balances["metal_mass"][-1]),
        added=float(sum(values[-1, 0] for values in wire_table(case).values())),
        evaporated=float(evaporation["evaporatedMass"][-1]) if evaporation is not None else 0.0,
        inflow=float(inflow),
        outflow=float(outflow),
    )


def step_flows(case: Case | Path, name: str, run_start: float) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and metal volumes [m3] out (negative: in) per step of the
    patch flow function object ``name``: each row is the flow of the step
    that ended at its time, the first step starting at ``run_start``."""
    rows = Case(case).function_object(name, "surfaceFieldValue.dat")
    if rows.size == 0:
        return np.empty(0), np.empty(0)
    times = rows[:, 0]
    return times, rows[:, 1] * np.diff(np.concatenate(([run_start], times)))


def patch_flows(case: Case | Path, start: float = -np.inf, end: float = np.inf) -> dict[str, float]:
    """Metal volume [m3] that left through each of the template's patch flow
    function objects (``metalFlowIn``, ...; negative: entered) between
    ``start`` and ``end`` [s]."""
    case = Case(case)
    balance_times = case.balances()["time"]
    volumes = {}
    for name in FLOW_FUNCTION_OBJECTS:
        rows = case.function_object(name, "surfaceFieldValue.dat")
        if rows.size == 0:
            continue
        # The step before the table's first: the run's start (the balances
        # of a continued weld hold the saved weld's rows before it)
        before = balance_times[balance_times < rows[0, 0]]
        run_start = float(before[-1]) if before.size else float(balance_times[0])
        times, volume = step_flows(case, name, run_start)
        if times.size:
            volumes[name] = float(volume[(times > start) & (times <= end)].sum())
    return volumes


@dataclass(frozen=True)
class SolverHealth:
    """What the linear solvers and the energy iteration reported over a run."""

    solves: int
    max_iterations: int
    worst_final_residual: float
    all_finite: bool
    #: Time steps whose energy iteration ended at its limit unconverged
    energy_unconverged: int
    #: Most energy iterations a converged step took
    max_energy_iterations: int

    def diverged(self, max_iter: int = DEFAULT_MAX_ITER) -> bool:
        """A solve hit the iteration limit or produced a non-finite residual."""
        return (not self.all_finite) or self.max_iterations >= max_iter


def solver_health(case: Case | Path) -> SolverHealth:
    """Iterations and residuals of every linear solve and energy iteration of
    a run, from the solver's balance table."""
    balances = Case(case).balances()[1:]
    if balances["linear_solves"].sum() == 0:
        raise ValueError(f"{case}: no linear solves recorded")
    return SolverHealth(
        solves=int(balances["linear_solves"].sum()),
        max_iterations=int(balances["max_linear_iterations"].max()),
        worst_final_residual=float(balances["max_final_residual"].max()),
        all_finite=bool(balances["non_finite_solves"].sum() == 0),
        energy_unconverged=int(balances["energy_unconverged"].sum()),
        max_energy_iterations=int(balances["energy_iterations"].max()),
    )
