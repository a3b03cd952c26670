"""What accuracy costs: a scene run at several resolutions, error against cost.

``ldna accuracy CASE OUT`` copies a case once per mesh level (and per
time-step setting), runs each copy, and records

- the cost: wall time of the solver run, core-seconds per simulated
  millisecond (CPU time of the master rank from the timeInfo table, or the
  wall time without it, x MPI ranks / simulated ms), cells and steps;
- the scene's key outputs and their relative error against the analytical
  answer where the scene has one (``cases/stefanMelting``: the Neumann
  melting front) or against the finest run (the LDNA scene: melt-pool width
  and depth, peak temperature, metal mass, bead area);
- the observed order of convergence of each output: the least-squares slope
  of log(error) over log(cell size) at the finest time-step setting.

It writes ``OUT/accuracy.csv``, ``OUT/accuracy.md`` (a Markdown table) and
``OUT/accuracy.png`` (log-log error against core-hours per simulated second).
"""
from __future__ import annotations

import csv
import math
import os
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

import numpy as np

from .. import meshing
from ..case import BALANCES, PROJECT_DIR, RUN_FUNCTIONS, Case
from ..foamdict import read_scalars
from ..steady import MIN_WINDOW as STEADY_MIN_WINDOW
from ..steady import WINDOWS as STEADY_WINDOWS
from ..steady import SCALES as STEADY_SCALES
from ..stefan import NeumannSolution, front_position
from ..study import Parameter


class Scene(Protocol):
    """How ``ldna accuracy`` resolves, runs and measures one kind of case."""

    name: str
    #: Output name -> (label, unit, scale from SI to that unit)
    outputs_meta: dict[str, tuple[str, str, float]]
    default_levels: tuple[float, ...]

    def set_resolution(self, case: Case, level: float) -> float:
        """Mesh ``case`` at ``level``; return the finest cell size [mm]."""

    def prepare(self, case: Case, start: "StartState | None") -> None:
        """Make the mesh (refined where ``start`` has its weld, if the case
        asks for it) and the initial fields."""

    def run(self, case: Case, member: "Member") -> None:
        """Run the solver on the member's case (decomposed for its ranks)."""

    def outputs(self, case: Case) -> dict[str, float]:
        """Key outputs of a finished run, in SI units."""

    def exact(self, case: Case, end_time: float) -> dict[str, float] | None:
        """Analytical outputs at ``end_time``, or None (compare with the finest run)."""


#: Error bounds a user picks a level for: the cheapest level within each
ERROR_BOUNDS = (0.05, 0.10)


#: The LDNA scenes' outputs: label, unit and factor from SI to that unit
LDNA_OUTPUTS = {
    "pool_width": ("melt-pool width", "mm", 1e3),
    "pool_length": ("melt-pool length", "mm", 1e3),
    "penetration": ("penetration", "mm", 1e3),
    "bead_height": ("bead height", "mm", 1e3),
    "bead_width": ("bead width", "mm", 1e3),
    "body_width": ("bead body width (a quarter of its height thick)", "mm", 1e3),
    "bead_area": ("bead area", "mm2", 1e6),
    "wetting_angle": ("wetting angle", "deg", 1.0),
    "first_layer_gas": ("gas film under the bead", "mm", 1e3),
    "section_liquid": ("liquid share of the bead section", "-", 1.0),
    "coarse_surface": ("share of the bead section's width topped by cells coarser than its "
                       "finest", "-", 1.0),
    "bonded_width": ("bonded width", "mm", 1e3),
    "dilution": ("dilution", "-", 1.0),
    "chemical_dilution": ("chemical dilution (base metal in the bead section)", "-", 1.0),
    "peak_temperature": ("peak metal temperature", "K", 1.0),
    "droplet_fraction": ("largest metal fraction in flight", "-", 1.0),
    "metal_mass": ("metal mass", "g", 1e3),
}


class LdnaScene:
    """The LDNA template scene: outputs of the meltPoolMetrics function object."""

    name = "ldna"
    outputs_meta = {name: LDNA_OUTPUTS[name] for name in (
        "pool_width", "pool_length", "penetration", "bead_height", "bead_width",
        "peak_temperature", "droplet_fraction", "metal_mass")}
    #: Process-zone cells of 0.45, 0.32 and 0.225 mm (level 1 resolves droplets)
    default_levels = (0.0, 0.5, 1.0)

    #: Every level refines only the band (system/topoSetDict.band): level L
    #: is level L - 1 with its band split once (--band), so that every cell
    #: of the mesh, band and background, shrinks with the level (level 0:
    #: 0.45 mm in the band on the base mesh's 0.9 mm)
    band = False

    def mesh_level(self, case: Case, level: float) -> float:
        """Set the case's mesh for ``level``; the finest cell size [mm]."""
        banded = self.band
        if banded and not level - 1 >= meshing.MIN_LEVEL:
            raise ValueError(f"--band: level {level:g} would be level {level - 1:g} with its "
                             f"band split; the lowest level is {meshing.MIN_LEVEL}")
        process_level = level - 1 if banded else level
        meshing.set_level(case, process_level)
        if banded:
            case.set("system/caseParameters", "bandLevel", "1")
        return meshing.finest_cell_size(case, process_level)

    def set_resolution(self, case: Case, level: float) -> float:
        finest = self.mesh_level(case, level)
        # The metrics at the end time only: at write times, and the end is one
        for entry, value in (("writeControl", "writeTime"), ("writeInterval", "1")):
            case.set("system/controlDict", f"functions/meltPoolMetrics/{entry}", value)
        return finest

    def prepare(self, case: Case, start: "StartState | None") -> None:
        case.mesh(start=(start.case, start.time) if start else None)
        case.run("setFields")

    def run(self, case: Case, member: "Member") -> None:
        case.run("ldnaFoam", member.n_procs)

    def outputs(self, case: Case) -> dict[str, float]:
        from ..post import BeadMetrics, read_function_object_metrics

        last = dict(zip(("time",) + BeadMetrics.FUNCTION_OBJECT_COLUMNS,
                        read_function_object_metrics(case)[-1]))
        values = {name: float(last[name]) for name in self.outputs_meta if name in last}
        values["metal_mass"] = float(case.balances()["metal_mass"][-1])
        values["droplet_fraction"] = largest_fraction_in_flight(case)
        return values

    def exact(self, case: Case, end_time: float) -> dict[str, float] | None:
        return None


def largest_fraction_in_flight(case: Path) -> float:
    """Largest metal fraction of the latest time between the wire tips and the substrate.

    A droplet that flies as a resolved body has cells of metal fraction 1; one
    smeared over cells larger than itself stays well below (the droplet shape
    output of the study).  Droplets fly about 9 of every 10 ms, so one is
    almost always in the air; the column is the middle 80 % of the flight.
    """
    from ..post import read_case

    grid = read_case(case)
    z = np.asarray(grid.cell_centers().points)[:, 2]
    wire_height = 1e-3 * Case(case).scalar("system/caseParameters", "wireHeight")
    in_flight = (z > 0.1 * wire_height) & (z < 0.9 * wire_height)
    alpha = np.asarray(grid.cell_data["alpha.metal"])[in_flight]
    return float(alpha.max()) if alpha.size else math.nan


#: Wall time between a running level's progress lines [s]: a level of the
#: bead study runs for hours
PROGRESS_INTERVAL = 300.0


