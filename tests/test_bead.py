"""Droplets that arrive as bodies of metal (dropletSource mode insertion).

- insertion: a droplet enters as a sphere of metal fraction 1 whose volume
  on the mesh is exactly 4/3 pi R^3 (1 %), the metal fraction stays bounded
  and the solver's metal mass equals the mass the source reports;
- a droplet radius of fewer than 1.5 cells stops insertion with an error
  naming the cell size and the level that would do.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from conftest import prepare_test_case
from ldna.balance import WIRE_LOG_COLUMNS, wire_log
from ldna.foamcase import (alpha_bounds, read_balances, read_internal_field, run,
                           time_directories)
from ldna.foamdict import set_entry

VOLUME_TOLERANCE = 0.01
ALPHA_BOUND = 1e-6
#: A droplet body: cells this full between the wire tips and the surface
BODY_FRACTION = 0.99
#: The first pulse of the default switch (eq. 18) at 100 Hz starts at
#: (asin 0.8 - asin 0.9 + 2 pi)/(2 pi 100) = 9.69 ms; the box stops in the
#: step after it, with the droplets just inserted
END_OF_FIRST_DROPLET = "0.0098"


def droplet_radius(log_text: str) -> float:
    """The regular droplet radius [m] the source reports for its first wire."""
    return float(re.search(r"droplet radius (\S+) m", log_text).group(1))


@pytest.fixture
def insertion_box(tmp_path: Path) -> Path:
    """The closed argon box of the droplet tests, 1/3 mm cells, droplets inserted."""
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    run(case, "foamDictionary -entry wireDroplets/mode -add insertion constant/fvOptions",
        log_name="foamDictionary.mode")
    block_mesh = case / "system" / "blockMeshDict"
    block_mesh.write_text(block_mesh.read_text().replace("(20 16 32)", "(30 24 48)"))
    run(case, "blockMesh")
    return case


def test_inserted_droplet_is_a_sphere_of_exact_volume(insertion_box: Path) -> None:
    case = insertion_box
    for entry in ("endTime", "writeInterval"):
        set_entry(case / "system" / "controlDict", entry, END_OF_FIRST_DROPLET)
    set_entry(case / "system" / "controlDict", "writeFormat", "ascii")
    result = run(case, "ldnaFoam")
    log = result.output

    radius = droplet_radius(log)
    last = time_directories(case)[-1]
    alpha = read_internal_field(last / "alpha.metal")
    run(case, "postProcess -func writeCellVolumes -latestTime", log_name="postProcess")
    volumes = read_internal_field(last / "V")
    n_droplets = sum(len(np.unique(values[:, 0])) - 1 for values in wire_log(result.log).values())
    assert n_droplets == 2, "one droplet per wire by the end of the first pulse"
    expected = n_droplets * 4 / 3 * math.pi * radius**3
    assert abs(np.sum(alpha * volumes) / expected - 1) < VOLUME_TOLERANCE
    assert alpha.max() >= BODY_FRACTION, "the droplet is a body of metal, not a smear"
    low, high = alpha_bounds(result.log)
    assert low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND

    # The solver's metal mass is the mass the source reports it inserted
    balances = read_balances(result.log)
    added = sum(values[-1, WIRE_LOG_COLUMNS.index("added mass")]
                for values in wire_log(result.log).values())
    assert balances["metal_mass"][-1] - balances["metal_mass"][0] == pytest.approx(added, rel=1e-6)


def test_insertion_stops_on_unresolved_droplets(tmp_path: Path) -> None:
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    run(case, "foamDictionary -entry wireDroplets/mode -add insertion constant/fvOptions",
        log_name="foamDictionary.mode")
    run(case, "blockMesh")
    result = run(case, "ldnaFoam", check=False)
    assert result.returncode != 0
    text = result.output
    assert "FOAM FATAL IO ERROR" in text and "Segmentation" not in text
    assert "at least 1.5 cells per radius" in text and "level 0 or finer" in text
    assert "wireDroplets" in text
