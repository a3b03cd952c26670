"""Steadiness of the bead (``ldna steady``) on a real run whose bead is
still growing (the criterion on synthetic metrics is tests/unit/test_steady_judge.py)."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from ldna.case import Case
from ldna.meshing import LEVEL0_CELL
from ldna.steady import BALANCE_TOLERANCE, DomainBalance

#: The metal gained ahead of the bead section against the wires' metal in
#: the template's first 40 ms: the substrate carries as much metal in at the
#: inlet as out through the section, but the domain itself keeps the wires'
#: metal to 1.1e-3 only (what its boundaries let out; measured) and the
#: first droplets' splashes may cross the section
UPSTREAM_MASS_TOLERANCE = 0.01


def test_a_run_still_growing_is_not_steady(ldna_case: Case) -> None:
    """The template's first 40 ms, judged at the section under the droplets with
    four windows of 8 ms: the bead there grows with every droplet, so the tool
    must say 'not steady', and say which metrics change."""
    case = ldna_case
    case.set("system/controlDict", "endTime", "0.04")
    under_droplets = 1e-3 * case.scalar("system/caseParameters", "processPosition")
    for entry, value in (("writeInterval", "1"), ("beadSection", f"{under_droplets:g}")):
        case.set("system/controlDict", f"functions/meltPoolMetrics/{entry}", value)
    case.mesh()
    case.run("setFields")
    case.run("ldnaFoam")

    from ldna.steady import case_steadiness

    verdict = case_steadiness(case.path, min_window=0.008)
    print(verdict.reason)
    area = verdict.metrics["bead_area"]
    assert area.mean > area.previous_mean > 0, "the deposit under the droplets grows"
    assert not verdict.steady and "bead_area" in verdict.reason
    # Nothing leaves the domain's part ahead of the bead section in 40 ms
    # but the substrate, which enters at the inlet as it leaves through the
    # section: it fills with what the wires feed (a droplet every 10 ms per
    # wire: over four 8 ms windows the slope of the mass steps is not the
    # feed's mean, but far above the tolerance), so its balance is not
    # steady either
    balance = verdict.balance
    assert balance is not None and not balance.steady
    assert balance.region == "ahead of the section"
    assert balance.mass_rate > 10 * BALANCE_TOLERANCE * balance.mass_throughput
    assert "the metal and heat ahead of the section" in verdict.reason
    # ... by the wires' metal (the droplet sources' own count)
    ahead = case.table("upstreamTotals", "upstreamTotals")
    droplets = case.table("wireDroplets", "droplets")
    added = sum(droplets[c] for c in droplets.dtype.names if c.endswith("_addedMass"))
    rows = np.searchsorted(droplets["Time"], ahead["Time"][[0, -1]], side="right") - 1
    fed = float(added[rows[1]] - added[rows[0]])
    gained = float(ahead["metalMass"][-1] - ahead["metalMass"][0])
    print(f"metal ahead of the section gained {gained:.6e} kg, the wires added {fed:.6e} kg")
    assert gained == pytest.approx(fed, rel=UPSTREAM_MASS_TOLERANCE)
    # The part ahead of the section is the cells whose centres lie ahead of
    # it: before the droplets land the substrate is uniform along the weld,
    # so its metal is the domain's in proportion to the length, to half a
    # process-zone cell at the plane
    section = (case.scalar("system/caseParameters", "processPosition")
               + case.scalar("system/caseParameters", "beadSectionDistance"))
    length = case.scalar("system/caseParameters", "length")
    domain_mass = float(case.balances()["metal_mass"][0])
    share = float(ahead["metalMass"][0]) / domain_mass
    print(f"metal ahead of the section at {ahead['Time'][0]:.4g} s: {share:.5f} of the "
          f"domain's, the length ahead {section / length:.5f} of its length")
    assert share == pytest.approx(section / length, abs=0.5 * LEVEL0_CELL / length)
    # The command line says the same
    output = subprocess.run([sys.executable, "-m", "ldna.cli", "steady", str(case), "--json"],
                            capture_output=True, text=True, check=True).stdout
    assert json.loads(output)["steady"] is False
    # Without the droplets' temperature the heat brought in is unknown: the
    # tool says so instead of judging the heat balance on a NaN
    droplets = case.table("wireDroplets", "droplets")
    for wire in (c[:-len("_addedMass")] for c in droplets.dtype.names
                 if c.endswith("_addedMass")):
        case.run(f"foamDictionary -entry wireDroplets/wires/{wire}/temperature -remove "
                 "constant/fvOptions", log_name="foamDictionary")
    case.run("foamDictionary -entry dropletTemperature -remove system/caseParameters",
             log_name="foamDictionary")
    with pytest.raises(ValueError, match="no droplet temperature"):
        DomainBalance.of(case.path)