class RunProgress:
    """A progress line of a run from ``start_time`` to ``end_time``: the
    simulated time and steps from the solver's balances table (one row a
    step), the wall time, and the time left at the rate since it began."""

    def __init__(self, case: Case, label: str, start_time: float, end_time: float) -> None:
        self.case, self.label = case, label
        self.start_time, self.end_time = start_time, end_time
        self.began = time.monotonic()

    def __call__(self) -> None:
        wall = time.monotonic() - self.began
        try:
            table = self.case.latest_table(*BALANCES)
            times = np.empty(0) if table is None else np.asarray(table["Time"], dtype=float)
        except (OSError, ValueError):
            # Not there yet, or a number the solver is still writing: a
            # progress line must never stop the run
            times = np.empty(0)
        times = times[times > self.start_time]
        if not times.size:
            print(f"  {self.label}: {wall / 60:.1f} min wall, setting up", flush=True)
            return
        simulated = times[-1] - self.start_time
        left = (self.end_time - times[-1]) * wall / simulated
        print(f"  {self.label}: t = {times[-1]:.5g} of {self.end_time:g} s, {times.size} steps, "
              f"{wall / 60:.1f} min wall, about {left / 60:.0f} min left", flush=True)


class BeadScene(LdnaScene):
    """The LDNA template's quasi-steady bead: each level runs until ``ldna
    steady`` judges its bead quasi-steady (domain balance included), in
    stretches of ``STRETCH`` after the first ``WINDOWS`` shortest windows,
    at most to ``end_time``; its outputs are the means over the judged
    windows (the wetting angle, the body width and the gas film under the
    bead over the fields written in them: ``ldna post`` reads them from the
    fields).

    Start every level from a steady run of the scene (``--start-from``): a
    level then only relaxes to its own resolution's weld."""

    name = "bead"
    outputs_meta = {name: LDNA_OUTPUTS[name] for name in (
        "bead_width", "body_width", "bead_height", "bead_area", "wetting_angle",
        "first_layer_gas", "bonded_width",
        "penetration", "dilution", "chemical_dilution", "pool_length", "section_liquid",
        "coarse_surface")}
    #: Errors of the bond's metrics, which are 0 without fusion, are read
    #: against the bead's size in their direction, as ldna steady reads them
    #: (the penetration against the height, the bonded width against the
    #: width, the dilution against 1); the bead's own against themselves
    error_scales = {**{name: scale for name, scale in STEADY_SCALES.items()
                       if name in ("bonded_width", "penetration", "dilution")},
                    # a share of the bead, as the geometric dilution
                    "chemical_dilution": None,
                    # 0 where the clad wets its substrate: read against the
                    # height, as the penetration is
                    "first_layer_gas": "bead_height"}
    #: The outputs that only fusion makes (base metal in the bead section
    #: without fusion is numerical mixing at the surface, not dilution)
    fusion_outputs = ("bonded_width", "penetration", "dilution", "chemical_dilution")
    #: Penetration [m] below which the fusion metrics do not resolve a bond:
    #: their tested depth accuracy (tests/solver/test_fusion_line.py,
    #: docs/validation.md).  A study whose every level stays below it has no
    #: fusion to converge.
    fusion_depth_floor = 0.05e-3
    #: The outputs of the section's bead shape, which are its final shape
    #: only where the bead has frozen
    section_shape_outputs = ("bead_width", "body_width", "bead_height", "bead_area",
                             "wetting_angle", "first_layer_gas")
    #: Liquid share of the section's bead above which its shape is not the
    #: bead's final one: the finest error bound the study reports, since
    #: that much of the section may still move
    section_liquid_limit = min(ERROR_BOUNDS)
    #: Share of the section's bead width topped by cells coarser than its
    #: finest (outside the refined zone or band) above which the level's
    #: shape is not read at its own resolution: the finest error bound, as
    #: the liquid share's.  The superseded study's level 1 read 74 % at
    #: 32.25 s (docs/accuracy-cost.md)
    coarse_surface_limit = min(ERROR_BOUNDS)
    #: The section's diagnostics: read and reported, never judged
    diagnostics = ("section_liquid", "coarse_surface")
    #: Simulated time added each time a level is judged not yet steady [s]
    STRETCH = 0.25
    #: Longest run of a level from its start without ``--end-time`` [s]: a
    #: level mapped from the saved weld is judged from its bead's arrival
    #: (1.47 s) plus four windows of whole ripple periods (0.44 s at the
    #: band's level 0: 1.76 s), and may need stretches more
    MAX_SPAN = 4.0
    #: Shortest window ``ldna steady`` judges with [s] (``--min-window``):
    #: longer windows for a weld that fills and drains slower than the
    #: default's ripple periods
    min_window = STEADY_MIN_WINDOW

    def set_resolution(self, case: Case, level: float) -> float:
        return self.mesh_level(case, level)

    def run(self, case: Case, member: "Member") -> None:
        from .. import post, section_fields, steady

        control = "system/controlDict"
        # Every stretch's end is written, so that a stopped study resumes
        case.set(control, "writeInterval", f"{self.STRETCH:g}")
        start = member.start_time
        written = [float(t.name) for t in case.times]
        if (case / "processor0").is_dir():
            written += [float(t.name) for t in Case(case / "processor0").times]
        # The first judgeable time: four windows after the level's own bead
        # reaches the section (a level mapped from another mesh holds the
        # start's bead until then), or where a resumed member stopped
        section = post.configured_bead_section(case.path)
        arrival = None if section is None else post.bead_arrival_time(case, section)
        first = start if arrival is None else max(start, arrival)
        target = max(first + steady.WINDOWS * self.min_window, *written)
        stop = member.end_time
        target = min(self.STRETCH * math.ceil(target / self.STRETCH - 1e-9), stop)
        while True:
            case.set(control, "endTime", f"{target:g}")
            latest = max(written, default=start)
            case.run("ldnaFoam", member.n_procs, log_name=f"ldnaFoam.{target:g}",
                     progress=RunProgress(case, member.name, latest, target),
                     every=PROGRESS_INTERVAL)
            # Read the fields the stretch wrote while they are there (a
            # packed study keeps only its first and latest)
            section_fields.update(case.path)
            # Later stretches continue from the latest written time
            case.set(control, "startFrom", "latestTime")
            verdict = steady.case_steadiness(case.path, min_window=self.min_window)
            member.steady = verdict.steady
            member.verdict = verdict.reason
            written.append(target)
            if verdict.steady or target >= stop - 1e-9:
                break
            print(f"  {member.name} at {target:g} s: not quasi-steady ({verdict.reason}); "
                  f"on to {min(target + self.STRETCH, stop):g} s (at most {stop:g} s)",
                  flush=True)
            target = min(target + self.STRETCH, stop)
        member.end_time = target
        times, table, arrival = steady.case_table(case.path)
        member.first_steady = steady.first_steady(times, table, max(arrival or 0.0, start),
                                                  self.min_window,
                                                  balance=steady.DomainBalance.of(case.path))

    def outputs(self, case: Case) -> "WindowMeans":
        """Every output's mean over the ``steady.WINDOWS`` judged windows,
        and its ripple: the standard deviation of its windows' means (the
        mean's standard error is that over sqrt(WINDOWS)).  The last
        window's mean alone scatters by the ripple: read over windows of
        0.5 and 1 s, levels 0 and 0.5 of the superseded study differed by
        up to 8 % in their last windows and by at most 3.6 % over the
        four, within their standard errors (docs/accuracy-cost.md).  The
        section's metrics come from meltPoolMetrics' table, those only the
        fields hold (wetting angle, body width, gas film) from the fields
        written in the windows (``section_fields``)."""
        from .. import section_fields, steady

        verdict = steady.case_steadiness(case.path, min_window=self.min_window)
        ends = verdict.end_time - verdict.window * np.arange(steady.WINDOWS)[::-1]
        tabled = [name for name in self.outputs_meta
                  if name not in section_fields.COLUMNS]
        times, table, _ = steady.case_table(case.path, names=tuple(tabled))
        means = {name: np.array([steady.window_mean(times, table[name], end - verdict.window,
                                                    end) for end in ends])
                 for name in tabled}
        rows = section_fields.update(case.path)
        # The table's last row lies a few steps before the run's last
        # written field: the fields' windows end at that field
        latest = max(rows, default=verdict.end_time)
        offset = latest - verdict.end_time
        field_ends = ends + (offset if 0 <= offset < verdict.window else 0.0)
        for name in section_fields.COLUMNS:
            means[name] = section_fields.window_means(rows, name, field_ends, verdict.window)
        # A run shorter than the windows (not judged) has means in its
        # last ones only: those are averaged, and a ripple needs two
        measured = {name: m[np.isfinite(m)] for name, m in means.items()}
        return WindowMeans(
            {name: float(m.mean()) if m.size else math.nan for name, m in measured.items()},
            ripples={name: float(np.std(m, ddof=1)) if m.size > 1 else math.nan
                     for name, m in measured.items()},
            fields_in_window=section_fields.times_in_window(
                rows, field_ends[-1], steady.WINDOWS * verdict.window))


