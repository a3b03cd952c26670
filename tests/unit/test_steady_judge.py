"""``ldna steady``'s criterion on synthetic rippled metrics and domain
balances (a real run whose bead is still growing is tests/solver/test_steady.py)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ldna.steady import (BALANCE_TOLERANCE, JUDGING_INTERVAL, METRICS, MIN_WINDOW, NOISE_CAP,
                         RELATIVE_TOLERANCE, SCALES, WINDOWS, DomainBalance, averaging_window,
                         first_steady, judge, ripple_period, window_mean)
from ldna import steady as steady_module

#: A bead of mean section 35 mm2 whose area swings by 10 % with a period
#: longer than the shortest window (as the template's bead: 0.6-0.7 s)
MEAN_AREA = 35e-6
RIPPLE = 3.5e-6
PERIOD = 0.65
#: The other metrics of the synthetic bead: means [SI], rippling with the area
MEANS = {"bead_area": MEAN_AREA, "bead_width": 15e-3, "bead_height": 3e-3,
         "bonded_width": 10e-3, "penetration": 0.3e-3, "fused_area": 3e-6, "dilution": 0.08,
         "pool_length": 15e-3, "pool_width": 11e-3}


def sampled(end: float, trend: float = 0.0, period: float = PERIOD
            ) -> tuple[np.ndarray, np.ndarray]:
    """Irregular time steps (as the adjustable step writes them) of a rippled area."""
    rng = np.random.default_rng(3)
    times = np.cumsum(rng.uniform(0.5e-3, 1.5e-3, int(end / 1e-3) + 10))
    times = times[times <= end]
    areas = (MEAN_AREA * (1 + trend * times)
             + RIPPLE * np.sin(2 * np.pi * times / period))
    return times, areas


def bead(end: float, growing: str | None = None, trend: float = 0.025
         ) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Every metric rippling by 10 % about its mean; ``growing`` grows by ``trend`` a second."""
    times, _ = sampled(end)
    ripple = 0.1 * np.sin(2 * np.pi * times / PERIOD)
    table = {name: mean * (1 + ripple + (trend * times if name == growing else 0))
             for name, mean in MEANS.items()}
    return times, table


def test_the_window_is_whole_ripple_periods() -> None:
    times, areas = sampled(4.0)
    assert ripple_period(times, areas, 0.0) == pytest.approx(PERIOD, rel=1e-2)
    assert averaging_window(times, areas, 0.0) == pytest.approx(PERIOD, rel=1e-2)
    # A short ripple: as many periods as make the shortest window
    short = sampled(4.0, period=0.1)
    assert averaging_window(*short, 0.0) == pytest.approx(
        0.1 * math.ceil(MIN_WINDOW / 0.1), rel=1e-2)
    # No ripple: the shortest window
    assert averaging_window(times, np.full_like(times, MEAN_AREA), 0.0) == MIN_WINDOW


def test_window_mean_of_a_ripple_is_its_mean() -> None:
    times, areas = sampled(4.0)
    window = averaging_window(times, areas, 0.0)
    mean = window_mean(times, areas, times[-1] - window, times[-1])
    # A window of whole periods: the ripple averages out but for the
    # period's estimate and the steps' discreteness at its ends
    assert mean == pytest.approx(MEAN_AREA, rel=2e-3)
    # A window of 0.5 s on the 0.65 s ripple does not average it out
    off = window_mean(times, areas, times[-1] - 0.5, times[-1])
    assert abs(off / MEAN_AREA - 1) > RELATIVE_TOLERANCE


def test_a_steady_ripple_passes() -> None:
    verdict = judge(*bead(4.0))
    assert verdict.steady, verdict.reason
    area = verdict.metrics["bead_area"]
    assert area.low == pytest.approx(0.9 * MEAN_AREA, rel=1e-3)
    assert area.high == pytest.approx(1.1 * MEAN_AREA, rel=1e-3)


@pytest.mark.parametrize("metric", METRICS)
def test_any_growing_metric_is_not_steady(metric: str) -> None:
    """Growing by 1.6 % of the bead's size in that direction per window
    (2.5 % a second of the metric for the bead's own sizes)."""
    scale = MEANS[SCALES[metric]] if SCALES[metric] else 1.0
    trend = 0.025 * max(scale, MEANS[metric]) / MEANS[metric]
    verdict = judge(*bead(4.0, growing=metric, trend=trend))
    assert not verdict.steady
    assert verdict.reason == f"still changing: {metric}"


def test_a_longer_shortest_window_is_whole_periods_and_needs_four() -> None:
    """``ldna steady --min-window S``: windows of whole ripple periods of at
    least S, four of them after the bead's arrival."""
    shortest = 4 * PERIOD
    verdict = judge(*bead(13.5), 0.0, min_window=shortest)
    periods = verdict.window / PERIOD
    assert verdict.window >= shortest
    assert periods == pytest.approx(round(periods), rel=0.02)
    assert verdict.steady, verdict.reason
    short = judge(*bead(3 * shortest), 0.0, min_window=shortest)
    assert not short.steady and short.reason.startswith("too short")


