"""``ldna bench --json``: the benchmark's figures as one object, with the
ratios the performance goals are stated in."""
from __future__ import annotations

import json

import pytest

from ldna.dev.benchmark import (TEMPLATE, SolverCosts, StepCost, _median_ratio,
                                 _monte_carlo_laser)


def test_summary_holds_the_ratios_of_the_measured_times() -> None:
    costs = SolverCosts(
        level=0, cells=36077, steps=40, delta_t=5e-5, start_time=0.1,
        ldna_no_effects=0.30, compressible_inter_foam=0.25,
        effects=[StepCost("wireDroplets", 0.33, 0.33 / 0.30)],
        all_effects=0.45, template_delta_t=1.2e-4,
        serial_all_effects=0.45, parallel_all_effects=0.30, n_procs=2, repeats=3,
        reference_limiter_iterations=10, default_reference=0.20,
        ldna_alpha_excursion=0.0, reference_alpha_excursions={3: 2e-4, 10: 5e-9},
        effect_active={"wireDroplets": True}, effect_evidence={"wireDroplets": "inserted"},
        spreads={"wireDroplets": 0.015})
    summary = json.loads(json.dumps(costs.summary()))
    assert summary["reference_limiter_iterations"] == 10
    assert summary["default_limiter_iterations"] == 3
    assert summary["all_effects_ratio_default_reference"] == pytest.approx(0.45 / 0.20)
    assert summary["reference_alpha_excursions"] == {"3": 2e-4, "10": 5e-9}
    assert summary["effect_active"] == {"wireDroplets": True}
    assert summary["ratio_spreads"] == {"wireDroplets": 0.015}
    assert summary["reference_s_per_step"] == 0.25
    assert summary["no_effects_ratio"] == pytest.approx(0.30 / 0.25)
    assert summary["all_effects_ratio"] == pytest.approx(0.45 / 0.25)
    assert summary["effect_ratios"] == {"wireDroplets": pytest.approx(1.1)}
    assert summary["np2_efficiency"] == pytest.approx(0.45 / (2 * 0.30))
    assert (summary["cells"], summary["level"]) == (36077, 0)


def test_ratios_are_medians_of_each_rounds_ratio() -> None:
    """A slow spell of the machine in one round slows both variants of it:
    the round's own ratio is unchanged, and the median ignores an outlier."""
    effect = [0.33, 0.66, 0.34, 0.33, 0.40]
    none = [0.30, 0.60, 0.30, 0.30, 0.30]
    ratio, spread = _median_ratio(effect, none)
    assert ratio == pytest.approx(1.1)
    ratios = sorted(a / b for a, b in zip(effect, none))
    assert spread == pytest.approx((ratios[-1] - ratios[0]) / ratio)


def test_monte_carlo_variant_changes_only_the_templates_absorption_model() -> None:
    options = (TEMPLATE / "constant" / "fvOptions").read_text()
    variant = _monte_carlo_laser(options)
    laser = variant[variant.index("\nlaser\n"):]
    laser = laser[:laser.index("\n}\n")]
    assert "absorptionModel     monteCarlo;" in laser
    assert "beerLambert" not in variant
    # Every other line of the template stays
    kept = [line for line in options.splitlines() if "beerLambert" not in line
            and "nRaysAcross" not in line and not line.strip().startswith("//")]
    assert all(line in variant for line in kept)
