"""One ldnaFoam case on disk: copy, set entries, mesh, decompose, run, read.

``Case`` is what the tools (``ldna bench``, ``study``, ``accuracy``) do to a
case, in one place, the way foamlib's ``FoamCase`` does for OpenFOAM
cases.  Fields are read and written with foamlib.  Dictionaries are edited
as text (``ldna.foamdict``), keeping comments, ``#include`` and ``#eval``:
foamlib 1.7.10 stops at the v1912 ``#eval{ ... }`` entries of the
template's ``constant/fvOptions``, ``system/blockMeshDict`` and
``system/controlDict`` (measured on cases/ldna), and OpenFOAM's
``foamDictionary -set`` writes the file with every macro expanded.
"""
from __future__ import annotations

import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from . import _foamcase as foamcase
from . import foamdict, meshing
# The project's places, for scripts and tests (the rest of _foamcase is private)
from ._foamcase import BALANCES, ENV_SCRIPT, PROJECT_DIR, RUN_FUNCTIONS, TIME_INFO, RunResult

__all__ = ["BALANCES", "Case", "ENV_SCRIPT", "PROJECT_DIR", "RUN_FUNCTIONS", "RunResult",
           "TIME_INFO"]


#: Steps at a run's start that read the fields and set up the solvers
#: (the first solves' matrices and preconditioners); cost figures leave
#: them out
START_UP_STEPS = 2