def test_a_small_metric_is_read_to_the_beads_size() -> None:
    """A 0.3 mm penetration drifting by 5 um a window (1.6 % of itself, 0.17 %
    of the 3 mm bead): as steady as a macro-section reads."""
    verdict = judge(*bead(4.0, growing="penetration"))
    assert verdict.steady, verdict.reason
    assert verdict.metrics["penetration"].tolerance == pytest.approx(
        RELATIVE_TOLERANCE * verdict.metrics["bead_height"].mean)


def test_the_first_steady_time() -> None:
    """A bead that grows linearly until G = 1.5 s, then ripples about its mean:
    not judged steady while the last two windows still hold growth (their
    means rise by more than the noise cap, 5 %, a window), so no earlier
    than G + 2 W - sqrt(0.02 G W) (where a window before the last holds a
    deficit of 1 %); steady once all WINDOWS windows lie after the growth,
    G + WINDOWS W, or before; a bead still growing at the end: never."""
    growth_end = 1.5
    times, table = bead(4.0)
    growth = np.clip(times / growth_end, 0, 1)
    grown = {name: values * growth for name, values in table.items()}
    first = first_steady(times, grown)
    earliest = growth_end + 2 * PERIOD - np.sqrt(2 * RELATIVE_TOLERANCE * growth_end * PERIOD)
    print(f"first steady at {first} s, earliest by the criterion {earliest:.3f} s")
    # The ripple's residue in a window mean: +-0.1 s of its phase here
    assert first is not None
    assert earliest - 0.1 <= first <= growth_end + WINDOWS * PERIOD + JUDGING_INTERVAL
    assert first_steady(*bead(4.0, growing="bead_width")) is None


def scattered(end: float, scatter: float, trend: float = 0.0
              ) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """The rippling bead with its metrics scattered at random as splashes
    make them: independent values every 0.1 s, ``scatter`` of the mean
    (standard deviation), held between them; ``trend`` a second on all."""
    times, table = bead(end)
    rng = np.random.default_rng(7)
    blocks = np.floor(times / 0.1).astype(int)
    noise = rng.normal(0.0, scatter, (len(MEANS), blocks.max() + 1))
    return times, {name: values * (1 + noise[i][blocks] + trend * times)
                   for i, (name, values) in enumerate(table.items())}


def test_a_scattered_steady_bead_passes_and_a_drift_beyond_the_scatter_does_not() -> None:
    """Splash scatter of 10 % in 0.1 s blocks scatters 0.65 s window means by
    about 4 %, which 1 % alone would never pass; a drift of twice the noise
    cap a window (16 % a second over 0.65 s windows) is not steady."""
    verdict = judge(*scattered(4.0, 0.10))
    print(verdict.reason, {n: f"{m.tolerance / max(abs(m.mean), 1e-30):.3f}"
                           for n, m in verdict.metrics.items()})
    assert verdict.steady, verdict.reason
    drift = 2 * NOISE_CAP / PERIOD
    assert not judge(*scattered(4.0, 0.10, trend=drift)).steady


def test_too_short_or_empty_is_not_steady() -> None:
    assert "too short" in judge(*bead(4.0), start=3.0).reason
    assert "after this run's end" in judge(*bead(4.0), start=5.0).reason
    times, table = bead(4.0)
    table["bead_area"] = np.zeros_like(times)
    assert judge(times, table).reason == "no bead at the section"
    # A metric that stays zero (no fusion) is steady at zero
    times, table = bead(4.0)
    table["penetration"] = np.zeros_like(times)
    assert judge(times, table).steady


#: The template's throughput: 2.08 g/s of metal from the wires, 3.4 kW of heat
FEED = 2.08e-3
HEAT = 3.4e3


def domain(end: float, mass_drift: float = 0.0, heat_drift: float = 0.0) -> DomainBalance:
    """A domain that holds 50 g and 8.1 kJ, changing by the given shares of
    its throughput, with the droplets' steps (a droplet of the feed every 5 ms
    in, as much out at random) on its mass; wires feed FEED at HEAT."""
    rng = np.random.default_rng(5)
    times = np.arange(0.0, end, 2e-4)
    droplets = FEED * 5e-3 * (np.floor(times / 5e-3) - np.floor(
        times / 5e-3 + rng.uniform(0.0, 1.0, times.size)))
    mass = 50e-3 + mass_drift * FEED * times + droplets
    enthalpy = 8.1e3 + heat_drift * HEAT * times
    fed = FEED * times
    # Without the laser, the droplets bring all the heat
    return DomainBalance(times, mass, enthalpy, times, fed, fed * HEAT / FEED,
                         np.zeros(0), np.zeros(0))


