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
    """Run ``command -parallel`` on ``n_procs`` MPI ranks (bin/ldna-env sets mpirun up)."""
    return run(case, f"mpirun -np {n_procs} {command} -parallel",
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


def write_internal_field(path: Path, values: np.ndarray) -> None:
    """Replace the internalField of an ASCII scalar field file by cell ``values``.

    The boundary conditions of the file stay as they are.
    """
    path = Path(path)
    text = path.read_text()
    body = "\n".join(f"{value:.12g}" for value in np.asarray(values, dtype=float))
    field = f"internalField   nonuniform List<scalar> {len(values)}\n(\n{body}\n);"
    text, count = re.subn(r"internalField\s+uniform\s+[^;]+;", lambda _: field, text, count=1)
    if count != 1:
        raise ValueError(f"{path}: no uniform internalField to replace")
    path.write_text(text)


_BALANCE = re.compile(
    r"^Balance at t = (\S+): metal mass = (\S+) kg, total enthalpy = (\S+) J, "
    r"min/max T = (\S+) / (\S+) K, liquid metal volume = (\S+) m3",
    re.M,
)

#: Columns of :func:`read_balances`
BALANCE_COLUMNS = ("time", "metal_mass", "enthalpy", "T_min", "T_max", "liquid_volume")


def read_balances(log: Path) -> np.ndarray:
    """Domain totals an ldnaFoam log reports once per time step.

    A structured array with the fields of :data:`BALANCE_COLUMNS`: time [s],
    metal mass [kg], total enthalpy [J], min and max temperature [K] and
    liquid metal volume [m3].
    """
    rows = [tuple(float(v) for v in m.groups()) for m in _BALANCE.finditer(Path(log).read_text())]
    return np.array(rows, dtype=[(name, float) for name in BALANCE_COLUMNS])


_ALPHA_BOUNDS = re.compile(r"Min\(alpha\.\w+\) = (\S+)\s+Max\(alpha\.\w+\) = (\S+)")


def alpha_bounds(log: Path) -> tuple[float, float]:
    """Lowest and highest metal fraction reported anywhere in a solver log."""
    pairs = np.array(_ALPHA_BOUNDS.findall(Path(log).read_text()), dtype=float)
    return float(pairs[:, 0].min()), float(pairs[:, 1].max())


def read_function_object(case: Path, name: str, file: str) -> np.ndarray:
    """Numeric rows of a function object's output, all start times joined."""
    rows = []
    for path in sorted((Path(case) / "postProcessing" / name).glob(f"*/{file}")):
        for line in path.read_text().splitlines():
            if line and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return np.array(rows)


def dictionary_value(case: Path, file: str, entry: str) -> str:
    """Value of a (scoped, slash-separated) entry, as OpenFOAM's foamDictionary reads it."""
    script = f'. "{ENV_SCRIPT}" && cd "{case}" && foamDictionary -entry "{entry}" -value "{file}"'
    proc = subprocess.run(["bash", "-c", script], capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise KeyError(f"{entry} in {case}/{file}: {proc.stderr.strip()[-300:]}")
    return proc.stdout.strip()


def dictionary_scalar(case: Path, file: str, entry: str) -> float:
    """Numeric value of an entry; ``constant 7000`` and ``uniform 1300`` give 7000 and 1300."""
    return float(dictionary_value(case, file, entry).split()[-1])
