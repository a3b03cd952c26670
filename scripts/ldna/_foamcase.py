"""Running OpenFOAM applications on ldnaFoam cases and reading their results.

Private to the package: the tools and the tests go through ``ldna.case.Case``,
which calls these functions.

Applications run in the environment of ``bin/ldna-env`` (the sourced
OpenFOAM, or the Debian v1912 one that ``bin/ldna-install`` set up), each with
its output in ``log.<application>`` inside the case, as OpenFOAM's
``runApplication`` does.
"""
from __future__ import annotations

import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

#: Root of the ldnaFoam project (this file is scripts/ldna/foamcase.py)
PROJECT_DIR = Path(__file__).resolve().parents[2]
ENV_SCRIPT = PROJECT_DIR / "bin" / "ldna-env"
#: The cases' shell steps (bin/tools/RunFunctions: meshing, starting from a state)
RUN_FUNCTIONS = PROJECT_DIR / "bin" / "tools" / "RunFunctions"


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
        timeout: float | None = None, progress: Callable[[], None] | None = None,
        every: float = 300.0) -> RunResult:
    """Run a shell ``command`` inside ``case`` with the ldnaFoam environment.

    The output goes to ``case/log.<log_name>`` (default: the first word of the
    command).  With ``check`` a non-zero exit raises ``RuntimeError`` quoting
    the end of the log.  ``progress`` is called every ``every`` seconds of
    wall time while the command runs (not with ``timeout``).
    """
    if progress is not None and timeout is not None:
        raise ValueError("run: give progress or timeout, not both")
    case = Path(case)
    log = case / f"log.{log_name or command.split()[0]}"
    script = f'. "{ENV_SCRIPT}" && cd "{case}" && {command}'
    with log.open("w") as out:
        if progress is None:
            returncode = subprocess.run(["bash", "-c", script], stdout=out,
                                        stderr=subprocess.STDOUT, timeout=timeout,
                                        check=False).returncode
        else:
            # As subprocess.run: the command does not outlive an interrupted call
            with subprocess.Popen(["bash", "-c", script], stdout=out,
                                  stderr=subprocess.STDOUT) as proc:
                try:
                    while True:
                        try:
                            returncode = proc.wait(timeout=every)
                            break
                        except subprocess.TimeoutExpired:
                            progress()
                except BaseException:
                    proc.kill()
                    raise
    result = RunResult(returncode, log)
    if check and returncode != 0:
        tail = "\n".join(result.output.splitlines()[-30:])
        raise RuntimeError(f"'{command}' failed in {case} (exit {returncode}):\n{tail}")
    return result


def start(case: Path, command: str, log_name: str, append: bool = False) -> subprocess.Popen:
    """Start a shell ``command`` inside ``case`` with the ldnaFoam environment
    and return at once; the output goes to ``case/log.<log_name>``."""
    case = Path(case)
    with (case / f"log.{log_name}").open("a" if append else "w") as out:
        # The child writes to its own copy of the log's descriptor
        return subprocess.Popen(["bash", "-c", f'. "{ENV_SCRIPT}" && {command}'], cwd=case,
                                stdout=out, stderr=subprocess.STDOUT)


def run_parallel(case: Path, command: str, n_procs: int, log_name: str | None = None,
                 check: bool = True, progress: Callable[[], None] | None = None,
                 every: float = 300.0) -> RunResult:
    """Run ``command -parallel`` on ``n_procs`` MPI ranks (bin/ldna-env sets mpirun up)."""
    return run(case, f"mpirun -np {n_procs} {command} -parallel",
               log_name=log_name or command.split()[0], check=check, progress=progress,
               every=every)


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


def read_internal_field(path: Path) -> np.ndarray:
    """Cell values of a volume field file (scalar or vector, ASCII or binary).

    A uniform field is returned as a single value (array of shape () or (3,)).
    Read with foamlib's FoamFieldFile.
    """
    from foamlib import FoamFieldFile

    return np.asarray(FoamFieldFile(path).internal_field, dtype=float)


