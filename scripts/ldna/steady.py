"""Is the bead quasi-steady?  (``ldna steady``)

A weld in the moving frame is quasi-steady when what a macro-section shows
stops changing.  The bead ripples (the pool sloshes: in the template's runs
the section's area swings by about 10 % with a period of 0.6-0.7 s), so each
metric is judged on its time-weighted mean over a window of whole ripple
periods: quasi-steady when the means over the last window and over the
window before agree, for every metric, within ``RELATIVE_TOLERANCE`` of the
last mean or of the bead's own size in that direction (``SCALES``: the
penetration against the bead's height, the bonded width against its width,
the fused area against its area; a metric that is zero, such as the
penetration of a clad that did not fuse, is steady at zero).  The window is the bead area's ripple period, measured from
its upward crossings of its mean, times the whole number that reaches
``MIN_WINDOW``; without a ripple, ``MIN_WINDOW``.  Two windows must lie
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
    """One metric over the last two windows (SI units)."""

    mean: float
    previous_mean: float
    change: float
    tolerance: float
    low: float
    high: float

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
    means = {name: (window_mean(times, table[name], end - window, end),
                    window_mean(times, table[name], end - 2 * window, end - window))
             for name in METRICS}
    metrics = {}
    for name in METRICS:
        last, previous = means[name]
        scale = 1.0 if SCALES[name] is None else abs(means[SCALES[name]][0])
        in_last = times >= end - window
        metrics[name] = MetricSteadiness(
            mean=last, previous_mean=previous, change=abs(last - previous),
            tolerance=RELATIVE_TOLERANCE * max(abs(last), scale),
            low=float(table[name][in_last].min()), high=float(table[name][in_last].max()))
    if end < start:
        verdict, reason = False, (f"the bead deposited by the run reaches the section at "
                                  f"{start:.3g} s, after this run's end")
    elif end - start < 2 * window:
        verdict, reason = False, (f"too short: {end - start:.3g} s after the bead's arrival, "
                                  f"two windows of {window:.3g} s needed")
    elif not metrics["bead_area"].mean > 0:
        verdict, reason = False, "no bead at the section"
    else:
        changing = [n for n, m in metrics.items() if not m.steady]
        verdict = not changing
        reason = ("every metric's mean within its tolerance of the window before" if verdict
                  else "still changing: " + ", ".join(changing))
    return Steadiness(verdict, reason, end, window, metrics)


#: Spacing of the end times at which ``first_steady`` judges a run [s]
JUDGING_INTERVAL = 0.05


def first_steady(times: np.ndarray, table: dict[str, np.ndarray], start: float | None = None,
                 min_window: float = MIN_WINDOW) -> float | None:
    """The first end time, every JUDGING_INTERVAL, at which the run up to it is
    judged quasi-steady (the time a run needed); None if never."""
    first = float(times[0]) if start is None else max(float(start), float(times[0]))
    for end in np.arange(first + 2 * min_window, float(times[-1]) + 1e-12, JUDGING_INTERVAL):
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
    lines = [f"{'metric':<14}{'last window':>13}{'window before':>15}{'change':>10}"
             f"{'tolerance':>11}  unit"]
    for name, m in verdict.metrics.items():
        factor, unit = scale[name]
        lines.append(f"{name:<14}{factor * m.mean:13.4g}{factor * m.previous_mean:15.4g}"
                     f"{factor * m.change:10.3g}{factor * m.tolerance:11.3g}  {unit}"
                     f"{'' if m.steady else '  changing'}")
    lines.append(f"windows of {verdict.window:.3g} s to t = {verdict.end_time:.4g} s: "
                 f"{'quasi-steady' if verdict.steady else 'not steady'} ({verdict.reason})")
    return "\n".join(lines)
