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

The section's metrics cannot see the slowest part of the weld: the
substrate under and around the pool heats up (or, from too hot a start,
cools down) over the seconds the workpiece takes to pass the pool, while a
section's metrics may already sit on a plateau.  So the domain's own
balance is judged too (``DomainBalance``): over the judged windows its
metal mass and total enthalpy may change by at most ``BALANCE_TOLERANCE``
of what flows through it (the wires' metal; its enthalpy above the ambient
plus the laser's absorbed power).  In the template's run from a flat
substrate the enthalpy still rose by 1.2 kW (of 3.4 kW brought in) at
2.6 s, when 0.25 s windows of the section's metrics already passed; it
settled within 1.5 % from 3.75 s on (docs/validation/steady-start.md).
Where the run writes the totals of the part of the domain ahead of the
bead section (the ``upstreamTotals`` function object), that part's balance
is judged instead: what lies behind the section only leaves the domain,
and heat reaches back from it against the motion less than a millimetre
or two (Peclet number v d / a = 1.4 per mm).  A weld continued with changed
parameters from a saved state holds the saved weld's workpiece behind the
section until it has left the domain, (domain end - section) / v after
the bead's arrival: 1.1 s in the template, when the domain's totals still
change while everything the section depends on may be steady.

The metrics are those the ``meltPoolMetrics`` function object writes every
few steps (``postProcessing/<name>/*/meltPoolMetrics.dat``), the balance
the solver's ``balances`` table, the wires' ``droplets`` and the laser's
``power`` tables: the judgement needs no fields and works on a run that is
still going.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from . import post
from .case import Case
from .material import Metal

#: Shortest averaging window [s].  In the template's run from a flat
#: substrate (3-5.6 s) the section's metrics lose their autocorrelation
#: within 0.07-0.35 s (integral times 0.02-0.09 s), so means over 0.25 s
#: are nearly independent; what changes more slowly is the substrate's
#: heat, which the domain's balance judges
MIN_WINDOW = 0.25
#: Over the judged windows the domain's metal mass and enthalpy change by at
#: most this share of what flows through it (mass: the wires' feed; heat:
#: their enthalpy above the ambient plus the laser's absorbed power).  The
#: template's flat run: within 1.5 % from 3.75 s on, 35 % at 2.6 s; the
#: run from the first estimate (too hot) lost 2.6-8 % throughout its 2.7 s
BALANCE_TOLERANCE = 0.02
#: The table of the totals ahead of the bead section (function object and file)
UPSTREAM_TOTALS = ("upstreamTotals", "upstreamTotals")
#: The totals ahead of the section are judged when their table starts within
#: this share of the judged span after its start (its first row comes a
#: few steps after the run's start); else the domain's totals are
AHEAD_COVER_SLACK = 0.05
#: Column of each wire's metal added since the run's start in the droplet
#: sources' tables (``<wire>_addedMass``)
ADDED_MASS_SUFFIX = "_addedMass"
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
#: A judged stretch shorter than this [s] (for the shortest window
#: MIN_WINDOW; in proportion for another) whose bead area shows no ripple
#: period yet (three upward crossings of its trend) may ripple more slowly
#: than the windows, which would then take the ripple for noise: too short
UNRESOLVED_SPAN = 2 * WINDOWS * MIN_WINDOW
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
    values' upward crossings of their trend there (their running mean over
    ``WINDOWS`` shortest windows: a bead still growing ripples about its
    trend); None with fewer than three crossings."""
    after = times >= start
    t, v = times[after], values[after]
    if t.size < 3 or not t[-1] > t[0]:
        return None
    step = float(np.median(np.diff(t)))
    uniform = np.arange(t[0], t[-1], step)
    resampled = np.interp(uniform, t, v)
    width = max(1, int(round(WINDOWS * MIN_WINDOW / step)))
    padded = np.pad(resampled, (width // 2, width - 1 - width // 2), mode="edge")
    trend = np.convolve(padded, np.ones(width) / width, mode="valid")
    above = resampled > trend
    crossings = uniform[1:][above[1:] & ~above[:-1]]
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
    #: The domain's balance over the windows (None: not judged)
    balance: BalanceDrift | None = None

    def as_dict(self) -> dict:
        """JSON-ready: every metric's means, change, tolerance and range, and
        the domain's balance."""
        return {"steady": self.steady, "reason": self.reason, "end_time_s": self.end_time,
                "window_s": self.window,
                "metrics": {name: {**asdict(m), "steady": m.steady}
                            for name, m in self.metrics.items()},
                "balance": None if self.balance is None
                else {**asdict(self.balance), "steady": self.balance.steady}}


@dataclass
class BalanceDrift:
    """The metal mass and enthalpy of the domain (or of its part ahead of
    the section) over the judged windows [SI]."""

    #: Least-squares slopes of the domain's metal mass [kg/s] and total
    #: enthalpy [W] over the windows
    mass_rate: float
    enthalpy_rate: float
    #: What flows through: the wires' metal [kg/s], their enthalpy above the
    #: ambient plus the laser's absorbed power [W]
    mass_throughput: float
    heat_throughput: float
    #: Where the totals are summed: "domain" or "ahead of the section"
    region: str = "domain"

    @property
    def steady(self) -> bool:
        return bool(abs(self.mass_rate) <= BALANCE_TOLERANCE * self.mass_throughput
                    and abs(self.enthalpy_rate) <= BALANCE_TOLERANCE * self.heat_throughput)


def _slope(times: np.ndarray, values: np.ndarray) -> float:
    if times.size < 2 or np.ptp(times) <= 0:
        return float("nan")
    return float(np.polyfit(times, values, 1)[0])


@dataclass
class DomainBalance:
    """The tables a run writes that say whether its domain still fills or heats."""

    #: Steps of the solver's balances table: time, metal mass, total enthalpy
    times: np.ndarray
    mass: np.ndarray
    enthalpy: np.ndarray
    #: Steps of the wires' tables: time, metal added since the start [kg] and
    #: its enthalpy above the ambient [J]
    wire_times: np.ndarray
    added_mass: np.ndarray
    added_enthalpy: np.ndarray
    #: Steps of the laser's table: time and power absorbed [W] (empty without)
    laser_times: np.ndarray
    laser_power: np.ndarray
    #: Rows of the ``upstreamTotals`` table, if the run wrote it: time, metal
    #: mass and total enthalpy of the domain's part ahead of the bead section
    ahead: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    @classmethod
    def of(cls, case: Path) -> "DomainBalance | None":
        """The case's balance, or None without droplet sources or balances."""
        case = Case(case)
        try:
            balances = case.balances()
            # Each source's table read once (a running case appends rows)
            tables = [case.table(source, "droplets")
                      for source in case.tables_named("droplets")]
        except (FileNotFoundError, KeyError, ValueError):
            return None
        if not tables:
            return None
        rows = min(len(table) for table in tables)
        metal = Metal.from_case(case.path)
        ambient = metal.enthalpy(_case_scalar(case, "system/caseParameters",
                                              "ambientTemperature", 300.0))
        default_temperature = _case_scalar(case, "system/caseParameters",
                                           "dropletTemperature", float("nan"))
        wire_times = np.asarray(tables[0]["Time"][:rows], dtype=float)
        added_mass = np.zeros(rows)
        added_enthalpy = np.zeros(rows)
        for table in tables:
            for column in table.dtype.names:
                if not column.endswith(ADDED_MASS_SUFFIX):
                    continue
                wire = column[:-len(ADDED_MASS_SUFFIX)]
                temperature = _case_scalar(case, "constant/fvOptions",
                                           f"wireDroplets/wires/{wire}/temperature",
                                           default_temperature)
                if not math.isfinite(temperature):
                    # Without it the heat brought in is unknown: never judge
                    # the heat balance on a NaN
                    raise ValueError(f"{case.path}: no droplet temperature of {wire} "
                                     "(wireDroplets/wires/<wire>/temperature in "
                                     "constant/fvOptions, or dropletTemperature in "
                                     "system/caseParameters)")
                added = np.asarray(table[column][:rows], dtype=float)
                added_mass += added
                added_enthalpy += added * (metal.enthalpy(temperature) - ambient)
        try:
            laser = case.table("laser", "power")
            laser_times = laser["Time"]
            laser_power = laser["absorbedMetal"] + laser["absorbedGas"]
        except (FileNotFoundError, ValueError):
            laser_times = laser_power = np.zeros(0)
        try:
            table = case.table(*UPSTREAM_TOTALS)
            ahead = tuple(np.asarray(table[column], dtype=float)
                          for column in ("Time", "metalMass", "totalEnthalpy"))
        except (FileNotFoundError, ValueError):
            ahead = None
        return cls(balances["time"], balances["metal_mass"], balances["enthalpy"],
                   wire_times, _continued(added_mass), _continued(added_enthalpy),
                   np.asarray(laser_times), np.asarray(laser_power), ahead)

    def drift(self, start: float, end: float) -> BalanceDrift | None:
        """Rates and throughputs over [start, end]; None if a table does not
        cover it.  The totals ahead of the section where their table covers
        the span (a run continued from a saved state that did not write it
        has it from its own start only), else the domain's."""
        times, mass, enthalpy, region = self.times, self.mass, self.enthalpy, "domain"
        if self.ahead is not None and self.ahead[0].size > 1 and (
                self.ahead[0][0] <= start + AHEAD_COVER_SLACK * (end - start)):
            (times, mass, enthalpy), region = self.ahead, "ahead of the section"
        inside = (times >= start) & (times <= end)
        fed = (self.wire_times >= start) & (self.wire_times <= end)
        if inside.sum() < 2 or fed.sum() < 2:
            return None
        t = self.wire_times[fed]
        span = float(t[-1] - t[0])
        mass_throughput = float(self.added_mass[fed][-1] - self.added_mass[fed][0]) / span
        heat = float(self.added_enthalpy[fed][-1] - self.added_enthalpy[fed][0]) / span
        lit = (self.laser_times >= start) & (self.laser_times <= end)
        if lit.sum() > 1:
            heat += window_mean(self.laser_times, self.laser_power, start, end)
        return BalanceDrift(_slope(times[inside], mass[inside]),
                            _slope(times[inside], enthalpy[inside]),
                            mass_throughput, heat, region)


def _case_scalar(case: Case, file: str, entry: str, default: float) -> float:
    try:
        return case.scalar(file, entry)
    except (KeyError, ValueError):
        return default


def _continued(totals: np.ndarray) -> np.ndarray:
    """Totals "since the start of the run" over runs that restarted: each
    restart counts from 0 again, so a drop continues from the total before."""
    steps = np.diff(totals, prepend=0.0)
    restarted = steps < 0
    steps[restarted] = totals[restarted]
    return np.cumsum(steps)


def judge(times: np.ndarray, table: dict[str, np.ndarray], start: float | None = None,
          min_window: float = MIN_WINDOW, balance: DomainBalance | None = None) -> Steadiness:
    """Judge the metrics ``table`` (name -> values at ``times``) for steadiness.

    ``start``: when the bead reached the section (default: the first time);
    ``balance``: the domain's, judged over the same windows (None: the
    section's metrics alone).
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
    drift = None if balance is None else balance.drift(end - WINDOWS * window, end)
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
        if drift is not None and not drift.steady:
            changing.append("the domain's metal and heat" if drift.region == "domain"
                            else f"the metal and heat {drift.region}")
        unresolved_span = UNRESOLVED_SPAN * min_window / MIN_WINDOW
        if changing:
            verdict, reason = False, "still changing: " + ", ".join(changing)
        elif (end - start < unresolved_span
              and ripple_period(times, table["bead_area"], start) is None):
            # What passed may be a ripple slower than the windows
            verdict, reason = False, (f"too short: {end - start:.3g} s after the bead's "
                                      f"arrival show no ripple period yet "
                                      f"({unresolved_span:.3g} s without one are needed)")
        else:
            verdict, reason = True, "every metric's drift within its tolerance"
    return Steadiness(verdict, reason, end, window, metrics, drift)


#: Spacing of the end times at which ``first_steady`` judges a run [s]
JUDGING_INTERVAL = 0.05


def first_steady(times: np.ndarray, table: dict[str, np.ndarray], start: float | None = None,
                 min_window: float = MIN_WINDOW,
                 balance: DomainBalance | None = None) -> float | None:
    """The first end time, every JUDGING_INTERVAL and at the last time, at
    which the run up to it is judged quasi-steady (the time a run needed);
    None if never."""
    first = float(times[0]) if start is None else max(float(start), float(times[0]))
    ends = np.arange(first + WINDOWS * min_window, float(times[-1]) + 1e-12, JUDGING_INTERVAL)
    for end in [*ends, float(times[-1])]:
        upto = times <= end
        if upto.sum() > 2 and judge(times[upto], {n: v[upto] for n, v in table.items()},
                                    start, min_window, balance).steady:
            return float(times[upto][-1])
    return None


def case_table(case: Path, section: str = "meltPoolMetrics", names: tuple[str, ...] = METRICS
               ) -> tuple[np.ndarray, dict[str, np.ndarray], float | None]:
    """Times, the metrics ``names`` (default: the judged ones; NaN where the
    table has no such column, as the chemical dilution of one metal) and the
    bead's arrival at the section [s] of the function object ``section`` of
    ``case``."""
    rows = post.read_function_object_metrics(case, section)
    # A restart's table repeats the rows after its start time: keep the last
    _, last = np.unique(rows[::-1, 0], return_index=True)
    rows = rows[::-1][last]
    columns = post.BeadMetrics.FUNCTION_OBJECT_COLUMNS
    table = {name: rows[:, 1 + columns.index(name)] if 1 + columns.index(name) < rows.shape[1]
             else np.full(len(rows), np.nan) for name in names}
    section_x = rows[-1, 1 + columns.index("bead_section")]
    return rows[:, 0], table, post.bead_arrival_time(case, section_x)


def case_steadiness(case: Path, section: str = "meltPoolMetrics",
                    min_window: float = MIN_WINDOW) -> Steadiness:
    """Judge the metrics that the function object ``section`` of ``case`` wrote,
    from the bead's arrival at its section on, with the domain's balance."""
    times, table, arrival = case_table(case, section)
    return judge(times, table, arrival, min_window, DomainBalance.of(case))


#: ``span_means`` needs the section's table to cover the span to within this
#: share of its length at either end
SPAN_COVER_SLACK = 0.01
#: Columns of the laser's power table averaged by ``span_means`` [W]
LASER_COLUMNS = ("absorbedMetal", "absorbedGas", "absorbedPool", "absorbedDeposit",
                 "absorbedSubstrate")


def span_means(case: Path, start: float, end: float,
               section: str = "meltPoolMetrics") -> dict[str, float]:
    """Time-weighted means over [start, end] of every column the section's
    function object wrote (``<metric>_mean``, SI) and their largest values
    (``<metric>_max``: a bond that forms only where the beam's ends pass),
    and of the laser's absorbed power by region (``laser_<column>_mean``
    [W]) if the case has a laser.  What a study compares over the same span
    of each member's own bead."""
    rows = post.read_function_object_metrics(case, section)
    # A restart's table repeats the rows after its start time: keep the last
    _, last = np.unique(rows[::-1, 0], return_index=True)
    rows = rows[::-1][last]
    times = rows[:, 0]
    # The table's rows come every few steps: its last may lie a little
    # before the run's end
    slack = SPAN_COVER_SLACK * (end - start)
    if not (times[0] - slack <= start < end <= times[-1] + slack):
        raise ValueError(f"{case}: the span {start:g}-{end:g} s is not within the "
                         f"section's table ({times[0]:g}-{times[-1]:g} s)")
    inside = (times >= start) & (times <= end)
    figures: dict[str, float] = {"start_s": start, "end_s": end}
    columns = post.BeadMetrics.FUNCTION_OBJECT_COLUMNS
    for index, name in enumerate(columns[:rows.shape[1] - 1]):
        values = rows[:, 1 + index]
        figures[f"{name}_mean"] = window_mean(times, values, start, end)
        figures[f"{name}_max"] = float(values[inside].max())
    try:
        laser = Case(case).table("laser", "power")
    except (FileNotFoundError, ValueError):
        return figures
    laser_times = np.asarray(laser["Time"], dtype=float)
    for column in LASER_COLUMNS:
        if column in laser.dtype.names:
            figures[f"laser_{column}_mean"] = window_mean(
                laser_times, np.asarray(laser[column], dtype=float), start, end)
    return figures


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
    if verdict.balance is not None:
        b = verdict.balance
        lines.append(f"{b.region}: metal {1e3 * b.mass_rate:+.3g} g/s of {1e3 * b.mass_throughput:.3g} "
                     f"fed, heat {b.enthalpy_rate:+.4g} W of {b.heat_throughput:.4g} brought in "
                     f"(tolerance {100 * BALANCE_TOLERANCE:g} %)"
                     f"{'' if b.steady else '  changing'}")
    lines.append(f"windows of {verdict.window:.3g} s to t = {verdict.end_time:.4g} s: "
                 f"{'quasi-steady' if verdict.steady else 'not steady'} ({verdict.reason})")
    return "\n".join(lines)
