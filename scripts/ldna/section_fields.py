"""The bead section's metrics that only the fields hold, at every written time.

``meltPoolMetrics`` writes the section's width, height, area and bond every
few steps, and ``ldna steady`` averages them over windows.  The wetting
angle, the body width and the gas film under the bead are read from the
fields (``ldna post``), which a run writes only every so often (the bead
study: every 0.25 s).  One field holds one phase of the pool's ripple: the
bead study's level 0 on the corrected band read, in the fields written
every 0.25 s from 17.5 to 18.75 s, wetting angles from 31.7 to 57.9 deg and
body widths from 11.7 to 14.0 mm.  A study that read them at each level's
last time alone would compare ripple phases, not resolutions; so they are
read at every written time and averaged over the same windows as the rest.
So are the liquid share of the section's bead (0: the bead's final shape)
and the share of its width topped by cells coarser than its finest (0:
the refined cells enclose the bead).

Each time's values are kept in the case's ``sectionFields.csv``, computed
once per time: ``ldna pack`` keeps that table while it drops the fields
between the first and the latest time.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from . import post
from .case import Case

#: The table, in the case's folder
FILE = "sectionFields.csv"
#: Its columns after the time: name -> (column, scale from SI to its unit)
COLUMNS = {"wetting_angle": ("wetting_angle_deg", 1.0),
           "body_width": ("body_width_mm", 1e3),
           "first_layer_gas": ("first_layer_gas_mm", 1e3),
           "section_liquid": ("section_liquid_share", 1.0),
           "coarse_surface": ("coarse_surface_share", 1.0)}
#: Two times closer than this [s] are one
TIME_TOLERANCE = 1e-9


def _written_times(case: Path) -> list[tuple[float, bool]]:
    """Every written time after 0 and whether it is only in the ranks'
    folders (a decomposed run keeps its times there until reconstructed)."""
    reconstructed = {float(t.name) for t in Case(case).times}
    decomposed = set()
    if (case / "processor0").is_dir():
        decomposed = {float(t.name) for t in Case(case / "processor0").times}
    times = {t: t not in reconstructed for t in reconstructed | decomposed}
    return sorted((t, only_ranks) for t, only_ranks in times.items() if t > 0)


def read(case: Path) -> dict[float, dict[str, float]]:
    """The table's rows: time -> metric (SI, the angle in degrees)."""
    path = Path(case) / FILE
    if not path.is_file():
        return {}
    rows = {}
    with path.open(newline="") as stream:
        for row in csv.DictReader(stream):
            # A table written before a column was added lacks it: update()
            # measures it where the time's fields are still there
            rows[float(row["time_s"])] = {
                name: float(row[column]) / scale for name, (column, scale) in COLUMNS.items()
                if row.get(column) not in (None, "")}
    return rows


def _write(case: Path, rows: dict[float, dict[str, float]]) -> None:
    path = Path(case) / FILE
    scratch = path.with_suffix(".csv.writing")
    with scratch.open("w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["time_s", *(column for column, _ in COLUMNS.values())])
        for time in sorted(rows):
            # A column the time's dropped fields can no longer give: NaN
            writer.writerow([f"{time:.12g}", *(f"{rows[time].get(name, math.nan) * scale:.9g}"
                                               for name, (_, scale) in COLUMNS.items())])
    # A stopped update leaves the table it had
    scratch.replace(path)


def measure(grid, section: float, surface_height: float = 0.0) -> dict[str, float]:
    """The field-read metrics of one time's grid at the section ``section`` [m]."""
    return {"wetting_angle": post.bead_wetting_angle(grid, section, surface_height),
            "body_width": post.bead_body_width(grid, section, surface_height),
            "first_layer_gas": post.first_layer(grid, section, surface_height)[1],
            "section_liquid": post.bead_liquid_share(grid, section, surface_height),
            "coarse_surface": post.bead_surface_cells(grid, section, surface_height)[2]}


def update(case: Path, surface_height: float = 0.0) -> dict[float, dict[str, float]]:
    """Measure every written time the table lacks at the case's configured
    bead section, write the table, and return its rows (none for a case
    without a bead section)."""
    case = Path(case)
    section = post.configured_bead_section(case)
    if section is None:
        return {}
    rows = read(case)

    def known(time: float) -> float | None:
        return next((t for t in rows if abs(t - time) <= TIME_TOLERANCE), None)

    missing = [(t, only_ranks) for t, only_ranks in _written_times(case)
               if known(t) is None or len(rows[known(t)]) < len(COLUMNS)]
    for time, only_ranks in missing:
        grid = post.read_case(case, time, decomposed=only_ranks)
        rows[known(time) if known(time) is not None else time] = measure(
            grid, section, surface_height)
    if missing:
        _write(case, rows)
    return rows


def _in_window(times: np.ndarray, end: float, window: float) -> np.ndarray:
    """Which ``times`` lie in the window (end - window, end]."""
    return (times > end - window + TIME_TOLERANCE) & (times <= end + TIME_TOLERANCE)


def window_means(rows: dict[float, dict[str, float]], name: str, ends: np.ndarray,
                 window: float) -> np.ndarray:
    """Means of ``name`` over the times in each window (end - window, end]
    (NaN for a window that holds no written time)."""
    times = np.array(sorted(rows))
    values = np.array([rows[t].get(name, math.nan) for t in times])
    return np.array([float(values[inside].mean()) if inside.any() else math.nan
                     for inside in (_in_window(times, end, window) for end in ends)])


def times_in_window(rows: dict[float, dict[str, float]], end: float, window: float) -> int:
    """How many written times the window (end - window, end] holds."""
    return int(_in_window(np.array(sorted(rows)), end, window).sum())
