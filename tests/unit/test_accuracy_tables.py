"""``ldna accuracy``'s tables without a run: the observed order fitted to
errors that follow a known power of the cell size, the bond's errors read
against the bead, the cheapest level within each bound (the runs are in
tests/solver/test_accuracy.py)."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from ldna.dev import accuracy

#: A bead study's level whose section holds no liquid and whose refined
#: zone encloses the bead's surface there (its shape judged)
FROZEN = {"section_liquid": 0.0, "coarse_surface": 0.0}


@pytest.mark.parametrize("order", [1.0, 2.0])
def test_order_fit_recovers_a_known_order(order: float) -> None:
    """Outputs q(h) = q0 (1 + h^p) against the finest run give slope p."""
    scene = accuracy.SCENES["ldna"]
    members = []
    for level, h in enumerate((0.8, 0.4, 0.2, 0.1, 0.001)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {"pool_width": 2e-3 * (1 + h**order)}
        members.append(member)
    study = accuracy.evaluate(scene, members, exact=None)
    # The finest run is not exact: its own error biases the fit a little
    assert study.orders["pool_width"] == pytest.approx(order, rel=0.05)
    assert math.isnan(study.orders["penetration"])


def test_bond_errors_read_against_the_bead() -> None:
    """Without fusion the reference's penetration, bonded width and dilution
    are 0: a coarse level's 0.2 mm penetration is then 5 % of the 4 mm bead
    height, its 1 mm bonded width 10 % of the 10 mm bead width, its dilution
    of 0.02 an error of 0.02 (against 1); the bead's own metrics against
    themselves."""
    scene = accuracy.BeadScene()
    reference = {**FROZEN, "bead_width": 10e-3, "bead_height": 4e-3, "penetration": 0.0,
                 "bonded_width": 0.0, "dilution": 0.0}
    coarse = accuracy.Member(level=0, max_co=None, cell_size_mm=0.45)
    coarse.outputs = {**FROZEN, "bead_width": 11e-3, "bead_height": 4e-3, "penetration": 0.2e-3,
                      "bonded_width": 1e-3, "dilution": 0.02}
    fine = accuracy.Member(level=1, max_co=None, cell_size_mm=0.225)
    fine.outputs = reference
    accuracy.evaluate(scene, [coarse, fine], None)
    assert coarse.errors["penetration"] == pytest.approx(0.2 / 4)
    assert coarse.errors["bonded_width"] == pytest.approx(1 / 10)
    assert coarse.errors["dilution"] == pytest.approx(0.02)
    assert coarse.errors["bead_width"] == pytest.approx(0.1)


def assert_not_judged(study: accuracy.Study, members: list[accuracy.Member],
                      names: set[str]) -> str:
    """The fusion outputs ``names`` of a study without fusion (a coarse
    level's bead 11 mm wide, the reference's 10 mm): no error, no cheapest level, the
    table says lack of fusion, the bead's width is judged (10 %); returns
    the table's text."""
    # The section's liquid share and coarse top are diagnostics, never judged
    assert study.fusion_unresolved and set(study.not_judged) == names | {
        "section_liquid", "coarse_surface"}
    assert study.not_judged["section_liquid"] == "diagnostic"
    assert all(math.isnan(members[0].errors[name]) for name in names)
    assert members[0].errors["bead_width"] == pytest.approx(0.1)
    assert all(accuracy.cheapest_levels(study)[name] == {"5%": None, "10%": None}
               for name in names)
    text = accuracy.markdown(study)
    assert "lack of fusion at every level" in text
    return text