class WindowMeans(dict):
    """Outputs (name -> SI value) that are window means, with each one's
    ripple (the standard deviation of its window means, SI) and how many
    written fields the judged windows held."""

    def __init__(self, values: dict[str, float], ripples: dict[str, float],
                 fields_in_window: int) -> None:
        super().__init__(values)
        self.ripples = ripples
        self.fields_in_window = fields_in_window


class StefanScene:
    """``cases/stefanMelting``: the melting front against the Neumann solution."""

    name = "stefan"
    outputs_meta = {"front": ("melting front position", "mm", 1e3)}
    #: 25 cells (0.8 mm) doubled per level; level 3 is the case's 0.1 mm
    default_levels = (0.0, 1.0, 2.0, 3.0, 4.0)
    #: Cells along the bar and time step at level 0; both halve per
    #: level, so that the first-order time error falls with the space error
    level0_cells = 25
    level0_delta_t = 16e-3

    def set_resolution(self, case: Case, level: float) -> float:
        cells = round(self.level0_cells * 2**level)
        case.set("system/caseParameters", "cellsAlongBar", str(cells))
        case.set("system/caseParameters", "deltaT", f"{self.level0_delta_t / 2**level:.9g}")
        return case.scalar("system/caseParameters", "barLength") / cells

    def prepare(self, case: Case, start: "StartState | None") -> None:
        case.run("blockMesh")

    def run(self, case: Case, member: "Member") -> None:
        case.run("ldnaFoam", member.n_procs)

    def outputs(self, case: Case) -> dict[str, float]:
        return {"front": front_position(case.path, case.times[-1].name)}

    def exact(self, case: Case, end_time: float) -> dict[str, float] | None:
        return {"front": NeumannSolution.from_case(case.path).front(end_time)}


SCENES: dict[str, Scene] = {"ldna": LdnaScene(), "bead": BeadScene(),
                            "stefan": StefanScene()}


def detect_scene(case: Path) -> Scene:
    """The scene of a case from its caseParameters."""
    parameters = read_scalars(Path(case) / "system" / "caseParameters")
    if "cellsAlongBar" in parameters:
        return SCENES["stefan"]
    if "level" in parameters:
        return SCENES["ldna"]
    raise ValueError(f"{case}: not an LDNA or Stefan case (system/caseParameters has "
                     "neither 'level' nor 'cellsAlongBar'); give --scene")


@dataclass
class Member:
    """One run of the study and what it cost."""

    level: float
    max_co: float | None
    cell_size_mm: float
    cells: int = 0
    steps: int = 0
    wall_time: float = math.nan
    #: CPU time of the master rank [s] (timeInfo table), or None without it
    cpu_time: float | None = None
    n_procs: int = 1
    start_time: float = 0.0
    end_time: float = math.nan
    outputs: dict[str, float] = field(default_factory=dict)
    errors: dict[str, float] = field(default_factory=dict)
    #: Outputs that are window means (bead scene): the standard deviation of
    #: each one's judged windows' means (SI), and the written fields of the
    #: judged windows (what the field-read outputs average)
    ripples: dict[str, float] = field(default_factory=dict)
    fields_in_window: int | None = None
    #: Bead scene: judged quasi-steady at the end, why (not), and the first
    #: time it was [s]
    steady: bool | None = None
    verdict: str = ""
    first_steady: float | None = None
    #: The run (folder name) and time whose state the member's weld started
    #: from (the weldStart record of Allrun -start-from), or None
    started_from: tuple[str, float] | None = None
    #: Cost measured by a serial window from the member's latest time
    #: (measure_cost_window): core-seconds per simulated ms and its steps;
    #: None without one
    window_core_s_per_ms: float | None = None
    window_steps: int = 0

    @property
    def name(self) -> str:
        """Folder name of the member."""
        co = "" if self.max_co is None else f"-co{self.max_co:g}"
        return f"level{meshing.level_name(self.level)}{co}"

    @property
    def core_seconds_per_ms(self) -> float:
        """Core-seconds per simulated millisecond: the cost window's where one
        was measured, else the runs' (legs_core_seconds_per_ms)."""
        if self.window_core_s_per_ms is not None:
            return self.window_core_s_per_ms
        return self.legs_core_seconds_per_ms

    @property
    def legs_core_seconds_per_ms(self) -> float:
        """Core-seconds per simulated millisecond of the member's runs: the
        master rank's CPU time (other work on the machine does not count), or
        the wall time of a case without the timeInfo table, times the ranks."""
        seconds = self.wall_time if self.cpu_time is None else self.cpu_time
        return seconds * self.n_procs / ((self.end_time - self.start_time) * 1e3)

    @property
    def core_hours_per_simulated_s(self) -> float:
        return self.core_seconds_per_ms * 1e3 / 3600

    @property
    def core_hours_to_steady(self) -> float | None:
        """From the member's start to its first quasi-steady time, at its mean cost."""
        if self.first_steady is None:
            return None
        return self.core_hours_per_simulated_s * (self.first_steady - self.start_time)


def route_core_hours_to_steady(member: Member, members: list[Member]) -> float | None:
    """Core-hours to the member's first quasi-steady time, with those of the
    study's members its weld started from, each counted from its own start
    to the time the next one started from (``--sequence``: level 1 needs
    level 0.5 run to the time it starts from); None if the member was never
    judged quasi-steady."""
    by_name = {m.name: m for m in members}
    hours, child = member.core_hours_to_steady, member
    while hours is not None and child.started_from and child.started_from[0] in by_name:
        parent = by_name[child.started_from[0]]
        hours += parent.core_hours_per_simulated_s * (child.started_from[1] - parent.start_time)
        child = parent
    return hours


