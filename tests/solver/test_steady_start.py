"""The estimate of the steady weld that ``ldna steady-start`` writes (unit
tests of its geometry and its heat balance; the run from it is in
docs/validation/steady-start.md)."""
from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from ldna.case import Case


def test_the_template_starts_from_the_estimate(ldna_case: Case) -> None:
    """The template, meshed and set, then ``ldna steady-start``: the deposit on
    the surface holds the mass balance's section behind the second wire and
    half of it between the wires (sampled in the cells within 1 %), the
    metal over it moves with the substrate, the solver runs on from it, and
    ``ldna post`` says the section holds the estimate."""
    case = ldna_case
    case.mesh()
    case.run("setFields")
    result = subprocess.run([sys.executable, "-m", "ldna.cli", "steady-start", str(case),
                             "--json"], capture_output=True, text=True, check=True)
    figures = json.loads(result.stdout.strip().splitlines()[-1])

    case.run("postProcess -func writeCellCentres -time 0", log_name="centres")
    case.run("postProcess -func writeCellVolumes -time 0", log_name="volumes")
    x, y, z = case.field("C", "0").T
    volume = case.field("V", "0")
    alpha = case.field("alpha.metal", "0")
    parameters = "system/caseParameters"
    mm = 1e-3
    mid = mm * case.scalar(parameters, "processPosition")
    spacing = mm * case.scalar(parameters, "wireSpacing")
    length = mm * case.scalar(parameters, "length")
    # The mass balance from the process numbers: two wires' feed over the
    # metal's density times the welding speed
    wire_density = case.scalar("constant/fvOptions", "wireDroplets/wireDensity")
    metal_density = case.scalar("constant/thermophysicalProperties", "metal/referenceDensity")
    area = (2 * wire_density * case.scalar(parameters, "wireFeedSpeed") * math.pi
            * case.scalar(parameters, "wireRadius") ** 2
            / (metal_density * case.scalar(parameters, "weldingSpeed")))
    expected = area * (length - (mid + spacing / 2)) + 0.5 * area * spacing
    deposit = float((alpha * volume)[z > 0].sum())
    print(f"deposit {1e9 * deposit:.1f} mm3, expected {1e9 * expected:.1f} mm3; {figures}")
    assert deposit == pytest.approx(expected, rel=0.01)
    assert figures["bead_area_mm2"] == pytest.approx(1e6 * area, rel=1e-9)
    velocity = case.field("U", "0")
    metal = alpha >= 0.5
    assert np.allclose(velocity[metal, 0], case.scalar(parameters, "weldingSpeed"))

    case.set("system/controlDict", "endTime", "0.002")
    case.run("ldnaFoam")
    low, high = case.alpha_bounds()
    assert -1e-6 < low and high < 1 + 1e-6
    estimate = post_process_note(case)
    assert "estimate of the start" in estimate


def post_process_note(case: Case) -> str:
    """What ``ldna post`` tells about the section of the short run."""
    result = subprocess.run([sys.executable, "-m", "ldna.cli", "post", str(case)],
                            capture_output=True, text=True, check=True)
    return " ".join(result.stdout.split())
