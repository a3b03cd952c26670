"""The README's commands as a user types them (marker ``user_path``).

Each command runs in a clean environment (``env -i``, HOME and a minimal
PATH), from a plain shell and from one with OpenFOAM already sourced: the
main scene ``bin/ldna-scene`` end to end and ``ldna post`` on its result,
a run that fails and the attempt after it, and every ``bin/`` script's
``--help`` and its refusal of bad options.  The tutorials and the template's
``Allrun`` scripts run in the same clean environment in test_tutorials and
test_cluster.
"""
from __future__ import annotations

import json
import math
import os
import re
import signal
import subprocess
import time
from pathlib import Path

import pytest

from ldna.case import Case
from ldna.case import PROJECT_DIR
from solver_cases import STEADY_WELD
from userpath import SHELLS, run_as_user, user_command

pytestmark = pytest.mark.user_path

#: The time of the saved steady weld the main command continues [s]
STATE_TIME = float(next(p.name for p in STEADY_WELD.iterdir() if p.name[0].isdigit()))
#: Simulated time of the short scenes [s]: not a multiple of the template's
#: write interval, so the last time must be written by the end-of-run rule
SPAN = 0.005
END_TIME = STATE_TIME + SPAN
#: The bead the continued weld shows at its section against the mass
#: balance: its area ripples by up to 8 % about a mean within 2.4 % of it
#: (32.2-36.1 mm2 about 34.1 mm2, docs/validation/bead.md)
BEAD_AREA_TOLERANCE = 0.10

#: What a second run on an installed, built machine must leave untouched
BUILD_PRODUCTS = ["build/bin/ldnaFoam", "build/lib/libldnaCore.so",
                  "build/lib/libldnaMixture.so", "build/lib/libldnaModels.so",
                  "build/lib/libldnaFunctionObjects.so",
                  "build/venv/.ldna-ready", "build/openfoam-env.sh"]


def scene_command(case: Case, end_time: float = END_TIME, options: str = "") -> str:
    """The README's main command with a short end time, on 2 ranks, into ``case``."""
    return f"bin/ldna-scene --level 0 --end-time {end_time:g} --np 2 --dir {case} {options}"


def build_stamps() -> dict[str, int]:
    return {path: (PROJECT_DIR / path).stat().st_mtime_ns for path in BUILD_PRODUCTS}


def last_reconstructed_time(case: Case) -> float:
    times = [t for t in case.times if float(t.name) > 0 and (t / "T").exists()]
    assert times, f"no reconstructed time directory in {case}"
    return float(times[-1].name)


def last_solved_time(case: Case) -> float:
    """The time of the solver's last step, from its balance table."""
    return float(case.balances()["time"][-1])


@pytest.mark.parametrize("shell", list(SHELLS))
def test_ldna_scene_as_written(tmp_path: Path, shell: str) -> None:
    case = Case(tmp_path / "scene")
    before = build_stamps()

    # A progress line every second, so that this short run shows some
    scene = run_as_user(scene_command(case), shell=shell, LDNA_PROGRESS_INTERVAL="1")

    assert scene.returncode == 0, scene.output[-3000:]
    progress = [float(m.group(1)) for m in
                re.finditer(r"^  t = (\S+) of [\d.e-]+ s, \d+ steps, \d+ s wall time", scene.output,
                            re.M)]
    assert progress, "no progress line while the solver ran"
    # Progress reads the solver's balances table, so it never passes the
    # table's last step (which may pass the end time by half a step)
    assert progress == sorted(progress) and STATE_TIME <= progress[0] \
        and progress[-1] <= last_solved_time(case)
    assert "[ldna-install]" not in scene.output, "an installed machine installs nothing"
    assert build_stamps() == before, "a built machine rebuilds nothing"
    # The last step is written whatever the write interval; OpenFOAM ends a
    # run within half a step of the end time
    assert last_reconstructed_time(case) == last_solved_time(case)
    # OpenFOAM stops within half a step of the end time; the table writes
    # time to timePrecision's significant digits
    max_step = case.scalar("system/controlDict", "maxDeltaT")
    precision = case.scalar("system/controlDict", "timePrecision")
    rounding = 0.5 * 10 ** (math.floor(math.log10(END_TIME)) + 1 - precision)
    assert abs(last_solved_time(case) - END_TIME) <= 0.5 * max_step + rounding
    assert (case / "ldna.foam").exists()
    assert "bead width" in scene.output and "peak metal T" in scene.output
    # The default continues the saved weld, with its tables before the start,
    # and judges it over them: whole windows from the first step on, not
    # "too short" (the verdict itself is the weld's at its start, which
    # lies at the edge of the tolerances)
    assert f"Continuing the weld of {STEADY_WELD}" in scene.output
    verdict = re.search(r"^windows of \S+ s to t = \S+ s: (.*)$", scene.output, re.M)
    assert verdict is not None and "too short" not in verdict.group(1), scene.output[-1500:]
    assert f"Results: {case}" in scene.output

    post = run_as_user(f"build/venv/bin/ldna post {case}", shell=shell)
    assert post.returncode == 0, post.output[-3000:]
    for picture in ("surface.png", "transverse.png", "longitudinal.png"):
        assert (case / "pictures" / picture).stat().st_size > 10_000, picture

    as_json = run_as_user(f"build/venv/bin/ldna post {case} --json", shell=shell)
    assert as_json.returncode == 0, as_json.output[-3000:]
    figures = json.loads([line for line in as_json.output.splitlines()
                          if line.startswith("{")][-1])
    assert figures["time_s"] == pytest.approx(last_solved_time(case), rel=1e-4)
    # A bead at the section, as the wires' mass rate makes it
    print(f"bead {figures['bead_width_mm']:.2f} x {figures['bead_height_mm']:.2f} mm, "
          f"{figures['bead_area_mm2']:.2f} mm2 (mass balance "
          f"{figures['expected_bead_area_mm2']:.2f} mm2)")
    assert figures["bead_area_mm2"] == pytest.approx(figures["expected_bead_area_mm2"],
                                                     rel=BEAD_AREA_TOLERANCE)
    # How much of the section's bead is still liquid: a share of its metal
    share = figures["section_liquid_share"]
    print(f"section liquid share {share}")
    assert share is not None and 0 <= share <= 1
    # The bead's start travels from the wires' midpoint with the substrate
    parameters = "system/caseParameters"
    travel_mm = figures["bead_section_mm"] - case.scalar(parameters, "processPosition")
    speed_mm_s = 1e3 * case.scalar(parameters, "weldingSpeed")
    assert figures["bead_arrival_s"] == pytest.approx(travel_mm / speed_mm_s, rel=1e-6)