@dataclass(frozen=True)
class StartState:
    """A developed state every member starts from: a reconstructed time of a run."""

    case: Path
    time: float

    def __post_init__(self) -> None:
        if not any(abs(t - self.time) <= 1e-9 * max(1.0, self.time)
                   for t in (float(d.name) for d in Case(self.case).times)):
            raise ValueError(f"{self.case}: no reconstructed time {self.time:g} to start from")

    def map_onto(self, case: Case) -> None:
        """Map the state onto ``case``'s mesh (volume-weighted) at the state's time.

        The member starts at that time (the droplets' and the laser's phase
        follow), with the state's fields; quantities the mapping cannot carry
        (the time step) start from the member's controlDict.
        """
        # The cases' own step (bin/tools/RunFunctions, as Allrun -start-from)
        case.run(f". '{RUN_FUNCTIONS}' && startFromState '{self.case.resolve()}' "
                 f"{self.time:g}", log_name="startFromState")


def resumed_start_time(directory: Path) -> float | None:
    """The start time of a member that has run before (it has written a time
    after its start, decomposed or not), which ``--resume`` continues; None
    for a member to make anew."""
    control = directory / "system" / "controlDict"
    if not control.is_file() or not (
            (directory / "processor0").is_dir() or len(Case(directory).times) > 1):
        return None
    return Case(directory).scalar("system/controlDict", "startTime")


def run_member(template: Path, directory: Path, scene: Scene, member: Member,
               end_time: float | None, n_procs: int,
               start: StartState | None = None, resume: bool = False,
               settings: "list[Parameter] | None" = None) -> Member:
    """Copy, mesh and run one member; fill in its cost and outputs.  With
    ``resume`` a member that has run before continues from its latest time.
    ``settings``: entries (one value each) set in every member's copy of the
    template before it is meshed; a resumed member must have them."""
    control = "system/controlDict"
    settings = settings or []
    began = resumed_start_time(directory) if resume else None
    if began is not None:
        case = Case(directory)
        for setting in settings:
            written = case.written(setting.file, setting.entry)
            if written != setting.values[0]:
                raise ValueError(f"{directory.name} ran with {setting.name} {written}, not "
                                 f"{setting.values[0]}: resume it with the settings it "
                                 "ran with, or start the study in another folder")
        member.cell_size_mm = scene.set_resolution(case, member.level)
        member.start_time = began
        case.set(control, "startFrom", "latestTime")
        member.end_time = end_time if end_time is not None else case.scalar(control, "endTime")
        member.cells = case.cells
        member.n_procs = n_procs
        if n_procs > 1 and not (directory / "processor0").is_dir():
            # Unpacked (ldna unpack) or run serially before: its latest time
            case.set_ranks(n_procs)
            case.run("decomposePar -latestTime -force", log_name="decomposePar.resume")
        return _run_and_measure(case, scene, member)
    if directory.exists():
        shutil.rmtree(directory)
    case = Case.copy_of(template, directory)
    for setting in settings:
        case.set(setting.file, setting.entry, setting.values[0])
    member.cell_size_mm = scene.set_resolution(case, member.level)
    if end_time is not None:
        case.set(control, "endTime", f"{end_time:g}")
    member.end_time = case.scalar(control, "endTime")
    member.start_time = start.time if start else 0.0
    if not member.end_time > member.start_time:
        raise ValueError(f"end time {member.end_time:g} s is not after the start "
                         f"{member.start_time:g} s")
    # The end time is written (and measured there)
    case.set(control, "writeInterval", f"{member.end_time - member.start_time:g}")
    if member.max_co is not None:
        case.set(control, "maxCo", f"{member.max_co:g}")
        case.set(control, "maxAlphaCo", f"{member.max_co:g}")
    scene.prepare(case, start)
    if start:
        start.map_onto(case)
    member.cells = case.cells
    member.n_procs = n_procs
    if n_procs > 1:
        case.decompose(n_procs)
    return _run_and_measure(case, scene, member)


def _run_and_measure(case: Case, scene: Scene, member: Member) -> Member:
    from ..post import weld_start_state

    began = time.perf_counter()
    scene.run(case, member)
    member.wall_time = time.perf_counter() - began
    try:
        member.cpu_time = case.cpu_seconds()
        # Every leg of a member that was continued (--resume), not this one's
        member.wall_time = case.clock_seconds()
    except FileNotFoundError:
        member.cpu_time = None
    if member.n_procs > 1:
        case.reconstruct()
    # Rows of the runs' balance table: the initial state and one per step
    member.steps = len(case.balances()) - 1
    member.started_from = weld_start_state(case.path)
    outputs = scene.outputs(case)
    member.outputs = dict(outputs)
    member.ripples = getattr(outputs, "ripples", {})
    member.fields_in_window = getattr(outputs, "fields_in_window", None)
    return member


def measure_cost_window(member_dir: Path, scratch: Path, window: float) -> tuple[float, int]:
    """Core-seconds per simulated millisecond of a serial run of ``window``
    simulated seconds from the member's latest reconstructed time, and its
    steps, the start-up left out (``Case.latest_run_cpu_rate``).

    The run is a copy in ``scratch`` (the mesh, the setup and that time), so
    the member stays as it was.  Measured for every level in one call of
    the study, the costs are of one machine in one state, which the legs of
    a study resumed over several sessions are not."""
    source = Case(member_dir)
    latest = source.times[-1]
    if scratch.exists():
        shutil.rmtree(scratch)
    case = Case.copy_of(source, scratch)
    shutil.copytree(source / "constant" / "polyMesh", case / "constant" / "polyMesh")
    shutil.copytree(latest, case / latest.name)
    start = float(latest.name)
    control = "system/controlDict"
    case.set(control, "startFrom", "latestTime")
    case.set(control, "endTime", f"{start + window:.12g}")
    # Nothing of the window is kept but its tables
    case.set(control, "writeInterval", f"{10 * window:g}")
    case.run("ldnaFoam", 1, log_name="ldnaFoam.costWindow")
    cpu_per_simulated_s, steps = case.latest_run_cpu_rate()
    return cpu_per_simulated_s / 1e3, steps


def cost_machine() -> str:
    """The processor the cost windows ran on (Linux's /proc/cpuinfo)."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return f"{line.split(':', 1)[1].strip()}, {os.cpu_count()} cores"
    except OSError:
        pass
    return "unknown"


@dataclass
class Study:
    """The members, the reference and the fitted orders of a study."""

    scene: Scene
    members: list[Member]
    reference: dict[str, float]
    reference_name: str
    orders: dict[str, float]
    #: The member the errors are read against (None: the analytical answer)
    reference_member: "Member | None" = None
    #: Outputs for which no error, order or cheapest level is read, each
    #: with its reason, a key of NOT_JUDGED_REASONS (accuracy.json's
    #: ``not_judged``)
    not_judged: dict[str, str] = field(default_factory=dict)
    fusion_unresolved: bool = False
    #: The three finest levels read without a reference (None with fewer)
    three_level: "dict[str, ThreeLevel] | None" = None
    #: Levels whose bead section holds more liquid than the scene's
    #: section_liquid_limit: the section's shape outputs are not judged
    not_frozen: tuple[str, ...] = ()
    #: Levels whose bead section has more of its width topped by cells
    #: coarser than its finest than the scene's coarse_surface_limit: its
    #: refined cells do not enclose the bead, so the shape outputs are not
    #: judged
    not_enclosed: tuple[str, ...] = ()
    #: Simulated time of the serial cost windows [s] and the processor they
    #: ran on (None: the cost is the members' runs')
    cost_window: float | None = None
    cost_machine: str | None = None


#: Why an output of a study is not judged (Study.not_judged), in the
#: order the checks apply
NOT_JUDGED_REASONS = {
    "diagnostic": "a diagnostic of the section, not a result of the weld",
    "lack_of_fusion": "no level fuses by more than the fusion metrics resolve",
    "not_frozen": "a level's section cuts the bead before it froze",
    "not_enclosed": "a level's refined cells do not enclose its bead in the section",
    "zero": "0 at every level and in the reference: nothing to converge",
}


#: Safety factor of the grid convergence index for three grids (Roache 1994;
#: Celik et al., J. Fluids Eng. 130 (2008) 078001)
GCI_SAFETY_FACTOR = 1.25
#: Highest order the index counts: the schemes are second order at best, so a
#: higher observed order is the levels' differences shrinking by chance, not
#: an error bound that small (Roache's advice)
GCI_MAX_ORDER = 2.0


@dataclass(frozen=True)
class ThreeLevel:
    """What the three finest levels say of one output on their own: whether
    their differences shrink (``converging``), change sign
    (``oscillating``) or grow (``diverging``); for converging ones the
    observed order, the output extrapolated to zero cell size and the finest
    level's grid convergence index (its relative error band)."""

    status: str
    order: float = math.nan
    extrapolated: float = math.nan
    gci: float = math.nan