def write_internal_field(path: Path, values: np.ndarray) -> None:
    """Replace the internalField of a field file by cell ``values`` (foamlib);
    the boundary conditions of the file stay as they are."""
    from foamlib import FoamFieldFile

    FoamFieldFile(path).internal_field = np.asarray(values, dtype=float)


def _table_file(directory: Path, file: str) -> Path | None:
    """The newest ``<file>.dat`` of one start-time directory of a table.

    OpenFOAM's writeFile names the table of a second run from the same start
    time ``<file>_<time>.dat``: the newest file is the latest run's.
    """
    files = [path for path in directory.glob(f"{file}*.dat") if _is_table_of(path, file)]
    return max(files, key=lambda path: path.stat().st_mtime) if files else None


def _is_table_of(path: Path, file: str) -> bool:
    """Whether ``path`` is ``<file>.dat`` or writeFile's ``<file>_<startTime>.dat``."""
    return path.stem in (file, f"{file}_{path.parent.name}")


def read_table(case: Path, name: str, file: str) -> np.ndarray:
    """Rows of a table written with OpenFOAM's ``functionObjects::writeFile``.

    ``postProcessing/<name>/<startTime>/<file>.dat`` of every start time of
    the runs (a restart writes a new start-time directory), as a structured
    array whose fields are the table's column names (its last comment line;
    the first is ``Time``).  Rows of an earlier run at or after a later run's
    start time are dropped: the later run replaced them.
    """
    directories = sorted((Path(case) / "postProcessing" / name).glob("*"),
                         key=lambda path: float(path.name) if _is_number(path.name) else -1.0)
    columns: list[str] | None = None
    blocks = []
    for directory in directories:
        path = _table_file(directory, file) if _is_number(directory.name) else None
        if path is None:
            continue
        rows = _parse_table(path)
        if rows is None:
            continue
        columns = list(rows.dtype.names)
        rows = np.column_stack([rows[column] for column in columns])
        start = float(directory.name)
        blocks = [block[block[:, 0] < start] for block in blocks]
        blocks.append(rows)
    if columns is None:
        raise FileNotFoundError(f"no postProcessing/{name}/*/{file}.dat in {case}")
    table = np.vstack(blocks)
    return np.rec.fromarrays(table.T, names=columns)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _parse_table(path: Path) -> np.ndarray | None:
    """One writeFile table as a structured array (a line still being written
    is left out); None for a table without its header (writeFile opens the
    file when the function object is made and writes the header with the
    first row: a run that ended before its first row leaves it empty)."""
    lines = path.read_text().splitlines()
    header = [line for line in lines if line.startswith("#")]
    if not header:
        return None
    columns = header[-1].lstrip("#").split()
    rows = [line.split() for line in lines if line and not line.startswith("#")]
    rows = [row for row in rows if len(row) == len(columns)]
    table = np.array(rows, dtype=float).reshape(-1, len(columns))
    return np.rec.fromarrays(table.T, names=columns)


def table_files(case: Path, name: str, file: str) -> list[Path]:
    """Every ``<file>.dat`` of ``postProcessing/<name>``: one per run, oldest first."""
    files = [path for path in (Path(case) / "postProcessing" / name).glob(f"*/{file}*.dat")
             if _is_table_of(path, file)]
    return sorted(files, key=lambda path: path.stat().st_mtime)


def latest_run_table(case: Path, name: str, file: str) -> np.ndarray:
    """The table ``<file>`` of the case's latest run (see :func:`read_table`)."""
    files = table_files(case, name, file)
    if not files:
        raise FileNotFoundError(f"no postProcessing/{name}/*/{file}.dat in {case}")
    return _parse_table(files[-1])


