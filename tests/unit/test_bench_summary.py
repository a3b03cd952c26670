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


def _dump(path, total: int) -> None:
    """A callgrind dump's head as valgrind 3.19 writes it (the fields the
    reader needs: the event and its total)."""
    path.write_text(f"# callgrind format\nversion: 1\ncreator: callgrind-3.19.0\n"
                    f"events: Ir\nsummary: {total}\n\nfl=(1) a.C\nfn=(1) main\n0 {total}\n"
                    f"\ntotals: {total}\n")


def test_step_counts_leave_out_the_start_up_the_first_step_and_the_end(tmp_path) -> None:
    """Callgrind dumps before each step: dump 1 is the start-up, dump k + 1
    step k, and the last file (no number) the last step with the end; the
    first step, where a model may set itself up, is left out unless asked."""
    from ldna.dev.benchmark import callgrind_step_counts

    prefix = tmp_path / "steps"
    _dump(tmp_path / "steps.1", 800)
    for step, total in enumerate((300, 130, 128, 127), start=1):
        _dump(tmp_path / f"steps.{step + 1}", total)
    _dump(prefix, 150)
    assert callgrind_step_counts(prefix, 3) == [130, 128, 127]
    assert callgrind_step_counts(prefix, 2) == [130, 128]
    assert callgrind_step_counts(prefix, 2, first=1) == [300, 130]
    with pytest.raises(RuntimeError, match="step 5"):
        callgrind_step_counts(prefix, 4)


def test_instruction_ratios_are_taken_against_no_effects_and_the_reference() -> None:
    costs = SolverCosts(
        level=0, cells=36077, steps=40, delta_t=5e-5, start_time=0.1,
        ldna_no_effects=0.30, compressible_inter_foam=0.25,
        effects=[StepCost("laser", 0.33, 1.1)], all_effects=0.45,
        template_delta_t=1.2e-4, serial_all_effects=0.45, parallel_all_effects=0.30,
        n_procs=2, repeats=3, instruction_steps=4, instruction_start=0.1096,
        instructions={"none": 1.3e9, "compressibleInterFoam": 1.0e9,
                      "compressibleInterFoamDefault": 0.9e9, "laser": 1.43e9, "all": 1.5e9})
    ratios = json.loads(json.dumps(costs.summary()))["instruction_ratios"]
    assert ratios == {"laser": pytest.approx(1.1), "no_effects": pytest.approx(1.3),
                      "all_effects": pytest.approx(1.5),
                      "all_effects_default_reference": pytest.approx(1.5 / 0.9)}
