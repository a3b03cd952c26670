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

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .foamcase import read_balances, read_function_object
from .material import Metal

#: The template's function objects of metal volume flow through its patches
FLOW_FUNCTION_OBJECTS = ("metalFlowIn", "metalFlowOut", "metalFlowAtmosphere")

_WIRE = re.compile(r"dropletSource \S+: wire (\S+) added mass = (\S+) kg, on time = (\S+) s, "
                   r"duty fraction = (\S+)")
_EVAPORATION = re.compile(
    r"^evaporation \S+: mass rate = (\S+) kg/s, evaporated mass = (\S+) kg, "
    r"latent heat = (\S+) W, heat sink = (\S+) W(?:, recoil force = \((\S+) (\S+) (\S+)\) N)?$",
    re.M)
_SOLVE = re.compile(r"Solving for (\S+), Initial residual = (\S+), Final residual = (\S+), "
                    r"No Iterations (\d+)")
#: The energy iteration's report of each time step (applications/solvers/ldnaFoam/TEqn.H)
_ENERGY_CONVERGED = re.compile(r"^Energy: converged in (\d+) iterations", re.M)
_ENERGY_UNCONVERGED = re.compile(r"^Energy: not converged in \d+ iterations", re.M)

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


#: Columns of :func:`wire_log`
WIRE_LOG_COLUMNS = ("added mass", "on time", "duty fraction")


def wire_log(log: Path) -> dict[str, np.ndarray]:
    """Per wire, per step: added mass [kg], on time [s], duty fraction, as dropletSource logs them."""
    rows: dict[str, list[tuple[float, ...]]] = {}
    for match in _WIRE.finditer(Path(log).read_text()):
        rows.setdefault(match.group(1), []).append(tuple(float(v) for v in match.groups()[1:]))
    return {wire: np.array(values) for wire, values in rows.items()}


def evaporation_log(log: Path) -> list[tuple[float, ...]]:
    """Per step: mass rate, evaporated mass, latent heat, heat sink (and recoil force)."""
    return [tuple(float(v) for v in m.groups() if v is not None)
            for m in _EVAPORATION.finditer(Path(log).read_text())]


def metal_mass_balance(case: Path, log_name: str = "ldnaFoam") -> MassBalance:
    """Mass budget of the run logged in ``case/log.<log_name>``."""
    case = Path(case)
    log = case / f"log.{log_name}"
    balances = read_balances(log)
    metal = Metal.from_case(case)
    if metal.density_model != "Boussinesq":
        raise ValueError(f"{case}: the flow balance needs the Boussinesq metal "
                         f"(constant mass density), not {metal.density_model}")

    inflow = outflow = 0.0
    for name in FLOW_FUNCTION_OBJECTS:
        rows = read_function_object(case, name, "surfaceFieldValue.dat")
        if rows.size == 0:
            continue
        # Each row is the flow of the step that ended at its time
        times = rows[:, 0]
        steps = np.diff(np.concatenate(([balances["time"][0]], times)))
        volume = rows[:, 1] * steps
        inflow -= metal.reference_density * volume[volume < 0].sum()
        outflow += metal.reference_density * volume[volume > 0].sum()

    evaporation = evaporation_log(log)
    return MassBalance(
        start=float(balances["metal_mass"][0]),
        end=float(balances["metal_mass"][-1]),
        added=float(sum(values[-1, 0] for values in wire_log(log).values())),
        evaporated=evaporation[-1][1] if evaporation else 0.0,
        inflow=float(inflow),
        outflow=float(outflow),
    )


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


def solver_health(log: Path) -> SolverHealth:
    """Iterations and residuals of every linear solve and energy iteration in a solver log."""
    text = Path(log).read_text()
    solves = _SOLVE.findall(text)
    if not solves:
        raise ValueError(f"{log}: no linear solves logged")
    finals = [float(final) for _, _, final, _ in solves]
    initials = [float(initial) for _, initial, _, _ in solves]
    energy_converged = [int(n) for n in _ENERGY_CONVERGED.findall(text)]
    return SolverHealth(
        solves=len(solves),
        max_iterations=max(int(n) for *_, n in solves),
        worst_final_residual=max(finals),
        all_finite=all(math.isfinite(v) for v in finals + initials),
        energy_unconverged=len(_ENERGY_UNCONVERGED.findall(text)),
        max_energy_iterations=max(energy_converged, default=0),
    )