#: OpenFOAM's timeInfo function object (cumulative CPU and clock time per
#: step), which the template and the benchmark cases run
TIME_INFO = ("timeInfo", "timeInfo")


def _time_info_runs(case: Path) -> list[tuple[Path, np.ndarray]]:
    """Each run's timeInfo table with its file, oldest first; a run stopped
    before its first step left an empty table, and took no time."""
    files = table_files(case, *TIME_INFO)
    if not files:
        raise FileNotFoundError(f"no postProcessing/timeInfo in {case}")
    tables = ((path, _parse_table(path)) for path in files)
    return [(path, table) for path, table in tables if table is not None and len(table)]


def cpu_seconds(case: Path) -> float:
    """CPU time of the master rank [s] of all runs of the case (timeInfo)."""
    return float(sum(table["cpuTime"][-1] for _, table in _time_info_runs(case)))


def clock_seconds(case: Path) -> float:
    """Wall-clock time [s] of all runs of the case (timeInfo's clockTime,
    whole seconds)."""
    return float(sum(table["clockTime"][-1] for _, table in _time_info_runs(case)))


def simulated_seconds(case: Path) -> float:
    """Process time the case's runs simulated [s]: from each run's start
    (its timeInfo folder) to its last step; the tables a continued weld
    brought from its saved state were not simulated here."""
    return float(sum(table["Time"][-1] - float(path.parent.name)
                     for path, table in _time_info_runs(case)))


def find_tables(case: Path, file: str) -> list[str]:
    """Names of the postProcessing directories holding a ``<file>.dat`` table."""
    return sorted({path.parents[1].name
                   for path in (Path(case) / "postProcessing").glob(f"*/*/{file}.dat")})


#: The solver's table of domain totals and solver health, one row per step
#: (applications/solvers/ldnaFoam/domainBalances.H)
BALANCES = ("balances", "balances")


#: The balance table's columns (C++ names) and their names here
BALANCE_COLUMNS = {
    "Time": "time", "metalMass": "metal_mass", "totalEnthalpy": "enthalpy",
    "Tmin": "T_min", "Tmax": "T_max", "liquidMetalVolume": "liquid_volume",
    "alphaMin": "alpha_min", "alphaMax": "alpha_max",
    "energyIterations": "energy_iterations", "energyUnconverged": "energy_unconverged",
    "linearSolves": "linear_solves", "maxLinearIterations": "max_linear_iterations",
    "maxFinalResidual": "max_final_residual", "nonFiniteSolves": "non_finite_solves",
}


def read_balances(case: Path) -> np.ndarray:
    """Domain totals and solver health of an ldnaFoam run, one row per time step.

    A structured array (the first row is the initial state) with the fields
    of :data:`BALANCE_COLUMNS`: time [s], metal mass [kg], total enthalpy
    [J], min and max temperature [K], liquid metal volume [m3], min and max
    metal fraction, the step's most energy iterations and unconverged energy
    solves, its linear solves, their most iterations and largest final
    residual, and the solves with non-finite residuals.
    """
    table = read_table(case, *BALANCES)
    return np.rec.fromarrays([table[column] for column in BALANCE_COLUMNS],
                             names=list(BALANCE_COLUMNS.values()))


def alpha_bounds(case: Path) -> tuple[float, float]:
    """Lowest and highest metal fraction of any time step of a run."""
    balances = read_balances(case)
    return float(balances["alpha_min"].min()), float(balances["alpha_max"].max())


def read_function_object(case: Path, name: str, file: str) -> np.ndarray:
    """Numeric rows (time first) of a function object's table ``file`` (e.g.
    ``surfaceFieldValue.dat``), all start times joined (:func:`read_table`);
    no rows when the function object wrote none."""
    try:
        table = read_table(case, name, file.removesuffix(".dat"))
    except FileNotFoundError:
        return np.empty((0, 0))
    return np.column_stack([table[column] for column in table.dtype.names])


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
