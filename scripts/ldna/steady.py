"""Is the bead quasi-steady?  (``ldna steady``)

A weld in the moving frame is quasi-steady when what a macro-section shows
stops changing.  The bead ripples (the pool sloshes: in the template's runs
the section's area swings by about 10 % with a period of 0.4-0.7 s) and
splashes land at random, so each metric is judged on its time-weighted
means over ``WINDOWS`` consecutive windows of whole ripple periods ending
at the judged time: quasi-steady when, for every metric, the drift of those
means (the least-squares slope through them, per window) is within
``RELATIVE_TOLERANCE`` of the last mean or of the bead's own size in that
direction (``SCALES``: the penetration against the bead's height, the
bonded width against its width, the fused area against its area; a metric
that is zero, such as the penetration of a clad that did not fuse, is
steady at zero), or within its noise: ``NOISE_SIGMAS`` standard errors of
the slope, from the means' scatter about the line, at most ``NOISE_CAP``.  In the template's run
from a flat substrate the means of 0.5 s windows scatter by 2-5 % from 3 s
on with no trend (docs/validation/steady-start.md), which two windows
compared to 1 % never pass; a drift of the size of the scatter or more is
still caught.  The window is the bead area's ripple period, measured from
its upward crossings of its mean, times the whole number that reaches
``MIN_WINDOW``; without a ripple, ``MIN_WINDOW``.  All windows must lie
after the bead reached the section (``start``), and the section must hold
a bead.

The metrics are those the ``meltPoolMetrics`` function object writes every
few steps (``postProcessing/<name>/*/meltPoolMetrics.dat``): the judgement
needs no fields and works on a run that is still going.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from . import post

#: Shortest averaging window [s]: the template's ripple period is 0.56-0.7 s
MIN_WINDOW = 0.5
#: Two consecutive window means agree within this share of the last one, or
#: of the macro-section's own size in that direction (``SCALES``): a metric
#: far smaller than the bead (a thin bond's penetration, a sporadic fusion
#: spot) is read to 1 % of the bead, as a macro-section is
RELATIVE_TOLERANCE = 0.01
#: Consecutive windows whose means are judged, and the standard errors of
#: their slope that count as noise: Student's t at 95 % for the fit's
#: WINDOWS - 2 = 2 degrees of freedom (a steady metric's scattered means
#: pass 95 % of the time)
WINDOWS = 4
NOISE_SIGMAS = 4.303
#: The noise allowance is at most this share of the metric (or of the
#: bead's size): the largest scatter of the template's 0.5 s window means
#: once its bead stopped growing (bead area at 11 mm behind the wires,
#: +-5 %); a larger scatter is a window too short for the ripple, and must
#: not let a drift of that size pass
NOISE_CAP = 0.05
#: The bead's size each metric is read against: its width across the weld,
#: its height, its area; the dilution against 1 (the fused area against the
#: bead's area)
SCALES = {
    "bead_area": "bead_area",
    "bead_width": "bead_width",
    "bead_height": "bead_height",
    "bonded_width": "bead_width",
    "penetration": "bead_height",
    "fused_area": "bead_area",
    "dilution": None,
    "pool_length": "bead_width",
    "pool_width": "bead_width",
}
#: The metrics judged (columns of meltPoolMetrics.dat)
METRICS = tuple(SCALES)


def window_mean(times: np.ndarray, values: np.ndarray, start: float, end: float) -> float:
    """Time-weighted mean of ``values`` over [start, end] (the table's steps vary)."""
    inside = (times >= start) & (times <= end)
    if inside.sum() < 2:
        return float("nan")
    t, v = times[inside], values[inside]
    return float(np.trapezoid(v, t) / (t[-1] - t[0]))


def ripple_period(times: np.ndarray, values: np.ndarray, start: float) -> float | None:
    """The ripple's period [s] after ``start``: the median spacing of the
    values' upward crossings of their mean there; None with fewer than three
    crossings."""
    after = times >= start
    t, v = times[after], values[after]
    if t.size < 3:
        return None
    above = v > window_mean(t, v, t[0], t[-1])
    crossings = t[1:][above[1:] & ~above[:-1]]
    if crossings.size < 3:
        return None
    return float(np.median(np.diff(crossings)))


def averaging_window(times: np.ndarray, values: np.ndarray, start: float,
                     min_window: float = MIN_WINDOW) -> float:
    """Whole ripple periods, at least ``min_window`` [s] (that, without a ripple)."""
    period = ripple_period(times, values, start)
    if period is None:
        return min_window
    return period * math.ceil(min_window / period - 1e-9)


@dataclass
class MetricSteadiness:
    """One metric over the judged windows (SI units)."""

    #: Means of the last window and of the window before
    mean: float
    previous_mean: float
    #: Drift per window (the slope of the windows' means) and its tolerance
    change: float
    tolerance: float
    #: Range of the values in the last window
    low: float
    high: float
    #: NOISE_SIGMAS standard errors of the drift (part of the tolerance)
    noise: float = 0.0

    @property
    def steady(self) -> bool:
        return bool(self.change <= self.tolerance)


@dataclass
class Steadiness:
    """The verdict on a run's bead and the figures behind it."""

    steady: bool
    reason: str
    end_time: float
    window: float
    metrics: dict[str, MetricSteadiness] = field(default_factory=dict)

    def as_dict(self) -> dict:
        """JSON-ready: every metric's means, change, tolerance and range."""
        return {"steady": self.steady, "reason": self.reason, "end_time_s": self.end_time,
                "window_s": self.window,
                "metrics": {name: {**asdict(m), "steady": m.steady}
                            for name, m in self.metrics.items()}}


def judge(times: np.ndarray, table: dict[str, np.ndarray], start: float | None = None,
          min_window: float = MIN_WINDOW) -> Steadiness:
    """Judge the metrics ``table`` (name -> values at ``times``) for steadiness.

    ``start``: when the bead reached the section (default: the first time).
    """
    start = float(times[0]) if start is None else max(float(start), float(times[0]))
    window = averaging_window(times, table["bead_area"], start, min_window)
    end = float(times[-1])
    ends = end - window * np.arange(WINDOWS)[::-1]
    means = {name: np.array([window_mean(times, table[name], e - window, e) for e in ends])
             for name in METRICS}
    k = np.arange(WINDOWS) - (WINDOWS - 1) / 2
    metrics = {}
    for name in METRICS:
        m = means[name]
        scale = 1.0 if SCALES[name] is None else abs(means[SCALES[name]][-1])
        size = max(abs(float(m[-1])), scale)
        in_last = times >= end - window
        slope = float(np.dot(k, m - m.mean()) / np.dot(k, k))
        residual = m - m.mean() - slope * k
        slope_error = math.sqrt(float(np.dot(residual, residual)) / (WINDOWS - 2)
                                / float(np.dot(k, k)))
        noise = NOISE_SIGMAS * slope_error if math.isfinite(slope_error) else 0.0
        metrics[name] = MetricSteadiness(
            mean=float(m[-1]), previous_mean=float(m[-2]), change=abs(slope),
            tolerance=max(RELATIVE_TOLERANCE * size, min(noise, NOISE_CAP * size)),
            low=float(table[name][in_last].min()), high=float(table[name][in_last].max()),
            noise=noise)
    if end < start:
        verdict, reason = False, (f"the bead deposited by the run reaches the section at "
                                  f"{start:.3g} s, after this run's end")
    elif end - start < WINDOWS * window:
        verdict, reason = False, (f"too short: {end - start:.3g} s after the bead's arrival, "
                                  f"{WINDOWS} windows of {window:.3g} s needed")
    elif not metrics["bead_area"].mean > 0:
        verdict, reason = False, "no bead at the section"
    else:
        changing = [n for n, m in metrics.items() if not m.steady]
        verdict = not changing
        reason = ("every metric's drift within its tolerance" if verdict
                  else "still changing: " + ", ".join(changing))
    return Steadiness(verdict, reason, end, window, metrics)


#: Spacing of the end times at which ``first_steady`` judges a run [s]
JUDGING_INTERVAL = 0.05


def first_steady(times: np.ndarray, table: dict[str, np.ndarray], start: float | None = None,
                 min_window: float = MIN_WINDOW) -> float | None:
    """The first end time, every JUDGING_INTERVAL, at which the run up to it is
    judged quasi-steady (the time a run needed); None if never."""
    first = float(times[0]) if start is None else max(float(start), float(times[0]))
    for end in np.arange(first + WINDOWS * min_window, float(times[-1]) + 1e-12,
                         JUDGING_INTERVAL):
        upto = times <= end
        if upto.sum() > 2 and judge(times[upto], {n: v[upto] for n, v in table.items()},
                                    start, min_window).steady:
            return float(times[upto][-1])
    return None


def case_table(case: Path, section: str = "meltPoolMetrics"
               ) -> tuple[np.ndarray, dict[str, np.ndarray], float | None]:
    """Times, the judged metrics and the bead's arrival at the section [s] of
    the function object ``section`` of ``case``."""
    rows = post.read_function_object_metrics(case, section)
    # A restart's table repeats the rows after its start time: keep the last
    _, last = np.unique(rows[::-1, 0], return_index=True)
    rows = rows[::-1][last]
    columns = post.BeadMetrics.FUNCTION_OBJECT_COLUMNS
    table = {name: rows[:, 1 + columns.index(name)] for name in METRICS}
    section_x = rows[-1, 1 + columns.index("bead_section")]
    return rows[:, 0], table, post.bead_arrival_time(case, section_x)


def case_steadiness(case: Path, section: str = "meltPoolMetrics",
                    min_window: float = MIN_WINDOW) -> Steadiness:
    """Judge the metrics that the function object ``section`` of ``case`` wrote,
    from the bead's arrival at its section on."""
    times, table, arrival = case_table(case, section)
    return judge(times, table, arrival, min_window)


def format_steadiness(verdict: Steadiness) -> str:
    """A table of the metrics' window means, as a welding engineer reads them."""
    scale = {name: (1e6, "mm2") if name.endswith("area") else (1.0, "-")
             if name == "dilution" else (1e3, "mm") for name in METRICS}
    lines = [f"{'metric':<14}{'last window':>13}{'window before':>15}{'drift':>10}"
             f"{'tolerance':>11}  unit"]
    for name, m in verdict.metrics.items():
        factor, unit = scale[name]
        lines.append(f"{name:<14}{factor * m.mean:13.4g}{factor * m.previous_mean:15.4g}"
                     f"{factor * m.change:10.3g}{factor * m.tolerance:11.3g}  {unit}"
                     f"{'' if m.steady else '  changing'}")
    lines.append(f"windows of {verdict.window:.3g} s to t = {verdict.end_time:.4g} s: "
                 f"{'quasi-steady' if verdict.steady else 'not steady'} ({verdict.reason})")
    return "\n".join(lines)
