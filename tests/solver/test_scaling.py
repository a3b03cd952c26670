"""``ldna scaling``: the decompositions it projects from.

The busiest rank's cells, processor faces and neighbour ranks of the
template's split along x, on a block of 12 x 1 x 12 cells, against what the
block's geometry gives: n slabs of 12/n columns of 12 cells, an inner slab
bounded by two planes of 12 faces."""
from __future__ import annotations

import pytest

from ldna.dev import scaling
from ldna.case import Case

#: Cells of the energy box along x, y and z (tests/cases/energyBox)
COLUMNS, ROWS = 12, 12


@pytest.mark.parametrize("ranks", [1, 2, 3, 4])
def test_decomposition_counts_follow_the_block(energy_box_case: Case, ranks: int) -> None:
    split = scaling.decomposition(energy_box_case, (ranks, 1, 1))
    assert split.cells == COLUMNS * ROWS
    assert split.max_cells == COLUMNS // ranks * ROWS
    planes = min(ranks - 1, 2)
    assert split.max_processor_faces == planes * ROWS
    assert split.max_neighbours == planes
    # The dry run leaves the case as it was
    assert not list(energy_box_case.path.glob("*/cellDist"))
    assert not (energy_box_case / "system" / "decomposeParDict.scaling").exists()


def test_projection_without_traffic_is_the_balance(energy_box_case: Case) -> None:
    """With no traffic and a perfect node, a balanced split's efficiency is 1."""
    split = scaling.decomposition(energy_box_case, (4, 1, 1))
    quiet = scaling.StepTraffic(messages=0, bytes_per_face=0, collectives=0)
    projection = scaling.project(split, serial_step=1.0, node_efficiency=1.0, traffic=quiet)
    assert projection.efficiency == pytest.approx(1.0, rel=1e-12)