#: Bracket of the observed order the three-level estimate searches
THREE_LEVEL_ORDERS = (1e-6, 50.0)


def three_level_estimate(cells: tuple[float, float, float], values: tuple[float, float, float],
                         scale: float) -> ThreeLevel:
    """Celik et al. (2008)'s three-grid estimate on cell sizes ``cells``
    (finest first) and their outputs ``values``; the index relative to
    ``scale`` (the output's size, as its errors are read).

    The order p is the one for which q0 + C h^p passes through the three
    points: (h3^p - h2^p)/(h2^p - h1^p) = e32/e21 (Celik's equation for
    any refinement ratios), found by bisection.  That ratio grows with p from
    ln(r32)/ln(r21) at p -> 0, so differences of one sign converge only
    above it; below it they shrink more slowly than any positive order
    (``diverging``), and of opposite signs they ``oscillate``."""
    (h1, h2, h3), (q1, q2, q3) = cells, values
    if not (0 < h1 < h2 < h3):
        raise ValueError(f"cell sizes {cells} are not positive, finest first and distinct")
    e21, e32 = q2 - q1, q3 - q2
    if e21 == 0 and e32 == 0:
        return ThreeLevel("unchanged", extrapolated=q1, gci=0.0)
    if e21 == 0:
        return ThreeLevel("converging", order=math.inf, extrapolated=q1, gci=0.0)
    ratio = e32 / e21
    if ratio < 0:
        return ThreeLevel("oscillating")

    def spread(order: float) -> float:
        return (h3**order - h2**order) / (h2**order - h1**order)

    low, high = THREE_LEVEL_ORDERS
    if not ratio > spread(low):
        return ThreeLevel("diverging")
    if ratio >= spread(high):
        order = high
    else:
        for _ in range(200):
            middle = 0.5 * (low + high)
            low, high = (middle, high) if spread(middle) < ratio else (low, middle)
        order = 0.5 * (low + high)
    r21 = h2 / h1
    extrapolated = (r21**order * q1 - q2) / (r21**order - 1)
    counted = min(order, GCI_MAX_ORDER)
    gci = GCI_SAFETY_FACTOR * abs(e21) / scale / (r21**counted - 1) if scale > 0 else math.nan
    return ThreeLevel("converging", order, extrapolated, gci)


def error_scale(scales: dict[str, str | None], outputs: dict[str, float], name: str) -> float:
    """What an error of ``name`` is read against: the output itself in
    ``outputs``, or at least the bead's size in its direction
    (``scales[name]``, an output's name; None: 1)."""
    if name not in scales:
        return abs(outputs.get(name, math.nan))
    scale = 1.0 if scales[name] is None else abs(outputs.get(scales[name], math.nan))
    return max(abs(outputs.get(name, math.nan)), scale)


def evaluate(scene: Scene, members: list[Member], exact: dict[str, float] | None) -> Study:
    """Errors against the exact answer or the finest member, and the observed orders."""
    finest_co = min((m.max_co for m in members if m.max_co is not None), default=None)
    at_finest_co = [m for m in members if m.max_co == finest_co]
    if exact is not None:
        reference, reference_name = exact, "analytical solution"
        fitted = at_finest_co
    else:
        finest = min(at_finest_co, key=lambda m: m.cell_size_mm)
        reference, reference_name = finest.outputs, f"finest run ({finest.name})"
        fitted = [m for m in at_finest_co if m is not finest]
    scales = getattr(scene, "error_scales", {})

    def size(name: str) -> float:
        return error_scale(scales, reference, name)

    fusion_outputs = getattr(scene, "fusion_outputs", ())
    floor = getattr(scene, "fusion_depth_floor", math.nan)
    # NaN (no penetration read) is not below the floor
    fusion_unresolved = exact is None and bool(fusion_outputs) and all(
        abs(outputs.get("penetration", math.nan)) < floor
        for outputs in [reference, *(m.outputs for m in members)])

    # Levels whose section cuts the bead before it froze, or whose share was
    # not measured (NaN: not shown frozen): their shape there need not be
    # the bead's, so no level's shape outputs are compared
    not_frozen = ()
    if hasattr(scene, "section_liquid_limit"):
        not_frozen = tuple(m.name for m in members
                           if not m.outputs.get("section_liquid", math.nan)
                           <= scene.section_liquid_limit)
    # Levels whose bead is topped partly by coarser cells than their finest
    # there, or whose share was not measured: their shape is not read at
    # their resolution
    not_enclosed = ()
    if hasattr(scene, "coarse_surface_limit"):
        not_enclosed = tuple(m.name for m in members
                             if not m.outputs.get("coarse_surface", math.nan)
                             <= scene.coarse_surface_limit)

    def reason_not_judged(name: str) -> str | None:
        if exact is not None or name not in reference:
            return None
        if name in getattr(scene, "diagnostics", ()):
            return "diagnostic"
        if fusion_unresolved and name in fusion_outputs:
            return "lack_of_fusion"
        if not_frozen and name in getattr(scene, "section_shape_outputs", ()):
            return "not_frozen"
        if not_enclosed and name in getattr(scene, "section_shape_outputs", ()):
            return "not_enclosed"
        if reference[name] == 0 and all(m.outputs.get(name) == 0 for m in members):
            return "zero"
        return None

    not_judged = {name: reason for name in scene.outputs_meta
                  if (reason := reason_not_judged(name)) is not None}
    for member in members:
        member.errors = {
            name: abs(value - reference[name]) / size(name)
            if name in reference and name not in not_judged and size(name) > 0
            else math.nan
            for name, value in member.outputs.items()
        }
    orders = {}
    for name in scene.outputs_meta:
        points = [(m.cell_size_mm, m.errors.get(name, math.nan)) for m in fitted]
        points = [(h, e) for h, e in points if e > 0 and math.isfinite(e)]
        if len(points) >= 2 and len({h for h, _ in points}) >= 2:
            h, e = np.log(np.array(points)).T
            orders[name] = float(np.polyfit(h, e, 1)[0])
        else:
            orders[name] = math.nan
    three = None
    by_size = sorted(at_finest_co, key=lambda m: m.cell_size_mm)
    if len(by_size) >= 3 and len({m.cell_size_mm for m in by_size[:3]}) == 3:
        finest3 = by_size[:3]
        three = {}
        for name in scene.outputs_meta:
            values = [m.outputs.get(name, math.nan) for m in finest3]
            if name in not_judged or not all(math.isfinite(v) for v in values):
                continue
            three[name] = three_level_estimate(
                tuple(m.cell_size_mm for m in finest3), tuple(values),
                error_scale(scales, finest3[0].outputs, name))
    return Study(scene, members, reference, reference_name, orders,
                 None if exact is not None else finest, not_judged, fusion_unresolved,
                 three, not_frozen=not_frozen, not_enclosed=not_enclosed)




