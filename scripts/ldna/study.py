"""Parameter studies of an ldnaFoam case template (``ldna study``).

A study copies a case template once per member of a parameter grid into a
study folder, sets the member's values, runs each member with the
template's ``Allrun`` (serially or on MPI ranks), shows a progress bar, and
collects parameters, run time and the bead metrics of each member's last
``meltPoolMetrics`` row into one CSV.  ``results.json`` holds per member
what ``ldna post --json`` reports at its last time (with its pictures in the
member's ``pictures/``) and ``ldna steady``'s verdict; ``sections.png`` the
members' transverse sections through the laser's target side by side, on
one temperature scale.

A study can start every member from the state of a steady run of the scene
(``--start-from RUN [--start-time T]``, the template's ``Allrun -start-from``):
each member then relaxes from a neighbouring weld instead of building its
bead and heating its substrate from nothing, which takes seconds of welding
(docs/validation/steady-start.md).

``--paired`` pairs the axes' values (the i-th member takes the i-th value
of each) instead of spanning their grid, and ``--jobs N`` runs N members at
a time (on a 2-core machine two serial members use both cores without the
ranks' exchanges).

Runs longer than a session resume: ``ldna study ... --resume`` with the same
``--set`` values keeps the members that exist, continues each from its
latest written time (``Allrun -resume``; ``--end-time`` may be raised) and
only collects the finished ones.

A parameter is named like the entry it sets:

- ``laserPower``, ``weldingSpeed``, ``wireFeedSpeed``,
  ``oscillationAmplitude``, ... : an entry of ``system/caseParameters``
  (the template's knobs; edited in place, comments kept);
- ``FILE:ENTRY``, e.g. ``constant/fvOptions:laser/absorptionModel`` or
  ``system/controlDict:maxCo``: any dictionary entry the file has (edited
  in place as well; an entry it does not have is an error, not added).
"""
from __future__ import annotations

import csv
import itertools
import json
import math
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .case import BALANCES, Case
from .post import BeadMetrics, post_process, read_function_object_metrics, summary
from .steady import DomainBalance, case_table, first_steady, judge

#: Dictionary of the template's knobs, for parameters without a file
CASE_PARAMETERS = "system/caseParameters"
#: Seconds between progress-bar updates
POLL_SECONDS = 1.0
#: Characters of the progress bar
BAR_WIDTH = 30


@dataclass
class Parameter:
    """One axis of the grid: a dictionary entry and its values."""

    file: str
    entry: str
    values: list[str]

    @property
    def name(self) -> str:
        """The name the user gave (column of the CSV)."""
        return self.entry if self.file == CASE_PARAMETERS else f"{self.file}:{self.entry}"

    @classmethod
    def parse(cls, text: str) -> "Parameter":
        """Parse ``NAME=v1,v2,...`` with NAME an entry or ``FILE:ENTRY``."""
        if "=" not in text:
            raise ValueError(f"parameter '{text}': expected NAME=value1,value2,...")
        name, values = text.split("=", 1)
        file, entry = name.split(":", 1) if ":" in name else (CASE_PARAMETERS, name)
        value_list = [v.strip() for v in values.split(",") if v.strip()]
        if not entry or not value_list:
            raise ValueError(f"parameter '{text}': no entry or no values")
        return cls(file, entry, value_list)


@dataclass
class Member:
    """One case of the study."""

    name: str
    values: dict[str, str]
    path: Path
    status: str = "pending"
    error: str = ""
    wall_time: float = 0.0
    metrics: dict[str, float] = field(default_factory=dict)
    #: The solver's last time [s] (the metrics' row may be a few steps before)
    end_time: float | None = None
    #: Kept from an earlier run of the study (--resume)
    resumed: bool = False
    #: What ``ldna post --json`` reports at the member's last time, and
    #: whether ``ldna steady`` judges its bead quasi-steady
    post: dict = field(default_factory=dict)
    steady: bool | None = None
    #: The last judged windows' means of the section's metrics [SI]
    window_means: dict[str, float] = field(default_factory=dict)
    #: The first time ``ldna steady`` judged the member quasi-steady [s]
    first_steady: float | None = None


def latest_time(case: Path) -> float:
    """The latest time a case has written (its first rank's when decomposed)."""
    case = Path(case)
    times = Case(case).times
    if (case / "processor0").is_dir():
        times += Case(case / "processor0").times
    return max((float(t.name) for t in times), default=0.0)


