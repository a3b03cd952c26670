"""A run's state kept to start other runs from (``ldna save-state``).

A saved state is a small OpenFOAM case: the run's mesh and the fields a
start needs at one time (``<time>/``), compressed (OpenFOAM reads ``.gz``
files as they are), its dictionaries (``system/``, ``constant/``: the knobs
and models it was computed with), and the tables that ``ldna steady``
judges (bead metrics, domain balances, the wires' droplets, the laser's
power) over the last seconds before that time.  ``./Allrun -start-from
STATE`` maps it onto a case's mesh; a case whose dictionaries are the
state's (but for its times and ranks) continues the weld, and the Allrun
puts the state's tables into its postProcessing, so that its steadiness is
judged over the seconds before the start as well as after.

``cases/steadyWeld`` is the template's quasi-steady weld at level 0, saved
this way; bin/ldna-scene starts from it.
"""
from __future__ import annotations

import gzip
import shutil
from pathlib import Path

from . import section_fields
from .case import Case
from .post import POST_FUNCTION, WELD_START_RECORD

#: Fields a start maps (the solver computes the rest from them)
STATE_FIELDS = ("alpha.metal", "T", "U", "p", "p_rgh", "fillerFraction")
#: Mesh files mapFields reads
MESH_FILES = ("boundary", "faces", "neighbour", "owner", "points")
#: Tables ``ldna steady`` judges: postProcessing folder, file name
HISTORY_TABLES = (("meltPoolMetrics", "meltPoolMetrics"), ("balances", "balances"),
                  ("upstreamTotals", "upstreamTotals"), ("wireDroplets", "droplets"),
                  ("laser", "power"))
#: Rows of a history table kept at most this often [s]: the per-step
#: tables' 5 400 rows a second would be most of the state's size, and the
#: judge's window means and slopes do not need them
HISTORY_ROW_INTERVAL = 1e-3
#: Seconds of tables kept by default: four windows of the template's ripple
#: (0.4-0.53 s) before the state's time, so that a continued run is judged
#: from its first step
HISTORY_SECONDS = 3.0
#: Subfolder of a saved state holding its tables
HISTORY = "history"


def _gzip(source: Path, target: Path) -> None:
    target.parent.mkdir(parents=True, exist_ok=True)
    with open(source, "rb") as raw, gzip.open(target.with_name(target.name + ".gz"), "wb") as out:
        shutil.copyfileobj(raw, out)


def _table_text(case: Path, name: str, file: str, start: float, end: float) -> str:
    """The table's comment lines and its rows in [start, end], at most one
    each HISTORY_ROW_INTERVAL (the first row of each interval)."""
    directories = sorted((case / "postProcessing" / name).glob("*"))
    header = next(iter(directories[0].glob(f"{file}.dat"))).read_text().splitlines()
    comments = [line for line in header if line.startswith("#")]
    rows = Case(case).table(name, file)
    kept, last = [], -float("inf")
    for row in rows:
        t = float(row[0])
        if start <= t <= end and t >= last + HISTORY_ROW_INTERVAL - 1e-12:
            kept.append("\t".join(f"{float(v):.9g}" for v in row))
            last = t
    return "\n".join(comments + kept) + "\n"


def save_state(run: Path, target: Path, time: str | None = None,
               history_seconds: float = HISTORY_SECONDS) -> Path:
    """Save ``run``'s reconstructed state at ``time`` (default its latest)
    and its tables of the ``history_seconds`` before it into ``target``."""
    run, target = Path(run), Path(target)
    case = Case(run)
    directory = case.times[-1] if time is None else run / time
    if not directory.is_dir() or directory.name == "0":
        raise FileNotFoundError(f"{run} has no reconstructed time {time or '(latest)'}")
    if target.exists():
        raise FileExistsError(f"{target} exists: remove it or choose another folder")
    for file in MESH_FILES:
        _gzip(run / "constant" / "polyMesh" / file, target / "constant" / "polyMesh" / file)
    for field in STATE_FIELDS:
        if (directory / field).is_file():
            _gzip(directory / field, target / directory.name / field)
    # The dictionaries: a run whose own are the same continues this weld
    # (not the one ldna post writes to run its function object)
    for folder in ("system", "constant"):
        (target / folder).mkdir(parents=True, exist_ok=True)
        for file in (run / folder).iterdir():
            if file.is_file() and file.name != POST_FUNCTION:
                shutil.copy(file, target / folder / file.name)
    end = float(directory.name)
    for name, file in HISTORY_TABLES:
        try:
            text = _table_text(run, name, file, end - history_seconds, end)
        except (FileNotFoundError, StopIteration, IndexError, ValueError):
            continue
        rows = [line for line in text.splitlines() if not line.startswith("#")]
        if not rows:
            continue
        first = rows[0].split("\t")[0]
        path = target / HISTORY / name / first / f"{file}.dat"
        path.parent.mkdir(parents=True)
        with gzip.open(path.with_name(path.name + ".gz"), "wt", encoding="utf-8") as out:
            out.write(text)
    # When this weld started from another's state, however long ago
    name, file = WELD_START_RECORD
    for record in (run / "postProcessing" / name).glob(f"*/{file}.dat"):
        _gzip(record, target / HISTORY / record.relative_to(run / "postProcessing"))
    return target