def test_ldna_scene_from_the_flat_substrate(tmp_path: Path) -> None:
    """``--from-flat`` welds from t = 0; a run shorter than the bead's travel
    to its section says so."""
    case = Case(tmp_path / "flat")
    scene = run_as_user(scene_command(case, SPAN, "--from-flat"))
    assert scene.returncode == 0, scene.output[-3000:]
    assert "Continuing the weld" not in scene.output
    assert 0.8 * SPAN < last_solved_time(case) <= SPAN * 1.01
    assert "The bead has not reached the section" in scene.output


def _kill_solver_in(directory: Path) -> int:
    """SIGKILL the ldnaFoam processes running in ``directory``."""
    killed = 0
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit():
            continue
        try:
            if (proc / "comm").read_text().strip() == "ldnaFoam" \
                    and Path(os.readlink(proc / "cwd")) == directory:
                os.kill(int(proc.name), signal.SIGKILL)
                killed += 1
        except (OSError, ValueError):
            continue
    return killed


def test_failed_scene_does_not_block_the_next_attempt(tmp_path: Path) -> None:
    case = Case(tmp_path / "scene")
    command = scene_command(case, end_time=STATE_TIME + 1.0)
    scene = subprocess.Popen(user_command(command), cwd=PROJECT_DIR,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    # The solver is killed once it is running, as a cluster kills a job
    log = case / "log.ldnaFoam"
    deadline = time.monotonic() + 600
    while not (log.exists() and log.read_text(errors="replace").count("\nTime = ") > 2):
        assert scene.poll() is None, scene.communicate()[0][-3000:]
        assert time.monotonic() < deadline, "the solver did not start"
        time.sleep(0.5)
    assert _kill_solver_in(case.path) > 0
    output = scene.communicate(timeout=300)[0]

    assert scene.returncode != 0
    assert "ldnaFoam failed" in output
    assert re.search(r"^ldna-scene: the case's Allrun -parallel .*failed$", output, re.M)
    failed = tmp_path / "scene.failed"
    assert f"kept in {failed}" in output
    assert (failed / "log.ldnaFoam").exists() and not case.path.exists()

    retry = run_as_user(scene_command(case))
    assert retry.returncode == 0, retry.output[-3000:]
    assert last_reconstructed_time(case) == last_solved_time(case)


BIN_SCRIPTS = ["bin/ldna-scene", "bin/ldna-test", "bin/ldna-install", "bin/ldna-env"]


@pytest.mark.parametrize("script", BIN_SCRIPTS)
def test_bin_script_help(script: str) -> None:
    outcome = run_as_user(f"{script} --help")
    assert outcome.returncode == 0, outcome.output
    assert script.split("/")[-1].replace("ldna-", "") in outcome.output.lower()
    assert "Traceback" not in outcome.output


BAD_OPTIONS = [
    ("bin/ldna-scene", "--np 0", "--np"),
    ("bin/ldna-scene", "--np two", "--np"),
    ("bin/ldna-scene", "--level 7", "--level"),
    ("bin/ldna-scene", "--end-time -1", "--end-time"),
    ("bin/ldna-scene", "--end-time nan", "--end-time"),
    ("bin/ldna-scene", "--end-time", "needs a value"),
    ("bin/ldna-scene", "--dir cases/ldna", "exists"),
    ("bin/ldna-scene", "--levle 1", "unknown option"),
    ("bin/ldna-scene", "--end-time 2.5", "not past the start's time"),
    ("bin/ldna-scene", "--from-flat --steady-start", "different starts"),
    ("bin/ldna-scene", "--start-time 3", "needs --start-from"),
    ("bin/ldna-test", "--fast", "unknown option"),
    ("bin/ldna-test", "-k", "needs a value"),
    ("bin/ldna-install", "--yes", "unknown option"),
    ("bin/ldna-env", "--yes", "unknown option"),
]


@pytest.mark.parametrize("script,options,message", BAD_OPTIONS,
                         ids=[f"{s.split('/')[-1]} {o}" for s, o, _ in BAD_OPTIONS])
def test_bin_script_rejects_bad_options(script: str, options: str, message: str) -> None:
    outcome = run_as_user(f"{script} {options}", timeout=60)
    assert outcome.returncode != 0
    lines = outcome.output.strip().splitlines()
    assert len(lines) == 1, outcome.output
    assert message in lines[0]
