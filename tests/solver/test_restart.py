"""Stopping a run and restarting it from its last written time changes nothing.

The LDNA template (level 0, every effect on) runs once straight to
END_TIME, and once to STOP_TIME, where it stops and is started again
(``startFrom latestTime``, as a resubmitted cluster job does) to END_TIME.
Fields are written with 17 significant digits, so the restart reads back
exactly the state the first leg wrote; the two runs must then agree at
END_TIME to within the linear solvers' tolerance.
"""
from __future__ import annotations

import sys
import tarfile
from pathlib import Path

import numpy as np
import pytest

from ldna.balance import metal_mass_balance
from ldna import post
from ldna.case import TIME_INFO, Case
from solver_cases import PROJECT_DIR

#: Where the interrupted run stops, and where both runs end [s]
#: The first droplets are inserted at 9.7 ms, before the stop, the next ones
#: (every 10 ms) after it; the end is a write time (a multiple of the stop)
STOP_TIME = "0.015"
END_TIME = "0.03"
#: Allowed difference relative to each field's scale.  The template's
#: solvers stop at an absolute residual of 1e-8 to 1e-9 (fvSolution);
#: the same sequence of operations must reproduce that to round-off
FIELD_TOLERANCE = 1e-9
FIELDS = ("alpha.metal", "T", "U", "p_rgh")
#: The continued runs' end [s]: a few steps past the saved state
CONTINUED_END = "0.016"
LDNA = Path(sys.executable).parent / "ldna"
#: The checkout the Allrun of a case outside it needs
LDNA_DIR = PROJECT_DIR


def prepare(case: Case) -> None:
    """Mesh and initialise the case; exact (17 digit) ASCII output every STOP_TIME."""
    case.set("system/controlDict", "writePrecision", "17")
    case.set("system/controlDict", "writeInterval", STOP_TIME)
    case.mesh()
    case.run("setFields")


def test_restart_equals_uninterrupted_run(ldna_case: Case, tmp_path: Path) -> None:
    straight = ldna_case
    prepare(straight)
    interrupted = Case.copy_of(straight, tmp_path / "interrupted")
    # The copy leaves out the mesh: mesh the copy the same way
    interrupted.mesh()
    interrupted.run("setFields")

    straight.set("system/controlDict", "endTime", END_TIME)
    straight.run("ldnaFoam")

    interrupted.set("system/controlDict", "endTime", STOP_TIME)
    interrupted.run("ldnaFoam", log_name="ldnaFoam.first")
    # The stopped run carried to another checkout (ldna pack / unpack) and
    # continued there with the Allrun's -resume, as well as in place
    archive = tmp_path / "interrupted.tar.xz"
    interrupted.run(f"{LDNA} pack {interrupted.path} {archive}", log_name="pack")
    with tarfile.open(archive) as tar:
        names = [Path(name) for name in tar.getnames()]
    assert not [n for n in names if n.name.startswith(("log.", "processor"))]
    assert {n.parts[1] for n in names if len(n.parts) > 1 and n.parts[1][0].isdigit()} \
        == {"0", STOP_TIME}
    carried = Case(tmp_path / "elsewhere" / "carried")
    interrupted.run(f"{LDNA} unpack {archive} {carried.path}", log_name="unpack")
    carried.set("system/controlDict", "endTime", END_TIME)
    carried.run(f"LDNA_DIR={LDNA_DIR} ./Allrun -resume", log_name="Allrun")

    interrupted.set("system/controlDict", "endTime", END_TIME)
    interrupted.run("ldnaFoam", log_name="ldnaFoam.restart")
    assert f"Create mesh for time = {STOP_TIME}" in \
        (interrupted / "log.ldnaFoam.restart").read_text(), "the second leg did not restart"
    assert f"Create mesh for time = {STOP_TIME}" in (carried / "log.ldnaFoam").read_text(), \
        "the unpacked run did not continue from the packed time"
    # Its cost covers both legs: the first leg's timings came with it
    assert len(carried.table_files(*TIME_INFO)) == 2
    assert carried.simulated_seconds() == pytest.approx(float(END_TIME), rel=1e-6)

    for continued in (interrupted, carried):
        for field in FIELDS:
            a = straight.field(field, END_TIME)
            b = continued.field(field, END_TIME)
            scale = np.abs(a).max()
            difference = np.abs(a - b).max() / scale
            print(f"{continued.name} {field}: largest difference {difference:.3e} "
                  f"of its scale {scale:.4g}")
            assert difference < FIELD_TOLERANCE


#: The metal's budget of a run, as the stability tests hold it: 0.5 % of the
#: turnover
MASS_TOLERANCE = 5e-3


