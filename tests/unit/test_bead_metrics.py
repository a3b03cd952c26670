"""Bead metrics that ``ldna post`` reads without a run: the wetting angle of
known caps, a run shorter than the bead's travel, a restarted run's rows
(the meltPoolMetrics function object on prescribed and solved fields is
tests/solver/test_post.py).
"""
from __future__ import annotations

import math
import os
import time
from pathlib import Path

import numpy as np
import pytest

from ldna.post import bead_not_yet_there, read_function_object_metrics, wetting_angle


#: Columns across the synthetic circular-cap bead (width 2 a) of the wetting-angle test
CAP_COLUMNS = 400
CAP_HALF_WIDTH = 7.5e-3


@pytest.mark.parametrize("contact_angle", [20.0, 45.0, 60.0, 90.0])
def test_wetting_angle_of_a_circular_cap(contact_angle: float) -> None:
    """The secant angle of a circular-cap bead against its closed form.

    A cap of half-width a and contact angle theta has radius R = a / sin(theta)
    and height H = a tan(theta / 2); its flank reaches H / 2 at
    |y| = sqrt(R^2 - (R - H / 2)^2), so the secant angle is
    atan(H / 2 / (a - |y|)).  Columns of width a / 200 give it within 0.5 deg.
    """
    a = CAP_HALF_WIDTH
    theta = math.radians(contact_angle)
    radius = a / math.sin(theta)
    height = a * math.tan(theta / 2)
    y = np.linspace(-a, a, CAP_COLUMNS + 1)
    y = 0.5 * (y[1:] + y[:-1])
    centre_height = height - radius
    profile = np.clip(np.sqrt(np.clip(radius**2 - y**2, 0, None)) + centre_height, 0, None)
    flank = math.sqrt(radius**2 - (radius - height / 2) ** 2)
    expected = math.degrees(math.atan2(height / 2, a - flank))
    measured = wetting_angle(y, profile, -a, a)
    print(f"contact angle {contact_angle:g}: secant {expected:.2f}, measured {measured:.2f}")
    assert measured == pytest.approx(expected, abs=0.5)
    assert 0 < measured < 90


def test_wetting_angle_of_flat_and_square_deposits() -> None:
    """No metal: angle 0; a rectangle of height H whose toes lie d outside its
    outermost columns: atan(H / 2 / d), near 90 degrees."""
    y = np.linspace(-1e-3, 1e-3, 201)
    assert wetting_angle(y, np.zeros_like(y), -1e-3, 1e-3) == 0.0
    height, toe_gap = 1e-3, 1e-5
    expected = math.degrees(math.atan2(height / 2, toe_gap))
    measured = wetting_angle(y, np.full_like(y, height), -1e-3 - toe_gap, 1e-3 + toe_gap)
    assert measured == pytest.approx(expected, rel=1e-9)


def test_a_run_shorter_than_the_bead_travel_says_so() -> None:
    section = 20.1e-3
    early = bead_not_yet_there(arrival=1.48, time=0.5, section=section)
    assert early is not None and "20.10 mm" in early and "t = 1.48 s" in early
    assert "--end-time 2" in early and "of the substrate" in early
    assert bead_not_yet_there(arrival=1.48, time=1.48, section=section) is None
    assert bead_not_yet_there(arrival=None, time=0.5, section=section) is None
    # Started at 10 s from another weld: the section holds that weld's bead
    changed = bead_not_yet_there(arrival=11.48, time=10.5, section=section, weld_start=10.0)
    assert changed is not None and "started from at t = 10 s" in changed
    assert "--end-time 12" in changed


def test_a_run_restarted_from_the_same_time_replaces_the_earlier_rows(tmp_path: Path) -> None:
    """OpenFOAM's writeFile names the table of a second run from the same
    start time meltPoolMetrics_<time>.dat: the metrics are that run's, not
    the first file's (a killed run resumed from its last written time)."""
    from ldna.post import read_function_object_metrics

    folder = tmp_path / "postProcessing" / "meltPoolMetrics" / "12.8"
    folder.mkdir(parents=True)
    header = "# Time\t" + "\t".join(f"c{i}" for i in range(15)) + "\n"

    def rows(times: list[float], value: float) -> str:
        return "".join(f"{t}" + f"\t{value}" * 15 + "\n" for t in times)

    (folder / "meltPoolMetrics.dat").write_text(header + rows([12.81, 12.82], 1.0))
    newer = folder / "meltPoolMetrics_12.8.dat"
    newer.write_text(header + rows([12.81, 12.82, 12.83, 12.84], 2.0))
    os.utime(newer, (time.time() + 10, time.time() + 10))
    table = read_function_object_metrics(tmp_path)
    np.testing.assert_array_equal(table[:, 0], [12.81, 12.82, 12.83, 12.84])
    assert (table[:, 1:] == 2.0).all()
