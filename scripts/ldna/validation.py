"""The bead validation report of a long LDNA run (``ldna bead-report``).

A run of the template from a flat substrate is quasi-steady once the bead's
transverse section at the function object's fixed section (``beadSection``
of meltPoolMetrics, behind the pool) stops changing.  The section's area
varies along the weld - ripples, as on a real bead: the pool sloshes, and
the area at the fixed section swings by about 10 % with a period of about
0.5 s (3.75 mm of bead) - so the bead is judged on its mean over
``AVERAGING_WINDOW``: quasi-steady when the means over the last window and
over the one before agree within ``STEADY_TOLERANCE``.  Then the mass
balance holds whatever the models: the mean section equals the wires' mass
rate over (metal density x welding speed).

The report reads the function object's table (bead area over time) and the
case's last time (``ldna post``: metrics and pictures), and writes

- ``bead.json``: the figures of ``ldna post --json`` (at the last time)
  plus ``end_time_s``, ``cells``, ``n_procs``, ``core_hours`` (and per
  simulated second), the mean areas over the last two windows, ``steady``
  (bool), the area's range over the last window and the mass balance error
  of the mean; and, as a check that needs no surface height, the net metal
  area the process added to the section at the last time (all metal in the
  plane minus the substrate's section) and its error;
- ``bead_area.png``: the section's bead area against time, its window means
  and the expected area;
- the pictures of ``ldna post`` (transverse section with the fusion line and
  the free surface, the surface coloured by temperature, the longitudinal
  section).
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np

from . import post
from .foamcase import cpu_seconds
from .meshing import cell_count

#: Window of the bead's mean section [s]: one ripple period of the
#: template's bead (0.5 s, 3.75 mm of bead at 7.5 mm/s)
AVERAGING_WINDOW = 0.5
#: The means over the last two windows agree within this share
STEADY_TOLERANCE = 0.01
#: Column of the bead area in meltPoolMetrics.dat (after the time)
BEAD_AREA_COLUMN = 1 + post.BeadMetrics.FUNCTION_OBJECT_COLUMNS.index("bead_area")

def bead_area_history(case: Path, section: str = "meltPoolMetrics"
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and bead areas [m2] at the fixed section of the meltPoolMetrics
    function object ``section``."""
    table = post.read_function_object_metrics(case, section)
    return table[:, 0], table[:, BEAD_AREA_COLUMN]


def window_mean(times: np.ndarray, areas: np.ndarray, start: float, end: float) -> float:
    """Time-weighted mean of the area over [start, end] (the table's steps vary)."""
    inside = (times >= start) & (times <= end)
    if inside.sum() < 2:
        return float("nan")
    t, a = times[inside], areas[inside]
    return float(np.trapezoid(a, t) / (t[-1] - t[0]))


def steadiness(times: np.ndarray, areas: np.ndarray) -> dict:
    """The mean areas [m2] over the last two windows, whether they agree, and
    the area's range over the last window."""
    end = times[-1]
    last = window_mean(times, areas, end - AVERAGING_WINDOW, end)
    previous = window_mean(times, areas, end - 2 * AVERAGING_WINDOW, end - AVERAGING_WINDOW)
    change = abs(last - previous) / last if last > 0 else float("inf")
    window = times >= end - AVERAGING_WINDOW
    return {
        "steady": bool(times[-1] - times[0] >= 2 * AVERAGING_WINDOW
                       and change <= STEADY_TOLERANCE),
        "mean": last,
        "previous_mean": previous,
        "change": float(change),
        "min": float(areas[window].min()),
        "max": float(areas[window].max()),
    }


def ranks(case: Path) -> int:
    """MPI ranks of the run: its processor directories, or 1."""
    return max(1, len(list(Path(case).glob("processor[0-9]*"))))


def core_hours(case: Path, master_cpu_seconds: float | None = None) -> float:
    """CPU time of the solver times its ranks [h], over all runs of the case.

    CPU time of the master rank (OpenFOAM's timeInfo table, or
    ``master_cpu_seconds`` for a run set up without it), not wall time, so
    that other work on the machine does not count.
    """
    seconds = cpu_seconds(case) if master_cpu_seconds is None else master_cpu_seconds
    return seconds * ranks(case) / 3600