def test_a_run_starts_from_another_runs_state(ldna_case: Case, tmp_path: Path) -> None:
    """``Allrun -start-from RUN`` (a steady neighbour for a study member):
    the case meshes itself, takes RUN's fields at RUN's latest time, mapped
    onto its mesh (here the same mesh, so exactly), starts at that time and
    keeps the metal's budget from there."""
    source = ldna_case
    prepare(source)
    source.set("system/controlDict", "endTime", STOP_TIME)
    source.run("ldnaFoam")

    member = Case.copy_of(source, tmp_path / "member")
    member.set("system/controlDict", "endTime", END_TIME)
    member.run(f"./Allrun -start-from {source.path}", log_name="Allrun")

    assert f"Create mesh for time = {STOP_TIME}" in (member / "log.ldnaFoam").read_text(), \
        "the member did not start at the source's time"
    balances = member.balances()
    assert float(balances["time"][0]) == float(STOP_TIME)
    # The member's first state is the source's last: same metal, same heat
    source_end = source.balances()[-1]
    assert float(balances["metal_mass"][0]) == pytest.approx(float(source_end["metal_mass"]),
                                                            rel=1e-12)
    assert float(balances["enthalpy"][0]) == pytest.approx(float(source_end["enthalpy"]),
                                                          rel=1e-9)
    for field in ("alpha.metal", "T"):
        np.testing.assert_allclose(member.field(field, STOP_TIME),
                                   source.field(field, STOP_TIME), rtol=1e-12, atol=1e-15)
    # From there on the member conserves metal as any run does
    budget = metal_mass_balance(member)
    print(f"member's metal budget: {budget.residual:.3e} kg, "
          f"{100 * budget.relative_residual:.2e} % of the turnover")
    assert budget.added > 0, "the member's wires fed no metal"
    assert budget.relative_residual < MASS_TOLERANCE


def test_start_from_a_run_without_a_time_is_refused(ldna_case: Case, tmp_path: Path) -> None:
    """A start state that does not exist stops the Allrun with a message
    naming the run, before anything is meshed."""
    empty = tmp_path / "empty"
    empty.mkdir()
    result = ldna_case.run(f"./Allrun -start-from {empty}", log_name="Allrun", check=False)
    log = (ldna_case / "log.Allrun").read_text()
    assert result.returncode != 0
    assert str(empty) in log and "no reconstructed time" in log
    assert not (ldna_case / "log.blockMesh").exists(), "it meshed before refusing"


def test_a_saved_state_continues_its_weld(ldna_case: Case, tmp_path: Path) -> None:
    """``ldna save-state`` keeps a run's state compressed; ``Allrun
    -start-from STATE`` starts from it exactly, and a case with the same
    dictionaries (the same weld) also gets the state's tables before the
    start, which ``ldna steady`` then reads; a case with other knobs does not."""
    source = ldna_case
    prepare(source)
    source.set("system/controlDict", "endTime", STOP_TIME)
    source.run("ldnaFoam")
    state = tmp_path / "state"
    source.run(f"{LDNA} save-state {source.path} {state}", log_name="saveState")
    assert (state / STOP_TIME / "T.gz").is_file()
    assert (state / "constant" / "polyMesh" / "faces.gz").is_file()

    same = Case.copy_of(source, tmp_path / "same")
    other = Case.copy_of(source, tmp_path / "other")
    other.set("system/caseParameters", "laserPower", "1000")
    for member in (same, other):
        member.set("system/controlDict", "endTime", CONTINUED_END)
        member.run(f"./Allrun -start-from {state}", log_name="Allrun")
        assert f"Create mesh for time = {STOP_TIME}" in (member / "log.ldnaFoam").read_text()
        # The gzipped fields are the source's, digit for digit
        np.testing.assert_array_equal(member.field("T", STOP_TIME), source.field("T", STOP_TIME))

    balances = same.balances()
    source_balances = source.balances()
    kept = source_balances[source_balances["time"] < float(STOP_TIME)]
    print(f"continued weld: {len(balances)} balance rows from t = {balances['time'][0]} s, "
          f"of which {int((balances['time'] < float(STOP_TIME)).sum())} the state's "
          f"(the source wrote {len(kept)} before the start)")
    before = balances[balances["time"] < float(STOP_TIME)]
    assert 0 < len(before) <= len(kept)
    # The history rows are the source's own rows (thinned), not recomputed
    for row in before:
        match = kept[np.isclose(kept["time"], row["time"], rtol=0, atol=1e-12)]
        assert len(match) == 1
        assert float(row["metal_mass"]) == pytest.approx(float(match["metal_mass"][0]), rel=1e-8)
    assert float(other.balances()["time"][0]) == float(STOP_TIME), \
        "a case with other knobs got the state's history"
    # The totals ahead of the section continue too: the judge reads them over
    # the windows before the start (the short continuation itself may end
    # before its first row: its table is then empty, and skipped)
    ahead = same.table("upstreamTotals", "upstreamTotals")
    assert float(ahead["Time"][0]) < float(STOP_TIME)
    # The other weld starts at the state's time: its bead reaches a section
    # that long after the continued weld's (which started at 0)
    section = 0.02
    assert post.weld_start_time(same.path) == 0.0
    assert post.weld_start_time(other.path) == float(STOP_TIME)
    delay = post.bead_arrival_time(other, section) - post.bead_arrival_time(same, section)
    assert delay == pytest.approx(float(STOP_TIME), rel=1e-12)
    # ... and a state saved from it remembers when that weld started
    other_state = tmp_path / "other-state"
    other.run(f"{LDNA} save-state {other.path} {other_state}", log_name="saveState")
    assert list(other_state.glob("history/weldStart/*/start.dat.gz"))