def make_members(template: Path, study_dir: Path, parameters: list[Parameter],
                 end_time: float | None = None, n_procs: int = 1,
                 resume: bool = False, paired: bool = False) -> list[Member]:
    """Copy the template once per grid point (``paired``: once per position
    of the axes' equally long value lists) and set each member's values
    (with ``resume``, keep a member that exists and only set its end time)."""
    template, study_dir = Path(template), Path(study_dir)
    if not (template / CASE_PARAMETERS).exists() and any(
            p.file == CASE_PARAMETERS for p in parameters):
        raise FileNotFoundError(f"{template} has no {CASE_PARAMETERS}")
    study_dir.mkdir(parents=True, exist_ok=True)
    members = []
    if paired:
        lengths = {len(p.values) for p in parameters}
        if len(lengths) > 1:
            raise ValueError("paired axes need as many values each: "
                             + ", ".join(f"{p.name} has {len(p.values)}" for p in parameters))
        grid = list(zip(*(p.values for p in parameters)))
    else:
        grid = list(itertools.product(*(p.values for p in parameters)))
    for index, combination in enumerate(grid):
        name = f"member{index:03d}"
        path = study_dir / name
        values = {p.name: v for p, v in zip(parameters, combination)}
        if resume and (path / "system" / "controlDict").is_file():
            if end_time is not None:
                Case(path).set("system/controlDict", "endTime", f"{end_time:g}")
            members.append(Member(name, values, path, resumed=True))
            continue
        if path.exists():
            shutil.rmtree(path)
        case = Case.copy_of(template, path)
        # Knobs first: entries of other files may expand them
        ordered = sorted(zip(parameters, combination), key=lambda pv: pv[0].file != CASE_PARAMETERS)
        for parameter, value in ordered:
            case.set(parameter.file, parameter.entry, value)
        if end_time is not None:
            case.set("system/controlDict", "endTime", f"{end_time:g}")
        if n_procs > 1:
            case.set_ranks(n_procs)
        members.append(Member(name, values, path))
    return members


def _leg_fraction(case: Path, end_time: float) -> float:
    """How far the running leg of a member is, from its start (0, the time
    it started from or resumed at) to its end time, by the solver's balance
    table (0 before the solver starts)."""
    try:
        times = Case(case).latest_table(*BALANCES)["Time"]
    except (FileNotFoundError, IndexError, ValueError):
        return 0.0
    if len(times) < 2 or not end_time > times[0]:
        return 0.0
    return float(min(1.0, (times[-1] - times[0]) / (end_time - times[0])))


def _progress(done: float, total: int, label: str, started: float) -> None:
    """Draw the progress bar on stderr."""
    filled = int(BAR_WIDTH * done / total)
    elapsed = time.time() - started
    minutes, seconds = divmod(int(elapsed), 60)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (BAR_WIDTH - filled)}] "
                     f"{done:5.2f}/{total} members  {minutes:d}:{seconds:02d}  {label[:60]:<60}")
    sys.stderr.flush()


def finished(case: Path, end_time: float) -> bool:
    """Whether a case has written its end time: the solver stops at the
    first step that ends within half a step of it (its balance table gives
    the last step)."""
    try:
        times = Case(case).latest_table(*BALANCES)["Time"]
        last_step = float(times[-1] - times[-2]) if len(times) > 1 else 0.0
    except (FileNotFoundError, IndexError, ValueError, KeyError):
        last_step = 0.0
    return latest_time(case) >= end_time - 0.5 * last_step - 1e-9 * end_time


@dataclass(frozen=True)
class StartFrom:
    """The state every member starts from: a run of the scene and its
    reconstructed time (None: its latest)."""

    run: Path
    time: float | None = None

    def allrun_options(self) -> str:
        return (f" -start-from '{self.run.resolve()}'"
                + ("" if self.time is None else f" -start-time {self.time:g}"))


@dataclass
class _Running:
    """A member whose Allrun runs."""

    member: Member
    process: subprocess.Popen
    begin: float
    end_time: float


def _label(member: Member) -> str:
    return f"{member.name} " + " ".join(f"{k}={v}" for k, v in member.values.items())


def launch_member(member: Member, parallel: bool,
                  start: StartFrom | None = None) -> _Running | None:
    """Start one member's Allrun (or its continuation); None if it has
    already reached its end time."""
    end_time = Case(member.path).scalar("system/controlDict", "endTime")
    if member.resumed and finished(member.path, end_time):
        return None
    command = ("./Allrun" + (" -parallel" if parallel else "")
               + (" -resume" if member.resumed else
                  start.allrun_options() if start else ""))
    process = Case(member.path).start(command, "Allrun", append=member.resumed)
    return _Running(member, process, time.time(), end_time)