def state_time(state: Path) -> str:
    """The time of a saved state (its one time folder)."""
    times = Case(state).times
    if not times:
        raise FileNotFoundError(f"{state} holds no state")
    return times[-1].name


# A run carried to another machine or checkout (``ldna pack``/``unpack``)

#: What a packed case leaves out: the ranks' copies (its latest time is
#: reconstructed first; a continuation decomposes it again), the times
#: between its initial and its latest one, and its logs
PACK_SKIPPED_PREFIXES = ("processor", "log.")


def _is_case(path: Path) -> bool:
    return (path / "system" / "controlDict").is_file()


def _cases_in(folder: Path) -> list[Path]:
    """``folder`` itself if it is a case, else the cases below it (a study's members)."""
    if _is_case(folder):
        return [folder]
    return sorted(path.parents[1] for path in folder.rglob("system/controlDict")
                  if "processor" not in path.parents[1].name)


def _reconstruct_latest(case: Case) -> None:
    """Reconstruct the ranks' latest time if it is newer than the case's."""
    ranks = case / "processor0"
    if not ranks.is_dir():
        return
    decomposed = Case(ranks).times
    reconstructed = case.times
    if decomposed and (not reconstructed
                       or float(decomposed[-1].name) > float(reconstructed[-1].name) + 1e-12):
        case.reconstruct()


def pack_run(run: Path, archive: Path) -> Path:
    """Pack ``run`` (a case, or a folder of cases such as a study) into the
    xz-compressed tar ``archive``: per case its dictionaries, mesh, initial
    and latest reconstructed time, its postProcessing tables and the
    section's field-read metrics of every written time (what a
    continuation and the tools' verdicts and costs read)."""
    import tarfile

    run, archive = Path(run).resolve(), Path(archive)
    cases = _cases_in(run)
    if not cases:
        raise FileNotFoundError(f"{run} holds no case (no system/controlDict)")
    kept_times = set()
    for path in cases:
        case = Case(path)
        _reconstruct_latest(case)
        # What the bead study reads from the fields it drops (section_fields)
        section_fields.update(path)
        times = case.times
        kept_times.update(t.resolve() for t in times[:1] + times[-1:])
    case_times = {t.resolve() for path in cases for t in Case(path).times}

    case_folders = {path.resolve() for path in cases}

    def keep(member: tarfile.TarInfo) -> tarfile.TarInfo | None:
        path = (run.parent / member.name).resolve()
        if path.name.startswith(PACK_SKIPPED_PREFIXES) and path.parent in case_folders:
            return None
        if path in case_times and path not in kept_times:
            return None
        return member

    archive.parent.mkdir(parents=True, exist_ok=True)
    with tarfile.open(archive, "w:xz") as tar:
        tar.add(run, arcname=run.name, filter=keep)
    return archive


def unpack_run(archive: Path, run: Path) -> Path:
    """Unpack an archive of :func:`pack_run` as ``run`` (which must not
    exist); continue it with ``Allrun -resume`` or the study's ``--resume``."""
    import tarfile

    archive, run = Path(archive), Path(run)
    if run.exists():
        raise FileExistsError(f"{run} exists: remove it or choose another folder")
    with tarfile.open(archive, "r:xz") as tar:
        names = tar.getnames()
        tops = {name.split("/", 1)[0] for name in names}
        if len(tops) != 1 or any(".." in Path(name).parts or Path(name).is_absolute()
                                 for name in names):
            raise ValueError(f"{archive} is not an archive of ldna pack (one folder)")
        staging = run.parent / f".{run.name}.unpacking"
        if staging.exists():
            shutil.rmtree(staging)
        staging.mkdir(parents=True)
        try:
            # Regular files and folders only, where tarfile can check it
            tar.extractall(staging, filter="data")
        except TypeError:
            tar.extractall(staging)
    (staging / tops.pop()).rename(run)
    staging.rmdir()
    return run