def test_an_output_zero_at_every_level_is_not_judged(tmp_path: Path) -> None:
    """No level fuses the substrate: the bond's outputs are 0 everywhere, so
    they have no error (not 0 %), no order and no cheapest level, and the
    table says so; a coarse level that does fuse is judged as before."""
    scene = accuracy.BeadScene()
    bond = {"penetration": 0.0, "bonded_width": 0.0, "dilution": 0.0}
    members = []
    for level, h, width in ((0.0, 0.45, 11e-3), (1.0, 0.225, 10e-3)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {**FROZEN, "bead_width": width, "bead_height": 4e-3, **bond}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    text = assert_not_judged(study, members, set(bond))
    assert "penetration" in text
    path = tmp_path / "accuracy.json"
    accuracy.write_json(study, path)
    data = json.loads(path.read_text())
    assert data["not_judged"] == {**dict.fromkeys(bond, "lack_of_fusion"),
                                  "section_liquid": "diagnostic",
                                  "coarse_surface": "diagnostic"}
    assert set(data["not_judged_reasons"]) == {"lack_of_fusion", "diagnostic"}
    assert data["levels"][0]["errors"]["penetration"] is None

    members[0].outputs["penetration"] = 0.2e-3
    study = accuracy.evaluate(scene, members, None)
    assert "penetration" not in study.not_judged
    assert members[0].errors["penetration"] == pytest.approx(0.2 / 4)


def test_fusion_below_the_metrics_depth_accuracy_is_not_judged(tmp_path: Path) -> None:
    """The fusion metrics recover a fusion zone's depth within 0.05 mm
    (tests/solver/test_fusion_line.py).  Levels whose penetrations are a
    few hundredths of a millimetre (0.016 and 0.007 mm, as the bead study's
    levels 0 and 0.5 read) have no bond to converge: the fusion outputs get
    no error and no cheapest level, the table says lack of fusion, the
    bead's own metrics are judged as before.  One level at 0.08 mm fuses:
    every fusion output is judged again."""
    scene = accuracy.BeadScene()
    members = []
    for level, h, width, depth in ((0.0, 0.45, 11e-3, 0.016e-3), (0.5, 0.318, 10e-3, 0.007e-3)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {**FROZEN, "bead_width": width, "bead_height": 4e-3, "penetration": depth,
                          "bonded_width": 0.02e-3, "dilution": 1e-4,
                          "chemical_dilution": 6e-4}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    fusion = {"penetration", "bonded_width", "dilution", "chemical_dilution"}
    text = assert_not_judged(study, members, fusion)
    assert "0.05 mm" in text
    assert "0 at every level" not in text
    path = tmp_path / "accuracy.json"
    accuracy.write_json(study, path)
    data = json.loads(path.read_text())
    assert data["fusion_unresolved"] is True
    assert data["not_judged"] == {**dict.fromkeys(fusion, "lack_of_fusion"),
                                  "section_liquid": "diagnostic",
                                  "coarse_surface": "diagnostic"}

    members[0].outputs["penetration"] = 0.08e-3
    study = accuracy.evaluate(scene, members, None)
    assert not study.fusion_unresolved and study.not_judged == {
        "section_liquid": "diagnostic", "coarse_surface": "diagnostic"}
    assert members[0].errors["penetration"] == pytest.approx((0.08 - 0.007) / 4)


def test_a_bead_output_zero_at_every_level_beside_lack_of_fusion() -> None:
    """No gas film under the first layer at any level (0 everywhere) and no
    level fusing: the table names the gas film as 0 at every level and only
    the fusion outputs as lack of fusion; neither gets an error or a
    cheapest level, the bead's width still does."""
    scene = accuracy.BeadScene()
    members = []
    for level, h, width in ((0.0, 0.45, 11e-3), (1.0, 0.225, 10e-3)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {**FROZEN, "bead_width": width, "bead_height": 4e-3, "first_layer_gas": 0.0,
                          "penetration": 0.01e-3, "bonded_width": 0.0, "dilution": 0.0,
                          "chemical_dilution": 0.0}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    fusion = {"penetration", "bonded_width", "dilution", "chemical_dilution"}
    text = assert_not_judged(study, members, fusion | {"first_layer_gas"})
    assert math.isnan(members[0].errors["first_layer_gas"])
    assert study.not_judged["first_layer_gas"] == "zero"
    zero_line = next(line for line in text.splitlines() if line.startswith("0 at every level"))
    fusion_line = next(line for line in text.splitlines() if "lack of fusion" in line)
    gas = scene.outputs_meta["first_layer_gas"][0]
    assert gas in zero_line and gas not in fusion_line
    assert all(scene.outputs_meta[n][0] in fusion_line and scene.outputs_meta[n][0]
               not in zero_line for n in fusion)


#: The section's shape outputs a bead study judges only on a frozen section
#: read at its level's resolution
SHAPE = {"bead_width", "bead_height", "bead_area", "wetting_angle"}


def _two_bead_levels(level0: dict[str, float], level1: dict[str, float]) -> list:
    """Levels 0 and 1 of a bead study, 12.9 and 7.6 mm wide, their pool
    lengths 10 (1 + h) mm, frozen and enclosed but for ``level0`` and
    ``level1``'s diagnostics."""
    members = []
    for level, h, width, diagnostics in ((0.0, 0.45, 12.9e-3, level0),
                                         (1.0, 0.225, 7.6e-3, level1)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {"bead_width": width, "bead_height": 4e-3, "bead_area": 30e-6,
                          "wetting_angle": 50.0, "pool_length": 10e-3 * (1 + h),
                          **FROZEN, **diagnostics}
        members.append(member)
    return members


def _shape_not_judged(members: list, reason: str) -> "accuracy.Study":
    """The study of ``members``: its shape outputs not judged for ``reason``,
    its pool length judged; the level 0 errors of the shape NaN."""
    study = accuracy.evaluate(accuracy.BeadScene(), members, None)
    assert all(study.not_judged.get(name) == reason for name in SHAPE)
    assert "pool_length" not in study.not_judged
    assert all(math.isnan(members[0].errors[name]) for name in SHAPE)
    assert members[0].errors["pool_length"] == pytest.approx((1.45 - 1.225) / 1.225)
    return study


def _shape_judged(members: list) -> "accuracy.Study":
    study = accuracy.evaluate(accuracy.BeadScene(), members, None)
    assert not SHAPE & set(study.not_judged)
    assert members[0].errors["bead_width"] == pytest.approx((12.9 - 7.6) / 7.6)
    return study


def test_a_section_cut_before_the_bead_froze_is_not_judged(tmp_path: Path) -> None:
    """Level 0's section holds 1.3 % liquid, level 1's 23 % (the bead study
    at 11 mm behind the wires): level 1's section is not the bead's final
    shape, so the width, height, area, wetting angle and gas film are not
    compared (no error, no cheapest level), the pool length still is, and
    the table names the level and the shares.  With level 1 at 4 % every
    shape output is judged again; with its share not measured, not."""
    members = _two_bead_levels({"section_liquid": 0.013}, {"section_liquid": 0.23})
    study = _shape_not_judged(members, "not_frozen")
    assert study.not_frozen == ("level1",)
    assert all(accuracy.cheapest_levels(study)[name] == {"5%": None, "10%": None}
               for name in SHAPE)
    text = accuracy.markdown(study)
    assert "level0 1.3 %; level1 23 %" in text and "froze, so its shape" in text
    assert "0 at every level" not in text
    accuracy.write_json(study, tmp_path / "accuracy.json")
    assert json.loads((tmp_path / "accuracy.json").read_text())["not_frozen"] == ["level1"]

    members[1].outputs["section_liquid"] = 0.04
    assert _shape_judged(members).not_frozen == ()
    # A share not measured (NaN: fields without liquidFraction) does not
    # show the section frozen
    members[1].outputs["section_liquid"] = math.nan
    assert _shape_not_judged(members, "not_frozen").not_frozen == ("level1",)


def test_a_bead_out_of_its_refined_zone_is_not_judged(tmp_path: Path) -> None:
    """A level whose section's bead is topped by cells coarser than its
    finest over 13 % of its width (its band does not enclose its bead: the
    raised-zone study's level 0 read up to 9 %) is not read at its own
    resolution: the section's shape outputs are not compared, the pool
    length still is, and the table names the level and the shares.  At 4 %
    every shape output is judged again; with the share not measured, not."""
    members = _two_bead_levels({"coarse_surface": 0.13}, {})
    study = _shape_not_judged(members, "not_enclosed")
    assert study.not_enclosed == ("level0",) and study.not_frozen == ()
    assert study.not_judged["coarse_surface"] == "diagnostic"
    text = accuracy.markdown(study)
    assert "level0 13 %; level1 0 %" in text and "not read at its own resolution" in text
    accuracy.write_json(study, tmp_path / "accuracy.json")
    written = json.loads((tmp_path / "accuracy.json").read_text())
    assert written["not_enclosed"] == ["level0"] and written["coarse_surface_limit"] == 0.05

    members[0].outputs["coarse_surface"] = 0.04
    assert _shape_judged(members).not_enclosed == ()
    members[0].outputs["coarse_surface"] = math.nan
    assert _shape_not_judged(members, "not_enclosed").not_enclosed == ("level0",)


def test_the_cheapest_level_within_each_bound(tmp_path: Path) -> None:
    """Levels 0, 0.5 and 1 of a bead study, level 1 the reference: errors of
    12 % and 4 % on the width, 3 % and 1 % on the height.  The cheapest level
    within 5 % is 0.5 for the width and 0 for the height; within 10 %, 0.5 and
    0; the reference itself is never 'within'."""
    scene = accuracy.BeadScene()
    reference = {**FROZEN, "bead_width": 15e-3, "bead_height": 3e-3}
    members = []
    for level, cost, width_error, height_error in ((0.0, 1.0, 0.12, 0.03),
                                                   (0.5, 3.0, 0.04, 0.01), (1.0, 9.0, 0, 0)):
        member = accuracy.Member(level=level, max_co=None,
                                 cell_size_mm=0.45 / 2**level, wall_time=cost, n_procs=1,
                                 start_time=3.0, end_time=4.0, steady=True, first_steady=4.0)
        member.outputs = {**FROZEN, "bead_width": reference["bead_width"] * (1 + width_error),
                          "bead_height": reference["bead_height"] * (1 - height_error)}
        members.append(member)
    members[-1].outputs = reference
    study = accuracy.evaluate(scene, members, None)
    cheapest = accuracy.cheapest_levels(study)
    assert cheapest["bead_width"] == {"5%": 0.5, "10%": 0.5}
    assert cheapest["bead_height"] == {"5%": 0.0, "10%": 0.0}
    assert cheapest["penetration"] == {"5%": None, "10%": None}
    accuracy.write_json(study, tmp_path / "accuracy.json")
    written = json.loads((tmp_path / "accuracy.json").read_text())
    first = written["levels"][0]
    for key in ("level", "cell_mm", "cells", "core_hours_per_simulated_s",
                "core_hours_to_steady", "steady", "bead_width_mm", "bead_height_mm"):
        assert key in first
    # One core for 1 s of wall time per simulated second, all of it to steady
    assert first["core_hours_per_simulated_s"] == pytest.approx(1.0 / 3600)
    assert first["core_hours_to_steady"] == pytest.approx(1.0 / 3600)
    assert first["bead_width_mm"] == pytest.approx(15 * 1.12)
    assert "finer than tested" in accuracy.markdown(study)
    assert written["min_window_s"] == accuracy.STEADY_MIN_WINDOW


def test_the_cheapest_level_counts_the_window_means_scatter() -> None:
    """Level 0.5 is 4 % off the reference's width; with its and the
    reference's ripples of 0.3 mm on a 15 mm width (2 % each: 2.83 %
    together) its error may be 6.8 %, so it is within 10 % but not 5 %,
    where only the reference is; without ripples it is within 5 %."""
    scene = accuracy.BeadScene()
    width = 15e-3
    members = []
    for level, cost, error in ((0.0, 1.0, 0.12), (0.5, 3.0, 0.04), (1.0, 9.0, 0.0)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=0.45 / 2**level,
                                 wall_time=cost, n_procs=1, start_time=3.0, end_time=4.0,
                                 steady=True, first_steady=4.0)
        member.outputs = {**FROZEN, "bead_width": width * (1 + error)}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    assert accuracy.cheapest_levels(study)["bead_width"] == {"5%": 0.5, "10%": 0.5}
    for member in members:
        member.ripples = {"bead_width": 0.3e-3}
    study = accuracy.evaluate(scene, members, None)
    assert accuracy.error_spread(study, members[1], "bead_width") == pytest.approx(
        math.hypot(0.3, 0.3) / 15, rel=1e-12)
    assert accuracy.cheapest_levels(study)["bead_width"] == {"5%": None, "10%": 0.5}
    assert "ripples together within the bound" in accuracy.markdown(study)


def test_a_bead_study_states_its_steadiness_window(tmp_path: Path) -> None:
    """A study judged over windows of at least 1 s (``--min-window 1``) says
    so in its table and its JSON."""
    scene = accuracy.BeadScene()
    scene.min_window = 1.0
    members = []
    for level, h in ((0.0, 0.45), (1.0, 0.225)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h, wall_time=1.0,
                                 start_time=12.0, end_time=18.0, steady=True, first_steady=17.0)
        member.outputs = {"bead_width": 1e-3 * (7.0 + 4.0 * h)}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    assert "windows of at least 1 s" in accuracy.markdown(study)
    accuracy.write_json(study, tmp_path / "accuracy.json")
    assert json.loads((tmp_path / "accuracy.json").read_text())["min_window_s"] == 1.0


def test_a_sequenced_study_says_where_each_level_started(tmp_path: Path) -> None:
    """Levels that started from different welds (``--sequence``) say which,
    in the table and in the JSON."""
    starts = {0.0: ("steadyWeld", 12.0), 1.0: ("level0", 18.0)}
    members = []
    for level, h in ((0.0, 0.45), (1.0, 0.225)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h, wall_time=1.0,
                                 start_time=starts[level][1], end_time=starts[level][1] + 6.0,
                                 steady=True, first_steady=starts[level][1] + 5.0,
                                 started_from=starts[level])
        member.outputs = {"bead_width": 1e-3 * (7.0 + 4.0 * h)}
        members.append(member)
    study = accuracy.evaluate(accuracy.BeadScene(), members, None)
    assert ("level0 from steadyWeld at 12 s; level1 from level0 at 18 s (0.00 core-h "
            "to quasi-steady with the levels before)" in accuracy.markdown(study))
    accuracy.write_json(study, tmp_path / "accuracy.json")
    written = json.loads((tmp_path / "accuracy.json").read_text())["levels"]
    assert [level["started_from"] for level in written] == [
        {"run": "steadyWeld", "time_s": 12.0}, {"run": "level0", "time_s": 18.0}]
    # Each level costs 1 s of one core per 6 s simulated.  Level 1 needs
    # level 0 run to 18 s (6 s from its start) and its own 5 s to
    # quasi-steady; level 0 alone its 5 s
    rate = (1.0 / 6.0) / 3600
    assert written[0]["route_core_hours_to_steady"] == pytest.approx(5.0 * rate)
    assert written[1]["route_core_hours_to_steady"] == pytest.approx((6.0 + 5.0) * rate)


@pytest.mark.parametrize("cells", [(0.225, 0.318, 0.45), (0.2, 0.3, 0.36)])
@pytest.mark.parametrize("order", [1.0, 1.5, 2.0])
def test_three_levels_recover_order_and_error(cells: tuple[float, float, float],
                                              order: float) -> None:
    """Outputs q(h) = q0 + C h^p on three levels, with equal and unequal
    refinement ratios: the estimate finds p and q0, and the finest level's
    index is the safety factor times its true relative error."""
    q0, c = 10.0, 2.0
    values = tuple(q0 + c * h**order for h in cells)
    estimate = accuracy.three_level_estimate(cells, values, abs(values[0]))
    assert estimate.status == "converging"
    assert estimate.order == pytest.approx(order, rel=1e-6)
    assert estimate.extrapolated == pytest.approx(q0, rel=1e-9)
    true_error = (values[0] - q0) / values[0]
    assert estimate.gci == pytest.approx(accuracy.GCI_SAFETY_FACTOR * true_error, rel=1e-6)


def test_three_levels_count_a_high_order_as_second() -> None:
    """An observed order of 4 is counted as 2 in the index: the band is then
    wider than 1.25 times the true error, by (r^4 - 1)/(r^2 - 1) = r^2 + 1."""
    cells, q0 = (0.225, 0.318, 0.45), 4.0
    values = tuple(q0 + 3.0 * h**4 for h in cells)
    estimate = accuracy.three_level_estimate(cells, values, abs(values[0]))
    assert estimate.order == pytest.approx(4.0, rel=1e-6)
    ratio = cells[1] / cells[0]
    true_error = (values[0] - q0) / values[0]
    assert estimate.gci == pytest.approx(
        accuracy.GCI_SAFETY_FACTOR * true_error * (ratio**2 + 1), rel=1e-6)


@pytest.mark.parametrize("values,status", [
    ((7.5, 10.1, 13.4), "converging"),
    ((7.5, 12.0, 9.0), "oscillating"),
    ((5.0, 9.0, 10.0), "diverging"),
    ((3.0, 3.0, 3.0), "unchanged"),
])
def test_three_levels_say_when_they_do_not_converge(values: tuple[float, float, float],
                                                    status: str) -> None:
    """Differences that change sign oscillate; differences that grow towards
    the finest level diverge; neither has an order or an index."""
    estimate = accuracy.three_level_estimate((0.225, 0.318, 0.45), values, abs(values[0]))
    assert estimate.status == status
    if status in ("oscillating", "diverging"):
        assert math.isnan(estimate.order) and math.isnan(estimate.gci)


def test_a_study_of_three_levels_reports_them(tmp_path: Path) -> None:
    """A bead study of three levels carries the estimate of each acting output
    into its table and JSON (in the table's units); the bond, 0 everywhere, is
    left out."""
    scene = accuracy.BeadScene()
    members = []
    for level, h in ((0.0, 0.45), (0.5, 0.318), (1.0, 0.225)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h)
        member.outputs = {**FROZEN, "bead_width": 1e-3 * (7.0 + 4.0 * h), "bead_height": 4e-3,
                          "penetration": 0.0, "bonded_width": 0.0, "dilution": 0.0}
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    assert study.three_level is not None
    assert set(study.three_level) == {"bead_width", "bead_height"}
    assert study.three_level["bead_width"].order == pytest.approx(1.0, rel=1e-6)
    assert study.three_level["bead_height"].status == "unchanged"
    accuracy.write_json(study, tmp_path / "accuracy.json")
    written = json.loads((tmp_path / "accuracy.json").read_text())["three_level"]
    assert written["bead_width"]["extrapolated"] == pytest.approx(7.0, rel=1e-9)
    assert "three finest levels" in accuracy.markdown(study)


def test_field_metrics_are_window_means_of_the_written_fields() -> None:
    """The metrics only the fields hold are averaged over the fields written
    in each window (end - window, end]: a ripple sampled every 0.25 s, read
    over four windows of 1.25 s, gives each window the plain mean of its
    five fields."""
    from ldna import section_fields

    times = 12.0 + 0.25 * np.arange(1, 29)
    # A 0.42 s ripple of 12 deg about a slowly rising mean, as the bead
    # study's level 0 showed
    angle = 45.0 + 0.5 * (times - 12.0) + 12.0 * np.sin(2 * math.pi * times / 0.42)
    rows = {float(t): {"wetting_angle": float(a), "body_width": 0.012, "first_layer_gas": 1e-4}
            for t, a in zip(times, angle)}
    ends = 19.0 - 1.25 * np.arange(4)[::-1]
    means = section_fields.window_means(rows, "wetting_angle", ends, 1.25)
    for end, mean in zip(ends, means):
        inside = [a for t, a in zip(times, angle) if end - 1.25 < t - 1e-12 and t <= end + 1e-12]
        assert len(inside) == 5
        assert mean == pytest.approx(sum(inside) / 5, rel=1e-12)
    assert section_fields.times_in_window(rows, 19.0, 1.25) == 5
    # No field in a window: no mean, not a zero
    assert math.isnan(section_fields.window_means(rows, "body_width", np.array([30.0]), 1.0)[0])


def test_a_bead_output_is_its_mean_over_the_judged_windows(tmp_path: Path) -> None:
    """A level's output is its mean over the four judged windows, not the
    last window's: a width rippling by 20 % with a period of the four
    windows (0.5 s each, the bead area steady, so the window is the
    shortest) averages to its mean c over them, while its last window
    alone reads c (1 - 0.2 * 2 / pi), 13 % low.  Its ripple is the
    standard deviation of the four quarter-period means, 0.2 c (2 / pi)
    (1, 1, -1, -1): 0.2 c (2 / pi) sqrt(4 / 3)."""
    from ldna import post
    from ldna.case import Case

    window, width, amplitude = 0.5, 10e-3, 0.2
    metrics = tmp_path / "postProcessing" / "meltPoolMetrics" / "0"
    metrics.mkdir(parents=True)
    columns = post.BeadMetrics.FUNCTION_OBJECT_COLUMNS
    rows = []
    for t in np.linspace(0.0, 4.0, 4001):
        values = dict.fromkeys(columns, 1e-3)
        values.update(bead_area=35e-6, bead_width=width * (
            1 + amplitude * math.sin(2 * math.pi * t / (4 * window))))
        rows.append(f"{t:.6f}" + "".join(f"\t{values[c]:.9e}" for c in columns) + "\n")
    metrics.joinpath("meltPoolMetrics.dat").write_text(
        "# Time\t" + "\t".join(columns) + "\n" + "".join(rows))
    scene = accuracy.BeadScene()
    scene.min_window = window
    outputs = scene.outputs(Case(tmp_path))
    assert outputs["bead_width"] == pytest.approx(width, rel=1e-6)
    assert outputs.ripples["bead_width"] == pytest.approx(
        amplitude * width * 2 / math.pi * math.sqrt(4 / 3), rel=1e-3)


def test_a_bead_study_gives_each_window_mean_its_ripple(tmp_path: Path) -> None:
    """Each level's outputs carry the standard deviation of their window
    means: in the table as value ± ripple, in accuracy.json per level in the
    output's unit, and in the CSV."""
    scene = accuracy.BeadScene()
    members = []
    for level, h, ripple in ((0.0, 0.45, 0.4e-3), (1.0, 0.225, 0.2e-3)):
        member = accuracy.Member(level=level, max_co=None, cell_size_mm=h, wall_time=1.0,
                                 start_time=12.0, end_time=18.0, steady=True, first_steady=17.0)
        member.outputs = {**FROZEN, "bead_width": 1e-3 * (7.0 + 4.0 * h)}
        member.ripples = {"bead_width": ripple}
        member.fields_in_window = 5
        members.append(member)
    study = accuracy.evaluate(scene, members, None)
    table = accuracy.markdown(study)
    assert "8.8 ± 0.4" in table and "7.9 ± 0.2" in table
    assert "level0 5, level1 5 fields" in table
    # Level 0 is 11 % off; the reference's ripple against its width: 0.2 / 7.9 mm
    assert "bead width finer than tested / finer than tested (its ripple 2.5 %)" in table
    accuracy.write_json(study, tmp_path / "accuracy.json")
    levels = json.loads((tmp_path / "accuracy.json").read_text())["levels"]
    assert [level["ripples"]["bead_width_mm"] for level in levels] == pytest.approx([0.4, 0.2])
    accuracy.write_csv(study, tmp_path / "accuracy.csv")
    assert "bead_width_ripple_mm" in (tmp_path / "accuracy.csv").read_text().splitlines()[0]
    accuracy.plot(study, tmp_path / "accuracy.png")
    assert (tmp_path / "accuracy.png").stat().st_size > 0


def test_a_resumed_member_must_have_the_settings_it_ran_with(tmp_path: Path) -> None:
    """A member that ran (its ranks' folders are there) with the template's
    28 mm domain is not continued under --set length=33.4194: the error
    names the member, the entry and both values; with the value it has it
    is (the run itself is the solver tests')."""
    from ldna.case import Case
    from ldna.study import Parameter
    from solver_cases import TEMPLATE

    directory = tmp_path / "members" / "level0"
    Case.copy_of(TEMPLATE, directory)
    (directory / "processor0").mkdir()
    member = accuracy.Member(level=0.0, max_co=None, cell_size_mm=math.nan)
    with pytest.raises(ValueError, match=r"level0 ran with length 28, not 33\.4194"):
        accuracy.run_member(TEMPLATE, directory, accuracy.BeadScene(), member, None, 2,
                            resume=True, settings=[Parameter.parse("length=33.4194")])



def test_a_field_table_written_before_a_column_reads_without_it(tmp_path: Path) -> None:
    """sectionFields.csv of a study begun before the liquid share was read:
    its rows read without that column, their window means are NaN (not 0),
    and written again the table holds the column as NaN for those times."""
    from ldna import section_fields

    (tmp_path / section_fields.FILE).write_text(
        "time_s,wetting_angle_deg,body_width_mm,first_layer_gas_mm\n"
        "1,40,12,0.1\n1.25,50,13,0.2\n")
    rows = section_fields.read(tmp_path)
    assert rows[1.0] == pytest.approx({"wetting_angle": 40.0, "body_width": 12e-3,
                                       "first_layer_gas": 0.1e-3})
    assert "section_liquid" not in rows[1.25]
    means = section_fields.window_means(rows, "section_liquid", np.array([1.25]), 0.5)
    assert math.isnan(means[0])
    assert section_fields.window_means(rows, "wetting_angle", np.array([1.25]), 0.5)[0] == 45.0
    section_fields._write(tmp_path, rows)
    again = section_fields.read(tmp_path)
    assert math.isnan(again[1.0]["section_liquid"]) and again[1.25]["body_width"] == 13e-3