def finish_member(member: Member, returncode: int, wall_time: float) -> None:
    """Judge a member whose Allrun ended and read its metrics."""
    end_time = Case(member.path).scalar("system/controlDict", "endTime")
    member.wall_time = wall_time
    solver_log = member.path / "log.ldnaFoam"
    log_text = solver_log.read_text(errors="replace") if solver_log.exists() else ""
    member.status = ("done" if returncode == 0 and finished(member.path, end_time)
                     else "failed")
    if member.status == "failed":
        member.error = failure_line(log_text or (member.path / "log.Allrun").read_text(
            errors="replace"))
    if member.status == "done":
        member.end_time = float(Case(member.path).balances()["time"][-1])
        row = read_function_object_metrics(member.path)[-1]
        member.metrics = {"time": float(row[0]),
                          **dict(zip(BeadMetrics.FUNCTION_OBJECT_COLUMNS, map(float, row[1:])))}
        collect_post(member)


def run_members(members: list[Member], parallel: bool, jobs: int = 1,
                start: StartFrom | None = None) -> None:
    """Run the members, ``jobs`` at a time, with one progress bar."""
    pending = list(members)
    running: list[_Running] = []
    done = 0
    started = time.time()
    while pending or running:
        while pending and len(running) < jobs:
            member = pending.pop(0)
            launched = launch_member(member, parallel, start)
            if launched is None:
                finish_member(member, 0, 0.0)
                done += 1
            else:
                running.append(launched)
        for run in list(running):
            if run.process.poll() is None:
                continue
            finish_member(run.member, run.process.returncode, time.time() - run.begin)
            running.remove(run)
            done += 1
        fractions = sum(_leg_fraction(r.member.path, r.end_time) for r in running)
        _progress(done + fractions, len(members),
                  " | ".join(_label(r.member) for r in running), started)
        if running:
            time.sleep(POLL_SECONDS)


def collect_post(member: Member) -> None:
    """``ldna post`` (pictures, --json figures) and ``ldna steady`` of a finished member.

    A member whose bead cannot be judged yet (too short a run) is not steady.
    """
    result, _, time_read = post_process(member.path)
    member.post = summary(member.path, result, time_read)
    try:
        # The tables read once for the verdict and the first steady time
        times, table, arrival = case_table(member.path)
        balance = DomainBalance.of(member.path)
        verdict = judge(times, table, arrival, balance=balance)
        member.steady = verdict.steady
        member.window_means = {name: m.mean for name, m in verdict.metrics.items()}
        member.first_steady = first_steady(times, table, arrival, balance=balance)
    except (ValueError, IndexError):
        member.steady = False


#: The process parameters every run records (caseParameters entry -> key,
#: factor from the entry's unit)
PROCESS_PARAMETERS = {"laserPower": ("laser_power_W", 1.0),
                      "oscillationAmplitude": ("oscillation_amplitude_mm", 1e3),
                      "weldingSpeed": ("welding_speed_mm_per_s", 1e3),
                      "wireFeedSpeed": ("wire_feed_speed_m_per_s", 1.0)}


def process_parameters(case: Path) -> dict[str, float]:
    """The member's process parameters as its caseParameters hold them."""
    values = {}
    for entry, (key, factor) in PROCESS_PARAMETERS.items():
        try:
            values[key] = factor * Case(case).scalar(CASE_PARAMETERS, entry)
        except (KeyError, ValueError, FileNotFoundError):
            continue
    return values


def _cropped(image: np.ndarray) -> np.ndarray:
    """The picture without its white margins."""
    ink = (image[..., :3] < 0.98).any(axis=2)
    rows, columns = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    if not rows.size:
        return image
    return image[rows[0]:rows[-1] + 1, columns[0]:columns[-1] + 1]


def _laser_target(case: Path) -> float | None:
    """Where the laser aims along the weld [m] (the wires' midpoint plus its
    offset), or None for a template without those knobs (its bead section)."""
    try:
        return 1e-3 * (Case(case).scalar(CASE_PARAMETERS, "processPosition")
                       + Case(case).scalar(CASE_PARAMETERS, "laserOffset"))
    except (KeyError, ValueError, FileNotFoundError):
        return None