@pytest.mark.parametrize("mass_drift, heat_drift, steady", [
    (0.0, 0.0, True), (0.5 * BALANCE_TOLERANCE, -0.5 * BALANCE_TOLERANCE, True),
    (2 * BALANCE_TOLERANCE, 0.0, False), (0.0, -2 * BALANCE_TOLERANCE, False),
    (1.0, 1.0, False)])
def test_the_domain_must_stop_filling_and_heating(mass_drift: float, heat_drift: float,
                                                   steady: bool) -> None:
    """Over the judged windows the domain's metal and heat may change by
    BALANCE_TOLERANCE of what flows through; a flat start fills at the feed
    (share 1), a hot start cools.  The section's metrics are steady here, so
    the balance alone decides."""
    times, table = bead(4.0)
    balance = domain(4.0, mass_drift, heat_drift)
    drift = balance.drift(4.0 - 1.0, 4.0)
    assert drift.mass_throughput == pytest.approx(FEED, rel=1e-9)
    assert drift.heat_throughput == pytest.approx(HEAT, rel=1e-9)
    assert drift.mass_rate / FEED == pytest.approx(mass_drift, abs=2e-3)
    assert drift.enthalpy_rate / HEAT == pytest.approx(heat_drift, abs=1e-9)
    verdict = judge(times, table, balance=balance)
    assert verdict.steady is steady, verdict.reason
    if not steady:
        assert "the domain's metal and heat" in verdict.reason
    assert judge(times, table).steady, "without the balance the section alone passes"


def test_the_part_ahead_of_the_section_is_judged_where_its_table_covers() -> None:
    """A continued weld whose workpiece behind the section still cools (the
    domain's heat falls by 10 % of the throughput) while the part ahead of
    the section is steady: judged on the part ahead where its table covers
    the windows, on the domain where it starts only later (a run continued
    from a saved state that did not write it)."""
    times, table = bead(4.0)
    cooling = domain(4.0, heat_drift=-0.1)
    steady_ahead = domain(4.0)
    for first_row, region, steady in ((0.0, "ahead of the section", True),
                                      (3.5, "domain", False)):
        kept = steady_ahead.times >= first_row
        balance = DomainBalance(
            cooling.times, cooling.mass, cooling.enthalpy, cooling.wire_times,
            cooling.added_mass, cooling.added_enthalpy, cooling.laser_times,
            cooling.laser_power,
            (steady_ahead.times[kept], steady_ahead.mass[kept], steady_ahead.enthalpy[kept]))
        verdict = judge(times, table, balance=balance)
        assert verdict.balance.region == region
        assert verdict.steady is steady, verdict.reason


def test_totals_since_each_restart_continue() -> None:
    """A restart's droplet table counts its added metal from 0 again."""
    first_run = np.array([0.0, 1.0, 2.0, 3.0])
    second_run = np.array([0.5, 1.5, 2.5])
    continued = steady_module._continued(np.concatenate([first_run, second_run]))
    np.testing.assert_allclose(continued, [0.0, 1.0, 2.0, 3.0, 3.5, 4.5, 5.5])


def test_span_means_of_a_ramp(tmp_path: Path) -> None:
    """``ldna means``: over [1, 3] s a metric rising linearly from 0 at 0 s
    to 4 at 4 s has the mean 2 (the ramp's midpoint) and the largest value
    3; a laser's constant absorbed power is its mean."""
    metrics = tmp_path / "postProcessing" / "meltPoolMetrics" / "0"
    metrics.mkdir(parents=True)
    times = np.linspace(0.0, 4.0, 401)
    header = "# Time\t" + "\t".join(f"c{i}" for i in range(15)) + "\n"
    metrics.joinpath("meltPoolMetrics.dat").write_text(header + "".join(
        f"{t:.4f}" + f"\t{t:.6f}" * 15 + "\n" for t in times))
    laser = tmp_path / "postProcessing" / "laser" / "0"
    laser.mkdir(parents=True)
    laser.joinpath("power.dat").write_text(
        "# Time\tabsorbedMetal\tabsorbedGas\n"
        + "".join(f"{t:.4f}\t250\t150\n" for t in times))
    figures = steady_module.span_means(tmp_path, 1.0, 3.0)
    assert figures["bead_area_mean"] == pytest.approx(2.0, rel=1e-9)
    assert figures["bead_area_max"] == pytest.approx(3.0, rel=1e-9)
    assert figures["laser_absorbedMetal_mean"] == pytest.approx(250.0, rel=1e-12)
    assert "laser_absorbedPool_mean" not in figures
    with pytest.raises(ValueError, match="not within"):
        steady_module.span_means(tmp_path, 3.0, 5.0)