def error_spread(study: Study, member: Member, name: str) -> float:
    """How far ``member``'s error on ``name`` is known, as a share of the
    output's scale: the ripples of the level and of the reference combined
    (window means: about two standard errors of the difference of their
    four windows' means; 0 without ripples)."""
    finest = study.reference_member
    size = error_scale(getattr(study.scene, "error_scales", {}), study.reference, name)
    spread = math.hypot(member.ripples.get(name, 0.0),
                        0.0 if finest is None else finest.ripples.get(name, 0.0))
    return spread / size if size > 0 else math.nan


def cheapest_levels(study: Study) -> dict[str, dict[str, float | None]]:
    """Per output and error bound, the cheapest level (core-hours per simulated
    second) whose error against the reference is within the bound with its
    spread (``error_spread``): a bead whose window means scatter is within
    5 % only if its error and the scatter together are; None when only the
    reference itself is (a finer level than tested may be needed)."""
    chosen: dict[str, dict[str, float | None]] = {}
    for name in study.scene.outputs_meta:
        chosen[name] = {}
        for bound in ERROR_BOUNDS:
            within = [m for m in study.members
                      if m.outputs is not study.reference
                      and m.errors.get(name, math.nan) + error_spread(study, m, name) <= bound]
            best = min(within, key=lambda m: m.core_seconds_per_ms, default=None)
            chosen[name][f"{round(100 * bound)}%"] = None if best is None else best.level
    return chosen


def write_json(study: Study, path: Path) -> None:
    """Per level its resolution, cost, steadiness and outputs (in the units of
    the table) with their errors; the reference, the orders and the cheapest
    level for each error bound."""
    import json

    meta = study.scene.outputs_meta

    def unit_name(name: str) -> str:
        return name + {"mm": "_mm", "mm2": "_mm2", "deg": "_deg", "K": "_K",
                       "g": "_g"}.get(meta[name][1], "")

    def finite(value: float | None) -> float | None:
        return value if value is not None and math.isfinite(value) else None

    levels = []
    for m in study.members:
        levels.append({
            "level": m.level, "max_co": m.max_co, "cell_mm": m.cell_size_mm, "cells": m.cells,
            "n_procs": m.n_procs, "start_time_s": m.start_time, "end_time_s": m.end_time,
            "started_from": (None if m.started_from is None else
                             {"run": m.started_from[0], "time_s": m.started_from[1]}),
            "core_hours_per_simulated_s": finite(m.core_hours_per_simulated_s),
            # The runs' own cost (over sessions and machines for a resumed
            # study) and the cost window's steps
            "legs_core_hours_per_simulated_s": finite(m.legs_core_seconds_per_ms / 3.6),
            "cost_window_steps": m.window_steps if m.window_core_s_per_ms is not None else None,
            "core_hours_to_steady": m.core_hours_to_steady,
            # With the levels it started from (--sequence)
            "route_core_hours_to_steady": route_core_hours_to_steady(m, study.members),
            "steady": m.steady,
            "first_steady_s": m.first_steady, "verdict": m.verdict,
            **{unit_name(n): finite(m.outputs.get(n, math.nan) * meta[n][2]) for n in meta},
            "errors": {n: finite(m.errors.get(n, math.nan)) for n in meta},
            # Window means (bead scene): the standard deviation of each
            # output's judged windows' means, in its unit, and the fields
            # the judged windows held
            "ripples": {unit_name(n): finite(m.ripples[n] * meta[n][2])
                        for n in meta if n in m.ripples},
            "fields_in_window": m.fields_in_window,
        })
    path.write_text(json.dumps({
        "scene": study.scene.name, "reference": study.reference_name,
        "levels": levels,
        "orders": {n: finite(study.orders.get(n, math.nan)) for n in meta},
        "cheapest_level": cheapest_levels(study),
        # Outputs without error, order or cheapest level, each with its
        # reason (NOT_JUDGED_REASONS)
        "not_judged": dict(study.not_judged),
        "not_judged_reasons": {reason: NOT_JUDGED_REASONS[reason]
                               for reason in sorted(set(study.not_judged.values()))},
        # No level fuses by more than the fusion metrics resolve (penetration
        # below fusion_depth_floor_mm at every level)
        "fusion_unresolved": study.fusion_unresolved,
        "fusion_depth_floor_mm": (1e3 * study.scene.fusion_depth_floor
                                  if hasattr(study.scene, "fusion_depth_floor") else None),
        # Levels whose bead section was not yet frozen (liquid share above
        # the limit): the section's shape outputs are then not judged
        "not_frozen": list(study.not_frozen),
        "section_liquid_limit": getattr(study.scene, "section_liquid_limit", None),
        # Levels whose refined cells did not enclose the section's bead (the
        # share of its width topped by coarser cells above the limit): the
        # shape outputs are then not judged
        "not_enclosed": list(study.not_enclosed),
        "coarse_surface_limit": getattr(study.scene, "coarse_surface_limit", None),
        # The steadiness judge's shortest window of a bead study [s]
        "min_window_s": getattr(study.scene, "min_window", None),
        # Where core_hours_per_simulated_s comes from: a serial window of
        # this length per level, on this processor (null: the runs)
        "cost_window_s": study.cost_window,
        "cost_machine": study.cost_machine,
        # In the output's units; the index relative to the output's size
        "three_level": None if study.three_level is None else {
            n: {"status": t.status, "order": finite(t.order),
                "extrapolated": finite(t.extrapolated * meta[n][2]), "gci": finite(t.gci)}
            for n, t in study.three_level.items()},
    }, indent=2) + "\n")


def write_csv(study: Study, path: Path) -> None:
    """One row per member: resolution, cost, each output and its error."""
    names = list(study.scene.outputs_meta)
    with path.open("w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["level", "max_co", "cell_size_mm", "cells", "n_procs", "steps",
                         "wall_time_s", "core_s_per_sim_ms"]
                        + [f"{n}_{study.scene.outputs_meta[n][1]}" for n in names]
                        + [f"{n}_rel_error" for n in names]
                        + [f"{n}_ripple_{study.scene.outputs_meta[n][1]}" for n in names])
        for m in study.members:
            writer.writerow(
                [meshing.level_name(m.level), "" if m.max_co is None else f"{m.max_co:g}",
                 f"{m.cell_size_mm:.6g}", m.cells, m.n_procs, m.steps, f"{m.wall_time:.6g}",
                 f"{m.core_seconds_per_ms:.6g}"]
                + [f"{m.outputs.get(n, math.nan) * study.scene.outputs_meta[n][2]:.8g}"
                   for n in names]
                + [f"{m.errors.get(n, math.nan):.6g}" for n in names]
                + [f"{m.ripples.get(n, math.nan) * study.scene.outputs_meta[n][2]:.6g}"
                   for n in names])


