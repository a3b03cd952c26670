"""The bead report's criterion: the mean section of a rippled bead (unit tests)."""
from __future__ import annotations

import numpy as np
import pytest

from ldna.validation import (MIN_AVERAGING_WINDOW, STEADY_TOLERANCE, averaging_window,
                             ripple_period, steadiness, window_mean)

#: A bead of mean section 35 mm2 whose area swings by 10 % with a period
#: longer than the shortest window (as the template's bead: 0.6-0.7 s)
MEAN_AREA = 35e-6
RIPPLE = 3.5e-6
PERIOD = 0.65


def sampled(end: float, trend: float = 0.0, period: float = PERIOD
            ) -> tuple[np.ndarray, np.ndarray]:
    """Irregular time steps (as the adjustable step writes them) of a rippled area."""
    rng = np.random.default_rng(3)
    times = np.cumsum(rng.uniform(0.5e-3, 1.5e-3, int(end / 1e-3) + 10))
    times = times[times <= end]
    areas = (MEAN_AREA * (1 + trend * times)
             + RIPPLE * np.sin(2 * np.pi * times / period))
    return times, areas


@pytest.mark.unit
def test_the_window_is_whole_ripple_periods() -> None:
    times, areas = sampled(4.0)
    assert ripple_period(times, areas, 0.0) == pytest.approx(PERIOD, rel=1e-2)
    assert averaging_window(times, areas, 0.0) == pytest.approx(PERIOD, rel=1e-2)
    # A short ripple: as many periods as make the shortest window
    short = sampled(4.0, period=0.2)
    assert averaging_window(*short, 0.0) == pytest.approx(0.6, rel=1e-2)
    # No ripple: the shortest window
    assert averaging_window(times, np.full_like(times, MEAN_AREA), 0.0) == MIN_AVERAGING_WINDOW


@pytest.mark.unit
def test_window_mean_of_a_ripple_is_its_mean() -> None:
    times, areas = sampled(4.0)
    window = averaging_window(times, areas, 0.0)
    mean = window_mean(times, areas, times[-1] - window, times[-1])
    # A window of whole periods: the ripple averages out but for the
    # period's estimate and the steps' discreteness at its ends
    assert mean == pytest.approx(MEAN_AREA, rel=2e-3)
    # A window of 0.5 s on the 0.65 s ripple does not average it out
    off = window_mean(times, areas, times[-1] - 0.5, times[-1])
    assert abs(off / MEAN_AREA - 1) > STEADY_TOLERANCE


@pytest.mark.unit
def test_steady_ripple_passes_and_a_growing_bead_does_not() -> None:
    steady = steadiness(*sampled(4.0))
    assert steady["steady"] and steady["change"] < STEADY_TOLERANCE
    assert steady["min"] == pytest.approx(MEAN_AREA - RIPPLE, rel=1e-3)
    assert steady["max"] == pytest.approx(MEAN_AREA + RIPPLE, rel=1e-3)
    # 2.5 % a second: the two windows' means differ by about 1.6 %
    growing = steadiness(*sampled(4.0, trend=0.025))
    assert not growing["steady"]
    # Too short after the bead's arrival for two windows
    assert not steadiness(*sampled(4.0), start=3.0)["steady"]
