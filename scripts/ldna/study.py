"""Parameter studies of an ldnaFoam case template (``ldna study``).

A study copies a case template once per member of a parameter grid into a
study folder, sets the member's values, runs each member with the
template's ``Allrun`` (serially or on MPI ranks), shows a progress bar, and
collects parameters, run time and the bead metrics of each member's last
``meltPoolMetrics`` row into one CSV.

A parameter is named like the entry it sets:

- ``laserPower``, ``weldingSpeed``, ``wireFeedSpeed``,
  ``oscillationAmplitude``, ... : an entry of ``system/caseParameters``
  (the template's knobs; edited in place, comments kept);
- ``FILE:ENTRY``, e.g. ``constant/fvOptions:laser/absorptionModel`` or
  ``system/controlDict:maxCo``: any dictionary entry, set with OpenFOAM's
  ``foamDictionary`` (which writes the file with its macros expanded).
"""
from __future__ import annotations

import csv
import itertools
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from .case import Case
from .foamcase import BALANCES, ENV_SCRIPT
from .post import BeadMetrics, read_function_object_metrics

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


def make_members(template: Path, study_dir: Path, parameters: list[Parameter],
                 end_time: float | None = None, n_procs: int = 1) -> list[Member]:
    """Copy the template once per grid point and set each member's values."""
    template, study_dir = Path(template), Path(study_dir)
    if not (template / CASE_PARAMETERS).exists() and any(
            p.file == CASE_PARAMETERS for p in parameters):
        raise FileNotFoundError(f"{template} has no {CASE_PARAMETERS}")
    study_dir.mkdir(parents=True, exist_ok=True)
    members = []
    grid = list(itertools.product(*(p.values for p in parameters)))
    for index, combination in enumerate(grid):
        name = f"member{index:03d}"
        path = study_dir / name
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
            case.set("system/decomposeParDict", "numberOfSubdomains", str(n_procs))
            case.set("system/decomposeParDict", "coeffs/n", f"({n_procs} 1 1)")
        members.append(Member(name, {p.name: v for p, v in zip(parameters, combination)}, path))
    return members


def _simulated_time(case: Path) -> float:
    """Latest time of the solver's balance table (0 before the run starts)."""
    try:
        times = Case(case).latest_table(*BALANCES)["Time"]
    except (FileNotFoundError, IndexError, ValueError):
        return 0.0
    return float(times[-1]) if len(times) else 0.0


def _progress(done: float, total: int, label: str, started: float) -> None:
    """Draw the progress bar on stderr."""
    filled = int(BAR_WIDTH * done / total)
    elapsed = time.time() - started
    minutes, seconds = divmod(int(elapsed), 60)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (BAR_WIDTH - filled)}] "
                     f"{done:5.2f}/{total} members  {minutes:d}:{seconds:02d}  {label[:60]:<60}")
    sys.stderr.flush()


def run_member(member: Member, parallel: bool, index: int, total: int, started: float) -> None:
    """Run one member's Allrun and read its metrics."""
    end_time = Case(member.path).scalar("system/controlDict", "endTime")
    command = f". '{ENV_SCRIPT}' && ./Allrun" + (" -parallel" if parallel else "")
    label = f"{member.name} " + " ".join(f"{k}={v}" for k, v in member.values.items())
    begin = time.time()
    with open(member.path / "log.Allrun", "w", encoding="utf-8") as log:
        process = subprocess.Popen(["bash", "-c", command], cwd=member.path,
                                   stdout=log, stderr=subprocess.STDOUT)
        while process.poll() is None:
            fraction = min(1.0, _simulated_time(member.path) / end_time)
            _progress(index + fraction, total, label, started)
            time.sleep(POLL_SECONDS)
    member.wall_time = time.time() - begin
    solver_log = member.path / "log.ldnaFoam"
    log_text = solver_log.read_text(errors="replace") if solver_log.exists() else ""
    finished = "\nEnd\n" in log_text or "Finalising parallel run" in log_text
    member.status = "done" if process.returncode == 0 and finished else "failed"
    if member.status == "failed":
        member.error = failure_line(log_text or (member.path / "log.Allrun").read_text(
            errors="replace"))
    if member.status == "done":
        row = read_function_object_metrics(member.path)[-1]
        member.metrics = {"time": float(row[0]),
                          **dict(zip(BeadMetrics.FUNCTION_OBJECT_COLUMNS, map(float, row[1:])))}
    _progress(index + 1, total, label, started)


def failure_line(log_text: str) -> str:
    """The line that says why a run stopped: the first of its FOAM FATAL error's
    message, else its last non-empty line."""
    lines = [line.strip() for line in log_text.splitlines() if line.strip()]
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
              end_time: float | None = None, n_procs: int = 1) -> tuple[list[Member], Path]:
    """Make, run and collect a study; returns the members and the CSV path."""
    members = make_members(template, study_dir, parameters, end_time, n_procs)
    started = time.time()
    for index, member in enumerate(members):
        run_member(member, n_procs > 1, index, len(members), started)
    sys.stderr.write("\n")
    return members, write_csv(members, Path(study_dir) / "results.csv")