def markdown(study: Study) -> str:
    """The study as a Markdown table with the reference and the fitted orders."""
    meta = study.scene.outputs_meta
    names = list(meta)
    head = ["level", "maxCo", "cell [mm]", "cells", "steps", "wall [s]", "core-s/ms"] + \
        [f"{meta[n][0]} [{meta[n][1]}] (error)" for n in names]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for m in study.members:
        cells = [meshing.level_name(m.level), "-" if m.max_co is None else f"{m.max_co:g}",
                 f"{m.cell_size_mm:.3g}", str(m.cells), str(m.steps), f"{m.wall_time:.1f}",
                 f"{m.core_seconds_per_ms:.3g}"]
        for n in names:
            value = m.outputs.get(n, math.nan) * meta[n][2]
            error = m.errors.get(n, math.nan)
            text = f"{value:.4g}"
            if n in m.ripples:
                text += f" ± {m.ripples[n] * meta[n][2]:.2g}"
            cells.append(f"{text} ({100 * error:.2f} %)" if math.isfinite(error) else text)
        lines.append("| " + " | ".join(cells) + " |")
    reference = ", ".join(f"{meta[n][0]} {study.reference[n] * meta[n][2]:.5g} {meta[n][1]}"
                          for n in names if n in study.reference)
    orders = ", ".join(f"{meta[n][0]} {study.orders[n]:.2f}" for n in names
                       if math.isfinite(study.orders.get(n, math.nan)))
    lines += ["", f"Errors are relative to the {study.reference_name}: {reference}.",
              f"Observed order of convergence (slope of log error over log cell size): "
              f"{orders or 'not enough non-zero errors to fit'}."]
    if any(m.ripples for m in study.members):
        lines += ["", f"Each value is its mean over the {STEADY_WINDOWS} judged windows; ± its "
                  "ripple, the standard deviation of its windows' means (the mean's standard "
                  f"error is that over sqrt({STEADY_WINDOWS}); an error below the ripples "
                  "of the two levels compared, about two standard errors of their "
                  "difference, is not resolved).  The "
                  "wetting angle, body width and gas film are means of the fields written in "
                  "the windows (" + ", ".join(
                      f"{m.name} {m.fields_in_window}" for m in study.members
                      if m.fields_in_window is not None) + " fields)."]
    if any(m.steady is not None for m in study.members):
        window = getattr(study.scene, "min_window", STEADY_MIN_WINDOW)
        lines += ["", f"Quasi-steady (`ldna steady`, windows of at least {window:g} s): " + "; ".join(
            f"{m.name} {'yes' if m.steady else 'no (' + m.verdict + ')'}"
            + (f", first at {m.first_steady:.4g} s ({m.core_hours_to_steady:.2f} core-h "
               f"from {m.start_time:g} s)" if m.first_steady is not None else "")
            + f", {m.core_hours_per_simulated_s:.2f} core-h per simulated s"
            for m in study.members) + "."]
    if any(m.started_from is not None for m in study.members):
        names = {m.name for m in study.members}

        def route(m: Member) -> str:
            if m.started_from is None or m.started_from[0] not in names:
                return ""
            hours = route_core_hours_to_steady(m, study.members)
            return ("" if hours is None else
                    f" ({hours:.2f} core-h to quasi-steady with the levels before)")

        lines += ["", "Started from (mapped onto each level's mesh): " + "; ".join(
            f"{m.name} from {m.started_from[0]} at {m.started_from[1]:g} s{route(m)}"
            for m in study.members if m.started_from is not None) + "."]
    cheapest = cheapest_levels(study)
    finest = study.reference_member
    scales = getattr(study.scene, "error_scales", {})

    def reference_ripple(name: str) -> str:
        # How well the reference itself is known, as its errors are read
        if finest is None or name not in finest.ripples:
            return ""
        size = error_scale(scales, study.reference, name)
        return f" (its ripple {100 * finest.ripples[name] / size:.2g} %)" if size > 0 else ""

    spread_note = (" (its error and the two levels' ripples together within the bound)"
                   if any(m.ripples for m in study.members) else "")
    lines += ["", f"Cheapest level within 5 % / 10 % of the reference{spread_note}: " + "; ".join(
        f"{meta[n][0]} {_level_or_finer(c['5%'])} / {_level_or_finer(c['10%'])}"
        + reference_ripple(n)
        for n, c in cheapest.items() if n not in study.not_judged) + "."]
    if study.three_level:
        lines += ["", "The three finest levels on their own (Celik et al. 2008; the grid "
                  f"convergence index with safety factor {GCI_SAFETY_FACTOR:g}, orders above "
                  f"{GCI_MAX_ORDER:g} counted as {GCI_MAX_ORDER:g}): " + "; ".join(
                      f"{meta[n][0]} {_three_level_text(t, meta[n])}"
                      for n, t in study.three_level.items()) + "."]
    if study.fusion_unresolved:
        floor = 1e3 * study.scene.fusion_depth_floor
        lines += ["", f"No level fuses its substrate by more than the fusion metrics resolve "
                  f"(penetration below {floor:g} mm, their tested depth accuracy, at every "
                  "level): lack of fusion at every level, so the fusion outputs are not "
                  "judged (no error, order or cheapest level; their values are in the "
                  "table): " + ", ".join(meta[n][0] for n, reason in study.not_judged.items()
                                        if reason == "lack_of_fusion") + "."]
    shape = getattr(study.scene, "section_shape_outputs", ())
    if "section_liquid" in meta:
        limit = study.scene.section_liquid_limit
        shares = "; ".join(f"{m.name} {_percent(m.outputs.get('section_liquid', math.nan))}"
                           for m in study.members)
        lines += ["", f"Liquid share of the bead section (its metal still liquid, mean of "
                  f"the fields of the judged windows): {shares}."]
        if study.not_frozen:
            lines += [f"Above {100 * limit:g} % (the finest error bound) the section cuts the "
                      f"bead before it froze, so its shape is not the bead's final one, and a "
                      f"share not measured does not show it frozen: at "
                      f"{', '.join(study.not_frozen)}.  The section's shape outputs are not "
                      "judged (no error, order or cheapest level; their values are in the "
                      "table): " + ", ".join(meta[n][0] for n in shape if n in meta) + "."]
    if "coarse_surface" in meta:
        limit = study.scene.coarse_surface_limit
        shares = "; ".join(f"{m.name} {_percent(m.outputs.get('coarse_surface', math.nan))}"
                           for m in study.members)
        lines += ["", f"Share of the bead section's width topped by cells coarser than its "
                  f"finest (out of the refined cells; mean of the fields of the judged "
                  f"windows): {shares}."]
        if study.not_enclosed:
            lines += [f"Above {100 * limit:g} % (the finest error bound) the level's shape is "
                      f"not read at its own resolution, and a share not measured does not "
                      f"show it enclosed: at {', '.join(study.not_enclosed)}.  The section's "
                      "shape outputs are not judged (no error, order or cheapest level; their "
                      "values are in the table): "
                      + ", ".join(meta[n][0] for n in shape if n in meta) + "."]
    zero = [n for n, reason in study.not_judged.items() if reason == "zero"]
    if zero:
        lines += ["", "0 at every level, so not judged (no error, order or cheapest "
                  "level): " + ", ".join(meta[n][0] for n in zero) + "."]
    if study.cost_window is not None:
        lines += ["", f"Cost (core-s/ms, core-h per simulated s): a serial window of "
                  f"{study.cost_window:g} s from each level's latest time, all on "
                  f"{study.cost_machine}; the runs' own: " + "; ".join(
                      f"{m.name} {m.legs_core_seconds_per_ms / 3.6:.2f} core-h per simulated s"
                      for m in study.members) + " (a resumed study's legs may have run on "
                  "other machines, beside other work)."]
    return "\n".join(lines) + "\n"


def _percent(share: float) -> str:
    return f"{100 * share:.3g} %" if math.isfinite(share) else "not measured"


