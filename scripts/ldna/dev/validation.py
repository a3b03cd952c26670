"""The bead validation report of a long LDNA run (``ldna bead-report``).

A run of the template from a flat substrate is quasi-steady once the bead's
transverse section at the function object's fixed section (``beadSection``
of meltPoolMetrics, behind the pool) stops changing: every metric's mean
over windows of whole ripple periods stops drifting (``ldna steady``)
(:mod:`ldna.steady`).  Then the mass balance holds whatever the models: the
mean section equals the wires' mass rate over (metal density x welding
speed).

The report reads the function object's table (bead area over time) and the
case's last time (``ldna post``: metrics and pictures), and writes

- ``bead.json``: the figures of ``ldna post --json`` (at the last time)
  plus ``end_time_s``, ``cells``, ``n_procs``, ``core_hours`` (and per
  simulated second), the mean areas over the last two windows, ``steady``
  (bool) and ``steadiness`` (every metric's window means, change and
  tolerance), the area's range over the last window, the mean over the
  judged windows together (``judged_mean_bead_area_mm2``, from
  ``judged_from_s``) and its mass balance error (and the last window's);
  and, as a check that needs no surface height, the net metal
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
import math
import shutil
from pathlib import Path

import numpy as np

from .. import post, steady
from ..balance import evaporation_table, patch_flows
from ..material import Metal
from ..case import Case
from ..meshing import cell_count

#: Column of the bead area in meltPoolMetrics.dat (after the time)
BEAD_AREA_COLUMN = 1 + post.BeadMetrics.FUNCTION_OBJECT_COLUMNS.index("bead_area")


def bead_area_history(case: Path, section: str = "meltPoolMetrics"
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and bead areas [m2] at the fixed section of the meltPoolMetrics
    function object ``section``."""
    table = post.read_function_object_metrics(case, section)
    return table[:, 0], table[:, BEAD_AREA_COLUMN]


def ranks(case: Path) -> int:
    """MPI ranks of the run: its processor directories, or 1."""
    return max(1, len(list(Path(case).glob("processor[0-9]*"))))


def core_hours(case: Path, master_cpu_seconds: float | None = None) -> float:
    """CPU time of the solver times its ranks [h], over all runs of the case.

    CPU time of the master rank (OpenFOAM's timeInfo table, or
    ``master_cpu_seconds`` for a run set up without it), not wall time, so
    that other work on the machine does not count.
    """
    seconds = Case(case).cpu_seconds() if master_cpu_seconds is None else master_cpu_seconds
    return seconds * ranks(case) / 3600


def judged_mean(times: np.ndarray, areas: np.ndarray, start: float) -> float:
    """Time-weighted mean of the bead area from ``start`` to the last row."""
    inside = times >= start
    if inside.sum() < 2:
        return float(areas[-1])
    t, a = times[inside], areas[inside]
    return float(np.trapezoid(a, t) / (t[-1] - t[0]))