@dataclass(frozen=True)
class Case:
    """An ldnaFoam case directory."""

    path: Path

    def __post_init__(self) -> None:
        # A Case of a Case or of a str is a Case of its path
        object.__setattr__(self, "path", Path(self.path))

    @classmethod
    def copy_of(cls, template: Path | "Case", destination: Path) -> "Case":
        """A copy of a case template, without the results of earlier runs."""
        source = template.path if isinstance(template, Case) else Path(template)
        return cls(foamcase.copy_case(source, Path(destination)))

    def __truediv__(self, relative: str) -> Path:
        return self.path / relative

    def __fspath__(self) -> str:
        return str(self.path)

    def __str__(self) -> str:
        return str(self.path)

    @property
    def name(self) -> str:
        """The case directory's name."""
        return self.path.name

    # Dictionaries

    def set(self, file: str, entry: str, value: str, create: bool = False) -> None:
        """Set the (scoped: ``coeffs/n``) ``entry`` of ``file`` (relative to
        the case) to ``value``, editing the text in place.  An entry the file
        does not have is a KeyError, unless ``create`` asks to add it."""
        foamdict.set_entry(self.path / file, entry, value, create)

    def written(self, file: str, entry: str) -> str:
        """The value of a (scoped) entry as written in the file (macros unexpanded)."""
        return foamdict.entry_text(self.path / file, entry)

    def value(self, file: str, entry: str) -> str:
        """The value of a (scoped) entry as OpenFOAM reads it."""
        return foamcase.dictionary_value(self.path, file, entry)

    def scalar(self, file: str, entry: str) -> float:
        """The numeric value of an entry (``constant 7000`` gives 7000)."""
        return foamcase.dictionary_scalar(self.path, file, entry)

    # Mesh and runs

    def mesh(self, start: tuple[Path, float] | None = None) -> int:
        """Mesh as the template's Allrun does (with ``start`` = (run, time):
        as ``Allrun -start-from``, which refines the band there); the number
        of cells."""
        return meshing.mesh_case(self.path, start)

    @property
    def cells(self) -> int:
        """Cells of the case's mesh."""
        return meshing.cell_count(self.path)

    def set_ranks(self, n_procs: int) -> None:
        """Decompose into ``n_procs`` subdomains: their number and the
        hierarchical split (``n_procs`` along the weld), which decomposePar
        requires to agree; a split written from the number
        (``($numberOfSubdomains 1 1)``, the template's) follows it."""
        parameters = "system/decomposeParDict"
        self.set(parameters, "numberOfSubdomains", str(n_procs))
        if "$numberOfSubdomains" not in self.written(parameters, "coeffs/n"):
            self.set(parameters, "coeffs/n", f"({n_procs} 1 1)")

    def decompose(self, n_procs: int | None = None) -> None:
        """decomposePar (into ``n_procs`` subdomains, if given)."""
        if n_procs is not None:
            self.set_ranks(n_procs)
        self.run("decomposePar -force", log_name="decomposePar")

    def run(self, command: str = "ldnaFoam", n_procs: int = 1, log_name: str | None = None,
            check: bool = True, timeout: float | None = None,
            progress: Callable[[], None] | None = None, every: float = 300.0) -> RunResult:
        """Run ``command`` in the case, on ``n_procs`` MPI ranks if more than one
        (the case must be decomposed); output in ``log.<log_name>``.
        ``progress`` is called every ``every`` seconds while it runs."""
        if n_procs > 1:
            return foamcase.run_parallel(self.path, command, n_procs, log_name=log_name,
                                         check=check, progress=progress, every=every)
        return foamcase.run(self.path, command, log_name=log_name, check=check,
                            timeout=timeout, progress=progress, every=every)

    def start(self, command: str, log_name: str, append: bool = False) -> subprocess.Popen:
        """Start ``command`` in the case and return at once (a member of a
        study runs beside others); output in ``log.<log_name>``."""
        return foamcase.start(self.path, command, log_name, append)

    def reconstruct(self) -> None:
        """reconstructPar of the latest time."""
        self.run("reconstructPar -latestTime", log_name="reconstructPar")

    # Results

    @property
    def times(self) -> list[Path]:
        """Time directories, sorted by time."""
        return foamcase.time_directories(self.path)

    def field(self, name: str, time: str | Path | None = None) -> np.ndarray:
        """Cell values of a field at ``time`` (a time name or time directory;
        default: the latest)."""
        directory = self.times[-1] if time is None else self.path / Path(time).name
        return foamcase.read_internal_field(directory / name)

    def write_field(self, name: str, values: np.ndarray, time: str = "0") -> None:
        """Replace the cell values of a field file, keeping its boundary conditions."""
        foamcase.write_internal_field(self.path / time / name, values)

    def table(self, name: str, file: str) -> np.ndarray:
        """A function object's table over all runs (``postProcessing/<name>``)."""
        return foamcase.read_table(self.path, name, file)

    def latest_table(self, name: str, file: str) -> np.ndarray:
        """A function object's table of the latest run only."""
        return foamcase.latest_run_table(self.path, name, file)

    def function_object(self, name: str, file: str) -> np.ndarray:
        """Numeric rows (time first) of a function object's table, no rows
        when it wrote none."""
        return foamcase.read_function_object(self.path, name, file)

    def tables_named(self, file: str) -> list[str]:
        """The postProcessing folders holding a ``<file>.dat`` table (the
        sources of one kind: ``droplets``, ``evaporation``, ...)."""
        return foamcase.find_tables(self.path, file)

    def table_files(self, name: str, file: str) -> list[Path]:
        """Every ``<file>.dat`` of ``postProcessing/<name>``: one per run, oldest first."""
        return foamcase.table_files(self.path, name, file)

    def clock_seconds(self) -> float:
        """Wall-clock time [s] of all runs (timeInfo)."""
        return foamcase.clock_seconds(self.path)

    def simulated_seconds(self) -> float:
        """Process time the runs simulated [s], from each run's start (timeInfo)."""
        return foamcase.simulated_seconds(self.path)

    def cpu_seconds(self) -> float:
        """CPU time of the master rank [s] of all runs (timeInfo)."""
        return foamcase.cpu_seconds(self.path)

    def balances(self) -> np.ndarray:
        """The solver's domain totals and health, one row per step."""
        return foamcase.read_balances(self.path)

    def alpha_bounds(self) -> tuple[float, float]:
        """Lowest and highest metal fraction of any step of the runs."""
        return foamcase.alpha_bounds(self.path)

    def _latest_run_after_start_up(self) -> np.ndarray:
        """The latest run's timeInfo rows from the end of its start-up on:
        its first ``START_UP_STEPS`` steps read the fields and set up the
        solvers, and a short window would count them."""
        table = self.latest_table(*TIME_INFO)
        if len(table) < START_UP_STEPS + 1:
            raise RuntimeError(f"{self.path}: its latest run holds {len(table)} steps, "
                               f"{START_UP_STEPS + 1} at least are needed; run a few more")
        return table[START_UP_STEPS - 1:]

    def latest_run_cpu_rate(self) -> tuple[float, int]:
        """CPU seconds of the master rank per simulated second of the latest
        run after its start-up (timeInfo), and the steps counted."""
        table = self._latest_run_after_start_up()
        simulated = float(table["Time"][-1] - table["Time"][0])
        return float(table["cpuTime"][-1] - table["cpuTime"][0]) / simulated, len(table) - 1

    def seconds_per_step(self) -> float:
        """Mean CPU time per step of the latest run after its start-up (timeInfo)."""
        return float(np.diff(self._latest_run_after_start_up()["cpuTime"]).mean())