def _three_level_text(estimate: ThreeLevel, meta: tuple[str, str, float]) -> str:
    if estimate.status != "converging":
        return estimate.status
    return (f"order {estimate.order:.2f}, extrapolated {estimate.extrapolated * meta[2]:.4g} "
            f"{meta[1]}, finest level within {100 * estimate.gci:.2g} %")


def _level_or_finer(level: float | None) -> str:
    return "finer than tested" if level is None else f"level {meshing.level_name(level)}"


def plot(study: Study, path: Path) -> None:
    """Log-log error against core-hours per simulated second."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    meta = study.scene.outputs_meta
    figure, axes = plt.subplots(figsize=(7.5, 7))
    # More outputs than the default cycle's ten colours
    colours = plt.get_cmap("tab20")
    plotted: set[int] = set()
    for index, name in enumerate(meta):
        points = sorted((m.core_hours_per_simulated_s, m.errors.get(name, math.nan), id(m), m)
                        for m in study.members if m.errors.get(name, 0) > 0)
        if not points:
            continue
        cost, error, _, members = zip(*points)
        plotted.update(id(m) for m in members)
        order = study.orders.get(name, math.nan)
        three = (study.three_level or {}).get(name)
        # The ripples of the level and the reference, as the error is read
        spread = [error_spread(study, m, name) for m in members]
        label = (meta[name][0] + (f" (order {order:.2f})" if math.isfinite(order) else "")
                 + ("" if three is None else
                    f", 3 finest: GCI {100 * three.gci:.2g} %" if three.status == "converging"
                    else f", 3 finest: {three.status}"))
        colour = colours(index % colours.N)
        # An error within the ripples is not resolved: a hollow marker with
        # its upper bar only (a log axis has no zero to draw the lower to)
        resolved = [e > d for e, d in zip(error, spread)]
        lower = [d if r else 0.0 for d, r in zip(spread, resolved)]
        axes.errorbar(cost, error, yerr=[lower, spread], fmt="-", capsize=3, label=label,
                      color=colour)
        for filled in (True, False):
            chosen = [(c, e) for c, e, r in zip(cost, error, resolved) if r == filled]
            if chosen:
                axes.plot(*zip(*chosen), "o", color=colour,
                          markerfacecolor=colour if filled else "white")
    # Each level once, at its cost: its name and cell size
    for m in study.members:
        if id(m) in plotted:
            axes.axvline(m.core_hours_per_simulated_s, color="lightgrey", lw=0.8, zorder=0)
            axes.annotate(f"{m.name}, {m.cell_size_mm:.2g} mm",
                          (m.core_hours_per_simulated_s, 0.02), xycoords=("data", "axes fraction"),
                          rotation=90, va="bottom", ha="right", fontsize=7, color="dimgrey")
    # Where the reference run stands when it is one of the members
    reference = study.reference_member
    if reference is not None and math.isfinite(reference.core_hours_per_simulated_s):
        axes.axvline(reference.core_hours_per_simulated_s, color="grey", ls=":")
        axes.annotate(f"reference: {reference.name}, {reference.cell_size_mm:.2g} mm",
                      (reference.core_hours_per_simulated_s, 0.02),
                      xycoords=("data", "axes fraction"), rotation=90, fontsize=7,
                      xytext=(-10, 0), textcoords="offset points", color="grey")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("core-hours per simulated second")
    axes.set_ylabel(f"relative error against the {study.reference_name}")
    axes.set_title(f"{study.scene.name} scene: accuracy against cost")
    axes.grid(True, which="both", alpha=0.3)
    if axes.get_legend_handles_labels()[0]:
        axes.plot([], [], "o", color="grey", markerfacecolor="white",
                  label="hollow: error within the two levels' ripples (not resolved)")
        axes.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=1)
    else:
        axes.text(0.5, 0.5, "no errors to plot yet", transform=axes.transAxes, ha="center")
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def run_study(template: Path, out: Path, scene: Scene | None = None,
              levels: list[float] | None = None, max_co: list[float] | None = None,
              end_time: float | None = None, n_procs: int = 1,
              start: StartState | None = None,
              resume: bool = False,
              cost_window: float | None = None,
              sequence: bool = False,
              settings: "list[Parameter] | None" = None) -> tuple[Study, list[Path]]:
    """Run the members, evaluate them and write CSV, Markdown and PNG into ``out``.

    ``settings`` (entries of one value each, as ``ldna study --set`` parses
    them) are set in every member's copy of the template: a longer process
    zone, a bead section farther behind the wires, ...

    With ``start`` every member starts from that developed state, mapped onto
    its mesh, and runs to ``end_time``: the finer levels then cost a window of
    the process (droplet impacts into a developed pool), not the whole run.
    With ``sequence`` (and ``start``) only the first level starts from it;
    each later level starts from the latest time of the level before it (for
    the bead scene its quasi-steady weld), mapped onto its own mesh, and may
    run as long from its start as the first may (``end_time`` - start): a
    finer level then relaxes from the nearest resolution's weld, not from
    the coarsest one's.
    With ``cost_window`` each member's cost is then measured by a serial run
    of that many simulated seconds from its latest time
    (:func:`measure_cost_window`, in ``out/cost``), all levels in this call.
    """
    template, out = Path(template), Path(out)
    scene = scene or detect_scene(template)
    levels = list(levels or scene.default_levels)
    if len(levels) < 2:
        raise ValueError("give at least two levels")
    out.mkdir(parents=True, exist_ok=True)
    if sequence and start is None:
        raise ValueError("sequenced levels start from the level before, the first from a "
                         "developed state: give start")
    members = []
    for co in (max_co or [None]):
        previous = None
        for level in levels:
            member = Member(level=level, max_co=co, cell_size_mm=math.nan)
            directory = out / "members" / member.name
            level_start, level_end = start, end_time
            if sequence and previous is not None:
                level_start = StartState(out / "members" / previous.name, previous.end_time)
                if end_time is not None:
                    # As long from its own start (a resumed member's may
                    # be another: it ran before)
                    began = resumed_start_time(directory) if resume else None
                    level_end = (level_start.time if began is None else began) + (
                        end_time - start.time)
                if previous.steady is False:
                    print(f"  {previous.name} was not judged quasi-steady: {member.name} "
                          f"starts from its latest time all the same", flush=True)
            print(f"{scene.name}: running {member.name} ...", flush=True)
            run_member(template, directory, scene, member, level_end, n_procs, level_start,
                       resume, settings)
            previous = member
            print(f"  {member.cells} cells, {member.steps} steps, {member.wall_time:.1f} s "
                  f"wall, {member.core_seconds_per_ms:.3g} core-s per simulated ms", flush=True)
            members.append(member)
    machine = None
    if cost_window is not None:
        machine = cost_machine()
        for member in members:
            print(f"{scene.name}: cost window of {cost_window:g} s from {member.name}'s "
                  f"latest time, serial ...", flush=True)
            member.window_core_s_per_ms, member.window_steps = measure_cost_window(
                out / "members" / member.name, out / "cost" / member.name, cost_window)
            print(f"  {member.window_steps} steps, {member.window_core_s_per_ms:.3g} core-s "
                  f"per simulated ms ({machine})", flush=True)
    exact = scene.exact(Case(out / "members" / members[0].name), members[0].end_time)
    study = evaluate(scene, members, exact)
    study.cost_window, study.cost_machine = cost_window, machine
    paths = [out / "accuracy.csv", out / "accuracy.md", out / "accuracy.png",
             out / "accuracy.json"]
    write_csv(study, paths[0])
    paths[1].write_text(markdown(study))
    plot(study, paths[2])
    write_json(study, paths[3])
    return study, paths