def plot_history(times: np.ndarray, areas: np.ndarray, expected: float, means: dict,
                 path: Path) -> Path:
    """The section's bead area against time, its window means, the mean over
    the judged windows and the mass balance's area."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4))
    axes.plot(times, 1e6 * areas, label="bead area at the section")
    axes.axhline(1e6 * expected, color="k", linestyle="--",
                 label=f"mass balance {1e6 * expected:.1f} mm$^2$")
    end = times[-1]
    for k, (mean, shade) in enumerate(((means["mean"], "0.85"), (means["previous_mean"], "0.93"))):
        start = end - (k + 1) * means["window"]
        axes.axvspan(start, start + means["window"], color=shade)
        axes.hlines(1e6 * mean, start, start + means["window"], color="C1",
                    label="mean over the window" if k == 0 else None)
    axes.hlines(1e6 * means["judged"], means["judged_start"], end, color="C2", linestyle=":",
                label=f"mean over the judged windows {1e6 * means['judged']:.1f} mm$^2$")
    axes.set_xlabel("time [s]")
    axes.set_ylabel("bead area [mm$^2$]")
    axes.legend(loc="upper left", fontsize="small")
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
    parameters = "system/caseParameters"
    case = Case(case)
    return 1e-6 * (case.scalar(parameters, "substrateDepth") * case.scalar(parameters, "width"))


def metal_budget(case: Path, start: float, end: float, expected_area: float,
                 mean_area: float) -> dict[str, float]:
    """Where the wires' metal goes [mm3/s], over the window [start, end]:
    the wires' feed, what passes the section with the bead (mean area times
    the welding speed), what leaves through the atmosphere (the bead crossing
    the downstream boundary, and any metal that leaves elsewhere), what
    evaporates; and the metal that left through the atmosphere over the
    whole run [mm3]."""
    speed = post.welding_speed(case)
    window = patch_flows(case, start, end)
    # The flows of this run only (a continued weld's saved tables have none)
    flow_rows = Case(case).function_object("metalFlowAtmosphere", "surfaceFieldValue.dat")
    duration = end - (max(start, float(flow_rows[0, 0])) if flow_rows.size else start)
    evaporation = evaporation_table(case)
    evaporated = 0.0
    if evaporation is not None:
        inside = (evaporation["Time"] >= start) & (evaporation["Time"] <= end)
        if inside.any():
            mass = evaporation["evaporatedMass"][inside]
            evaporated = float(mass[-1] - mass[0]) / Metal.from_case(case).reference_density
    return {
        "feed_mm3_per_s": 1e9 * expected_area * speed,
        "section_flow_mm3_per_s": 1e9 * mean_area * speed,
        "atmosphere_outflow_mm3_per_s": 1e9 * window.get("metalFlowAtmosphere", math.nan) / duration,
        "evaporation_mm3_per_s": 1e9 * evaporated / duration,
        "metal_to_atmosphere_mm3": 1e9 * patch_flows(case).get("metalFlowAtmosphere", math.nan),
    }


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
    verdict = steady.case_steadiness(case, section)
    area = verdict.metrics["bead_area"]
    end = float(times[-1])
    # The mass balance holds for the mean over whole ripples: the judged
    # windows together, not the last one alone (a window may be shorter
    # than the ripple when its period is read from few crossings)
    judged_start = end - steady.WINDOWS * verdict.window
    means = {"window": verdict.window, "mean": area.mean, "previous_mean": area.previous_mean,
             "judged_start": judged_start,
             "judged": judged_mean(times, areas, judged_start)}
    figures.update({
        "section_function_object": section,
        "end_time_s": float(times[-1]),
        "cells": cell_count(case),
        "n_procs": ranks(case),
        "core_hours": hours,
        # Over what the case's runs simulated (not a saved state's tables)
        "core_hours_per_simulated_s": hours / (
            Case(case).simulated_seconds() if master_cpu_seconds is None
            else float(times[-1]) - float(times[0])),
        "averaging_window_s": verdict.window,
        "mean_bead_area_mm2": 1e6 * area.mean,
        "previous_mean_bead_area_mm2": 1e6 * area.previous_mean,
        "steady": verdict.steady,
        "steadiness": verdict.as_dict(),
        "mean_change": area.change / area.mean if area.mean > 0 else float("inf"),
        "bead_area_min_mm2": 1e6 * area.low,
        "bead_area_max_mm2": 1e6 * area.high,
        "judged_from_s": judged_start,
        "judged_mean_bead_area_mm2": 1e6 * means["judged"],
        "mass_balance_error": 1e6 * means["judged"] / figures["expected_bead_area_mm2"] - 1,
        "last_window_mass_balance_error": 1e6 * area.mean / figures["expected_bead_area_mm2"] - 1,
    })
    figures.update(metal_budget(case, judged_start, end,
                                1e-6 * figures["expected_bead_area_mm2"], means["judged"]))
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
