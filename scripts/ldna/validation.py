"""The bead validation report of a long LDNA run (``ldna bead-report``).

A run of the template from a flat substrate is quasi-steady once the bead's
transverse section at the function object's fixed section (``beadSection``
of meltPoolMetrics, behind the pool) stops changing: its area stays within
``STEADY_TOLERANCE`` over the last ``STEADY_WINDOW`` seconds.  Then the mass
balance holds whatever the models: the section's area equals the wires'
mass rate over (metal density x welding speed).

The report reads the function object's table (bead area over time) and the
case's last time (``ldna post``: metrics and pictures), and writes

- ``bead.json``: the figures of ``ldna post --json`` plus ``end_time_s``,
  ``cells``, ``n_procs``, ``core_hours``, ``steady`` (bool), the area's
  spread over the window and the mass balance error; and, as a check that
  needs no surface height, the net metal area the process added to the
  section (all metal in the plane minus the substrate's section) and its
  error;
- ``bead_area.png``: the section's bead area against time, with the
  expected area;
- the pictures of ``ldna post`` (transverse section with the fusion line and
  the free surface, the surface coloured by temperature, the longitudinal
  section).
"""
from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import numpy as np

from . import post
from .meshing import cell_count

#: The bead area must stay within this relative band over the window
STEADY_TOLERANCE = 0.01
#: Window of the steadiness criterion [s]
STEADY_WINDOW = 0.2
#: Column of the bead area in meltPoolMetrics.dat (after the time)
BEAD_AREA_COLUMN = 1 + post.BeadMetrics.FUNCTION_OBJECT_COLUMNS.index("bead_area")

_CPU = re.compile(r"^ExecutionTime = (\S+) s", re.M)


def bead_area_history(case: Path) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and bead areas [m2] at the fixed section, from the function object."""
    table = post.read_function_object_metrics(case)
    return table[:, 0], table[:, BEAD_AREA_COLUMN]


def steadiness(times: np.ndarray, areas: np.ndarray) -> tuple[bool, float]:
    """Whether the area stayed within STEADY_TOLERANCE over the last window, and its spread."""
    window = times >= times[-1] - STEADY_WINDOW
    if times[-1] - times[0] < STEADY_WINDOW or areas[window].mean() <= 0:
        return False, float("inf")
    spread = float((areas[window].max() - areas[window].min()) / areas[window].mean())
    return spread <= STEADY_TOLERANCE, spread


def ranks(case: Path) -> int:
    """MPI ranks of the run: its processor directories, or 1."""
    return max(1, len(list(Path(case).glob("processor[0-9]*"))))


def core_hours(case: Path) -> float:
    """CPU time of the solver times its ranks [h], from the log's last time line.

    CPU time (OpenFOAM's ExecutionTime, of the master rank), not wall time,
    so that other work on the machine does not count.
    """
    cpu = _CPU.findall((Path(case) / "log.ldnaFoam").read_text())
    return float(cpu[-1]) * ranks(case) / 3600 if cpu else float("nan")


def plot_history(times: np.ndarray, areas: np.ndarray, expected: float, path: Path) -> Path:
    """The section's bead area against time, with the mass balance's area."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4))
    axes.plot(times, 1e6 * areas, label="bead area at the section")
    axes.axhline(1e6 * expected, color="k", linestyle="--",
                 label=f"mass balance {1e6 * expected:.1f} mm$^2$")
    axes.axvspan(times[-1] - STEADY_WINDOW, times[-1], color="0.9",
                 label=f"steadiness window ({STEADY_WINDOW:g} s)")
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


def bead_report(case: Path, output: Path) -> dict:
    """Write bead.json, bead_area.png and the pictures of ``case`` into ``output``."""
    case, output = Path(case), Path(output)
    output.mkdir(parents=True, exist_ok=True)
    result, pictures, time = post.post_process(case, output / "pictures")
    figures = post.summary(case, result, time)
    times, areas = bead_area_history(case)
    steady, spread = steadiness(times, areas)
    figures.update({
        "end_time_s": float(times[-1]),
        "cells": cell_count(case),
        "n_procs": ranks(case),
        "core_hours": core_hours(case),
        "steady": steady,
        "steady_window_s": STEADY_WINDOW,
        "bead_area_spread_in_window": spread,
        "mass_balance_error": figures["bead_area_mm2"] / figures["expected_bead_area_mm2"] - 1,
    })
    net = section_metal_area(case, 1e-3 * figures["bead_section_mm"]) - substrate_section(case)
    figures["net_deposit_area_mm2"] = 1e6 * net
    figures["net_mass_balance_error"] = (figures["net_deposit_area_mm2"]
                                         / figures["expected_bead_area_mm2"] - 1)
    (output / "bead.json").write_text(json.dumps(figures, indent=2) + "\n")
    plot_history(times, areas, 1e-6 * figures["expected_bead_area_mm2"], output / "bead_area.png")
    for picture in pictures:
        shutil.copy(picture, output / picture.name)
    shutil.rmtree(output / "pictures")
    return figures
