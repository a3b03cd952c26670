"""The bead report's criterion: the mean section of a rippled bead (unit tests)."""
from __future__ import annotations

import numpy as np
import pytest

from ldna.validation import AVERAGING_WINDOW, STEADY_TOLERANCE, steadiness, window_mean

#: A bead of mean section 35 mm2 whose area swings by 10 % with the window's period
MEAN_AREA = 35e-6
RIPPLE = 3.5e-6


def sampled(end: float, trend: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Irregular time steps (as the adjustable step writes them) of a rippled area."""
    rng = np.random.default_rng(3)
    times = np.cumsum(rng.uniform(0.5e-3, 1.5e-3, int(end / 1e-3) + 10))
    times = times[times <= end]
    areas = (MEAN_AREA * (1 + trend * times)
             + RIPPLE * np.sin(2 * np.pi * times / AVERAGING_WINDOW))
    return times, areas


@pytest.mark.unit
def test_window_mean_of_a_ripple_is_its_mean() -> None:
    times, areas = sampled(3.0)
    mean = window_mean(times, areas, times[-1] - AVERAGING_WINDOW, times[-1])
    # A window of whole periods: the ripple averages out but for the
    # steps' discreteness at its ends
    assert mean == pytest.approx(MEAN_AREA, rel=2e-3)


@pytest.mark.unit
def test_steady_ripple_passes_and_a_growing_bead_does_not() -> None:
    steady = steadiness(*sampled(3.0))
    assert steady["steady"] and steady["change"] < STEADY_TOLERANCE
    assert steady["min"] == pytest.approx(MEAN_AREA - RIPPLE, rel=1e-3)
    assert steady["max"] == pytest.approx(MEAN_AREA + RIPPLE, rel=1e-3)
    # 2.5 % a second: the two windows' means differ by about 1.2 %
    growing = steadiness(*sampled(3.0, trend=0.025))
    assert not growing["steady"]
    # Too short a run for two windows
    assert not steadiness(*sampled(0.8))["steady"]