def plot_history(times: np.ndarray, areas: np.ndarray, expected: float, means: dict,
                 path: Path) -> Path:
    """The section's bead area against time, its window means and the mass balance's area."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4))
    axes.plot(times, 1e6 * areas, label="bead area at the section")
    axes.axhline(1e6 * expected, color="k", linestyle="--",
                 label=f"mass balance {1e6 * expected:.1f} mm$^2$")
    end = times[-1]
    for k, (mean, shade) in enumerate(((means["mean"], "0.85"), (means["previous_mean"], "0.93"))):
        start = end - (k + 1) * AVERAGING_WINDOW
        axes.axvspan(start, start + AVERAGING_WINDOW, color=shade)
        axes.hlines(1e6 * mean, start, start + AVERAGING_WINDOW, color="C1",
                    label="mean over the window" if k == 0 else None)
    axes.set_xlabel("time [s]")
    axes.set_ylabel("bead area [mm$^2$]")
    axes.legend(loc="lower right")
    axes.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)
    return path


def section_metal_area(case: Path, x: float) -> float:
    """Metal area [m2] in the transverse plane at ``x``: sum of alpha times the
    transverse area of the cells the plane cuts (the mesh's cells are
    aligned boxes), at the case's latest time."""
    grid = post.read_case(case)
    points = np.asarray(grid.points, dtype=float)
    connectivity = np.asarray(grid.cell_connectivity)
    starts = np.asarray(grid.cell_offsets)[:-1]
    low = np.minimum.reduceat(points[connectivity, 0], starts)
    high = np.maximum.reduceat(points[connectivity, 0], starts)
    cut = (low <= x) & (x < high)
    volume = np.asarray(grid.compute_cell_sizes(length=False, area=False)["Volume"])
    alpha = np.asarray(grid.cell_data["alpha.metal"])
    return float(np.sum((alpha * volume / (high - low))[cut]))


def substrate_section(case: Path) -> float:
    """Transverse section of the substrate as meshed [m2]: depth x width."""
    from .foamcase import dictionary_scalar

    parameters = "system/caseParameters"
    return 1e-6 * (dictionary_scalar(case, parameters, "substrateDepth")
                   * dictionary_scalar(case, parameters, "width"))


def bead_report(case: Path, output: Path, section: str = "meltPoolMetrics",
                master_cpu_seconds: float | None = None) -> dict:
    """Write bead.json, bead_area.png and the pictures of ``case`` into ``output``.

    The bead is judged at the section of the meltPoolMetrics function object
    ``section`` (a case may measure several sections behind the pool).
    ``master_cpu_seconds`` gives the solver's CPU time for a run without the
    timeInfo table.
    """
    hours = core_hours(case, master_cpu_seconds)
    case, output = Path(case), Path(output)
    output.mkdir(parents=True, exist_ok=True)
    result, pictures, time = post.post_process(
        case, output / "pictures", bead_section=post.configured_bead_section(case, section))
    figures = post.summary(case, result, time)
    times, areas = bead_area_history(case, section)
    means = steadiness(times, areas)
    figures.update({
        "section_function_object": section,
        "end_time_s": float(times[-1]),
        "cells": cell_count(case),
        "n_procs": ranks(case),
        "core_hours": hours,
        "core_hours_per_simulated_s": hours / float(times[-1]),
        "averaging_window_s": AVERAGING_WINDOW,
        "mean_bead_area_mm2": 1e6 * means["mean"],
        "previous_mean_bead_area_mm2": 1e6 * means["previous_mean"],
        "steady": means["steady"],
        "mean_change": means["change"],
        "bead_area_min_mm2": 1e6 * means["min"],
        "bead_area_max_mm2": 1e6 * means["max"],
        "mass_balance_error": 1e6 * means["mean"] / figures["expected_bead_area_mm2"] - 1,
    })
    net = section_metal_area(case, 1e-3 * figures["bead_section_mm"]) - substrate_section(case)
    figures["net_deposit_area_mm2"] = 1e6 * net
    figures["net_mass_balance_error"] = (figures["net_deposit_area_mm2"]
                                         / figures["expected_bead_area_mm2"] - 1)
    (output / "bead.json").write_text(json.dumps(figures, indent=2) + "\n")
    plot_history(times, areas, 1e-6 * figures["expected_bead_area_mm2"], means,
                 output / "bead_area.png")
    for picture in pictures:
        shutil.copy(picture, output / picture.name)
    shutil.rmtree(output / "pictures")
    return figures
