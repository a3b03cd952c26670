"""Running OpenFOAM applications on ldnaFoam cases and reading their results.

Applications run in the environment of ``bin/ldna-env`` (the sourced
OpenFOAM, or the Debian v1912 one that ``bin/ldna-install`` set up), each with
its output in ``log.<application>`` inside the case, as OpenFOAM's
``runApplication`` does.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: Root of the ldnaFoam project (this file is scripts/ldna/foamcase.py)
PROJECT_DIR = Path(__file__).resolve().parents[2]
ENV_SCRIPT = PROJECT_DIR / "bin" / "ldna-env"

#: mpirun options: root in containers and more ranks than cores are common
MPIRUN_OPTIONS = "--allow-run-as-root --oversubscribe"


@dataclass
class RunResult:
    """Outcome of one application run."""

    returncode: int
    log: Path

    @property
    def output(self) -> str:
        """The whole log text."""
        return self.log.read_text(errors="replace")


def run(case: Path, command: str, log_name: str | None = None, check: bool = True,
        timeout: float | None = None) -> RunResult:
    """Run a shell ``command`` inside ``case`` with the ldnaFoam environment.

    The output goes to ``case/log.<log_name>`` (default: the first word of the
    command).  With ``check`` a non-zero exit raises ``RuntimeError`` quoting
    the end of the log.
    """
    case = Path(case)
    log = case / f"log.{log_name or command.split()[0]}"
    script = f'. "{ENV_SCRIPT}" && cd "{case}" && {command}'
    with log.open("w") as out:
        proc = subprocess.run(["bash", "-c", script], stdout=out, stderr=subprocess.STDOUT,
                              timeout=timeout, check=False)
    result = RunResult(proc.returncode, log)
    if check and proc.returncode != 0:
        tail = "\n".join(result.output.splitlines()[-30:])
        raise RuntimeError(f"'{command}' failed in {case} (exit {proc.returncode}):\n{tail}")
    return result


def run_parallel(case: Path, command: str, n_procs: int, log_name: str | None = None,
                 check: bool = True) -> RunResult:
    """Run ``command -parallel`` on ``n_procs`` MPI ranks."""
    return run(case, f"mpirun {MPIRUN_OPTIONS} -np {n_procs} {command} -parallel",
               log_name=log_name or command.split()[0], check=check)


def copy_case(source: Path, destination: Path) -> Path:
    """Copy a case template (without results of earlier runs)."""
    ignore = shutil.ignore_patterns("processor*", "log.*", "postProcessing", "polyMesh",
                                    "[1-9]*", "0.[0-9]*", "dynamicCode")
    shutil.copytree(source, destination, ignore=ignore)
    return Path(destination)


def time_directories(case: Path) -> list[Path]:
    """Time directories of a case, sorted by time."""
    times = []
    for path in Path(case).iterdir():
        try:
            times.append((float(path.name), path))
        except ValueError:
            continue
    return [path for _, path in sorted(times)]


_NONUNIFORM = re.compile(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", re.S)
_UNIFORM = re.compile(r"internalField\s+uniform\s+([^;]+);")


def read_internal_field(path: Path) -> np.ndarray:
    """Cell values of an ASCII volume field file (scalar or vector).

    A uniform field is returned as a single value (array of shape () or (3,)).
    """
    text = Path(path).read_text()
    match = _NONUNIFORM.search(text)
    if match:
        kind, count = match.group(1), int(match.group(2))
        body = text[match.end():]
        if kind == "scalar":
            values = np.array(body.split(")", 1)[0].split(), dtype=float)
        else:
            end = body.index("\n)")
            values = np.array(body[:end].replace("(", " ").replace(")", " ").split(),
                              dtype=float).reshape(count, -1)
        if len(values) != count:
            raise ValueError(f"{path}: expected {count} values, read {len(values)}")
        return values
    match = _UNIFORM.search(text)
    if match:
        return np.array(match.group(1).strip("() ").split(), dtype=float).squeeze()
    raise ValueError(f"{path}: no internalField found (binary format?)")


_BALANCE = re.compile(
    r"^Time = (\S+).*?^Balance: metal mass = (\S+) kg, total enthalpy = (\S+) J",
    re.M | re.S,
)


def read_balances(log: Path) -> np.ndarray:
    """Rows (time, metal mass [kg], total enthalpy [J]) from an ldnaFoam log."""
    rows = []
    time = None
    for line in Path(log).read_text().splitlines():
        if line.startswith("Time = "):
            time = float(line.split()[2])
        elif line.startswith("Balance: ") and time is not None:
            fields = re.findall(r"= (\S+)", line)
            rows.append((time, float(fields[0]), float(fields[1])))
    return np.array(rows)