def write_sections(members: list[Member], path: Path, at_bead: bool = False) -> Path | None:
    """The finished members' transverse sections side by side (fusion line,
    free surface, temperature) through the laser's target (the wires'
    midpoint plus the laser's offset: where the pool forms and the laser
    acts, so a member's own process shows within its run), or with
    ``at_bead`` through the bead section (where the bead has solidified; it
    holds a member's own bead once that has travelled there), drawn again on
    one temperature scale: from the lowest ambient to the hottest member's
    peak metal temperature."""
    done = [m for m in members if m.status == "done" and m.post]
    if not done:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        low = min(Case(m.path).scalar(CASE_PARAMETERS, "ambientTemperature") for m in done)
    except (KeyError, ValueError, FileNotFoundError):
        # A template without the knob: from absolute zero
        low = 0.0
    high = max(m.post["peak_metal_temperature_K"] for m in done)
    columns = min(3, len(done))
    rows = math.ceil(len(done) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(6 * columns, 4 * rows), squeeze=False)
    for axis in axes.flat:
        axis.axis("off")
    for axis, member in zip(axes.flat, done):
        where = (member.post["bead_section_mm"] * 1e-3 if at_bead
                 else _laser_target(member.path))
        _, pictures, _ = post_process(member.path, member.path / "pictures" /
                                      ("bead-section" if at_bead else "laser-target"),
                                      bead_section=where, temperature_range=(low, high))
        transverse = next(p for p in pictures if p.name == "transverse.png")
        axis.imshow(_cropped(plt.imread(transverse)))
        figures = (f"bead {member.post['bead_width_mm']:.1f} x "
                   f"{member.post['bead_height_mm']:.2f} mm, wetting angle "
                   f"{member.post['wetting_angle_deg']:.0f} deg" if at_bead else
                   f"pool {member.post['pool_length_mm']:.1f} x "
                   f"{member.post['pool_width_mm']:.1f} mm, substrate surface at most "
                   f"{member.post['peak_surface_temperature_K']:.0f} K")
        axis.set_title(" ".join(f"{k}={v}" for k, v in member.values.items())
                       + f"\n{figures}, bonded {member.post['bonded_width_mm']:.1f} mm",
                       fontsize=10)
    where_name = "bead section" if at_bead else "laser's target"
    figure.suptitle(f"Through the {where_name} at each member's last time; T {low:g}-"
                    f"{high:.0f} K in all", fontsize=11)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path


def write_json(members: list[Member], path: Path) -> Path:
    """``{"runs": [...]}``: per member its values, status, end time, verdict and post figures."""
    runs = []
    for member in members:
        post = {key: (None if isinstance(value, float) and math.isnan(value) else value)
                for key, value in member.post.items()}
        runs.append({"member": member.name, **member.values,
                     **process_parameters(member.path), "status": member.status,
                     "error": member.error, "end_time_s": member.end_time,
                     "wall_time_s": member.wall_time, "steady": member.steady,
                     "first_steady_s": member.first_steady,
                     "window_means": member.window_means, **post})
    path.write_text(json.dumps({"runs": runs}, indent=2) + "\n", encoding="utf-8")
    return path


#: The rank prefix of a parallel run's error lines ("[1] --> FOAM FATAL ...")
RANK_PREFIX = re.compile(r"^\[\d+\]\s?")


def failure_line(log_text: str) -> str:
    """The line that says why a run stopped: the first of its FOAM FATAL error's
    message (on any rank of a parallel run, not MPI's abort notice after
    it), else its last non-empty line."""
    lines = [RANK_PREFIX.sub("", line).strip() for line in log_text.splitlines()]
    lines = [line for line in lines if line]
    for i, line in enumerate(lines):
        if line.startswith("--> FOAM FATAL") and i + 1 < len(lines):
            return lines[i + 1]
    return lines[-1] if lines else "no output"


def write_csv(members: list[Member], path: Path) -> Path:
    """One row per member: name, parameter values, status, error, wall time, metrics."""
    parameter_names = list(members[0].values) if members else []
    metric_names = ["time", *BeadMetrics.FUNCTION_OBJECT_COLUMNS]
    with open(path, "w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream)
        writer.writerow(["member", *parameter_names, "status", "error", "wall_time_s",
                         *metric_names])
        for member in members:
            writer.writerow([member.name, *(member.values[n] for n in parameter_names),
                             member.status, member.error, f"{member.wall_time:.2f}",
                             *(f"{member.metrics[m]:.9g}" if m in member.metrics else ""
                               for m in metric_names)])
    return path


def run_study(template: Path, study_dir: Path, parameters: list[Parameter],
              end_time: float | None = None, n_procs: int = 1,
              resume: bool = False, start: StartFrom | None = None,
              paired: bool = False, jobs: int = 1) -> tuple[list[Member], Path]:
    """Make (or keep, with ``resume``), run and collect a study; returns the
    members and the CSV path (results.json beside it).  ``start``: the state
    every new member starts from; ``paired``: the axes' values go together
    (one member per position) instead of spanning a grid; ``jobs``: members
    run at a time."""
    members = make_members(template, study_dir, parameters, end_time, n_procs, resume,
                           paired)
    run_members(members, n_procs > 1, jobs, start)
    sys.stderr.write("\n")
    write_json(members, Path(study_dir) / "results.json")
    write_sections(members, Path(study_dir) / "sections.png")
    write_sections(members, Path(study_dir) / "bead-sections.png", at_bead=True)
    return members, write_csv(members, Path(study_dir) / "results.csv")
