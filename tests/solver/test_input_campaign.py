"""Malformed-input campaign: every numeric entry of the template, one bad value at a time.

The LDNA template on a coarse mesh (600 cells, Gaussian droplets, which need
no resolved droplet) runs one time step per variant.  For every numeric entry
(numbers, Function1s, vectors) of the effects in constant/fvOptions, of
constant/thermophysicalProperties, of the PIMPLE controls in
system/fvSolution and of meltPoolMetrics and upstreamTotals in
system/controlDict the variants are the values nan, inf, -1, 0 and 1e300,
the entry removed, its key misspelt and a word where the number goes.  Each
run must end in one of two ways:

- a named error: a non-zero exit with a FOAM FATAL (IO) ERROR whose text
  names the entry (a misspelt key: the misspelling and the key it suggests);
- a legal run: exit 0 with finite, bounded fields after the step (the value
  is allowed, or the removed entry is optional).

Anything else (a signal, an error that does not name the entry, NaN in the
fields, a misspelt key that runs with its default, a hang) counts as
"other", and there must be none.  The table of entries x variants and the
totals are printed (pytest -s); docs/validation.md quotes the totals.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from ldna.case import Case
from ldna.case import ENV_SCRIPT
from solver_cases import TEMPLATE

pytestmark = pytest.mark.bad_input

#: The dictionaries of the campaign and the scopes whose entries it varies
#: (None: all; in fvOptions the effects, not the case parameters that
#: #include brings to its top level)
SCOPES: dict[str, list[str] | None] = {
    "constant/fvOptions": ["wireDroplets", "laser", "marangoni", "evaporation",
                           "surfaceLosses", "enthalpyPorosity"],
    "constant/thermophysicalProperties": None,
    "system/fvSolution": ["PIMPLE"],
    "system/controlDict": ["functions/meltPoolMetrics", "functions/upstreamTotals"],
}
FILES = list(SCOPES)
#: The bad values of every numeric entry
VALUES = ["nan", "inf", "-1", "0", "1e300"]
#: The other malformations of every entry
MISSING, MISSPELT, WORD = "missing", "misspelt", "word"
VARIANTS = VALUES + [MISSING, MISSPELT, WORD]
#: Coarse cells over the template's 28 x 28 x 15.3 mm domain
COARSE_CELLS = {"nx": "10", "ny": "10", "nSub": "3", "nClad": "3", "nRefine": "0"}
#: A hang is a failure: one step on 600 cells takes well under a second
RUN_TIMEOUT = 60
#: Bounds of a legal step: the metal fraction within the hard cases' bounds,
#: temperatures above absolute zero and below the physical limit of the inputs
ALPHA_BOUND = 1e-6
TEMPERATURE_LIMIT = 1e4
WORKERS = 2


@dataclass(frozen=True)
class Entry:
    """A numeric entry: its file, slash-separated path and kind of value."""
    file: str
    path: str
    kind: str  # "scalar", "function" (a Function1) or "vector"

    @property
    def key(self) -> str:
        return self.path.split("/")[-1]

    def value(self, bad: str) -> str:
        if self.kind == "function":
            return f"constant {bad}"
        if self.kind == "vector":
            return f"({bad} {bad} {bad})"
        return bad


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_TOKEN = re.compile(r"//[^\n]*|/\*.*?\*/|[{};]|\([^;{}]*\)|[^\s{};()]+", re.S)


def numeric_entries(text: str, file: str) -> list[Entry]:
    """The numeric entries of an expanded dictionary (foamDictionary -expand)
    inside the file's scopes of :data:`SCOPES`."""
    scopes = SCOPES.get(file)
    entries: list[Entry] = []
    scope: list[str] = []
    statement: list[str] = []
    for match in _TOKEN.finditer(text):
        token = match.group()
        if token.startswith(("//", "/*")):
            continue
        if token == "{":
            scope.append(statement[0] if statement else "")
            statement = []
        elif token == "}":
            scope.pop()
            statement = []
        elif token == ";":
            if len(statement) >= 2 and scope[:1] != ["FoamFile"] and statement[0] != "FoamFile":
                key, value = statement[0], statement[1:]
                kind = None
                if len(value) == 1 and re.fullmatch(_NUMBER, value[0]):
                    kind = "scalar"
                elif value[0] in ("constant", "polynomial", "table"):
                    kind = "function"
                elif (len(value) == 1 and value[0].startswith("(")
                      and len(value[0].strip("()").split()) == 3
                      and all(re.fullmatch(_NUMBER, v) for v in value[0].strip("()").split())):
                    kind = "vector"
                path = "/".join(scope + [key])
                if kind and (scopes is None or any(path.startswith(f"{s}/") for s in scopes)):
                    entries.append(Entry(file, path, kind))
            statement = []
        else:
            statement.append(token)
    return entries


def misspelling(key: str) -> str:
    """A typing error of a key: its last letter doubled."""
    return key + key[-1]


@pytest.fixture(scope="module")
def coarse_template(tmp_path_factory: pytest.TempPathFactory) -> Case:
    """The template on 600 cells with Gaussian droplets, expanded, one step long."""
    case = Case.copy_of(TEMPLATE, tmp_path_factory.mktemp("campaign") / "base")
    for key, value in COARSE_CELLS.items():
        case.set("system/meshLevels/level0", key, value)
    case.set("system/controlDict", "endTime", "1e-4")
    case.set("system/controlDict", "writeInterval", "1")
    case.run("blockMesh")
    case.run("setFields")
    for file in FILES:
        case.run(f"foamDictionary -expand {file} > {file}.expanded && mv {file}.expanded {file}",
                 log_name="foamDictionary")
    case.run("foamDictionary -entry wireDroplets/mode -set gaussian constant/fvOptions",
             log_name="foamDictionary")
    return case


def edit_command(entry: Entry, variant: str) -> str:
    """The foamDictionary command that makes the variant of the entry."""
    if variant == MISSING:
        return f"foamDictionary -entry '{entry.path}' -remove {entry.file}"
    if variant == MISSPELT:
        # Add the misspelt key with the entry's value, then remove the entry
        scope = "/".join(entry.path.split("/")[:-1] + [misspelling(entry.key)])
        return (f"value=$(foamDictionary -entry '{entry.path}' -value {entry.file}) && "
                f"foamDictionary -entry '{scope}' -set \"$value\" {entry.file} && "
                f"foamDictionary -entry '{entry.path}' -remove {entry.file}")
    value = entry.value("one" if variant == WORD else variant)
    return f"foamDictionary -entry '{entry.path}' -set '{value}' {entry.file}"


@dataclass
class Outcome:
    entry: Entry
    variant: str
    result: str  # "named", "legal" or "other"
    detail: str


def names_word(name: str, text: str) -> bool:
    """True if text holds name as a word of its own (mu, not the mu of must)."""
    return re.search(rf"(?<![A-Za-z0-9]){re.escape(name)}(?![A-Za-z0-9])", text) is not None


def classify(entry: Entry, variant: str, returncode: int, output: str, case: Case) -> Outcome:
    """Named error, legal run or other, with the line that shows it."""
    error_start = output.find("FOAM FATAL")
    if returncode != 0:
        error = output[error_start:error_start + 3000] if error_start >= 0 else ""
        names = [misspelling(entry.key), entry.key] if variant == MISSPELT else [entry.key]
        if error and all(names_word(name, error) for name in names):
            lines = [line for line in error.splitlines()[1:] if line.strip()]
            return Outcome(entry, variant, "named", lines[0][:120] if lines else "")
        return Outcome(entry, variant, "other", f"exit {returncode}: "
                       + (error[:200] if error else output[-300:]).replace("\n", " "))
    if variant == MISSPELT:
        return Outcome(entry, variant, "other", "a misspelt key ran with the default")
    if "End" not in output or re.search(r"\b(nan|inf)\b", output, re.I):
        return Outcome(entry, variant, "other", "ran, but not to the end or with NaN/inf")
    balances = case.balances()
    low, high = case.alpha_bounds()
    finite = len(balances) > 0 and np.all(np.isfinite(balances["T_max"]))
    bounded = (finite and low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND
               and balances["T_min"].min() > 0 and balances["T_max"].max() < TEMPERATURE_LIMIT)
    if not bounded:
        return Outcome(entry, variant, "other",
                       f"ran, unbounded: alpha [{low:g}, {high:g}], "
                       f"T [{balances['T_min'].min():g}, {balances['T_max'].max():g}] K")
    return Outcome(entry, variant, "legal",
                   f"T [{balances['T_min'].min():.0f}, {balances['T_max'].max():.0f}] K")


def run_variant(base: Case, index: int, entry: Entry, variant: str) -> Outcome:
    """Copy the base case, apply one malformation, run one step, classify."""
    case = Case(base.path.parent / f"v{index:04d}")
    shutil.copytree(base, case, ignore=shutil.ignore_patterns("log.*", "postProcessing"))
    script = (f'. "{ENV_SCRIPT}" && cd "{case}" && ({edit_command(entry, variant)}) '
              f'> log.edit 2>&1 && ldnaFoam > log.ldnaFoam 2>&1')
    try:
        proc = subprocess.run(["bash", "-c", script], timeout=RUN_TIMEOUT, check=False)
        returncode = proc.returncode
    except subprocess.TimeoutExpired:
        return Outcome(entry, variant, "other", f"no end within {RUN_TIMEOUT} s")
    log = case / "log.ldnaFoam"
    output = log.read_text(errors="replace") if log.exists() else ""
    if not output:
        return Outcome(entry, variant, "other",
                       "the edit failed: " + (case / "log.edit").read_text()[-200:])
    outcome = classify(entry, variant, returncode, output, case)
    if outcome.result != "other":
        shutil.rmtree(case)
    return outcome


def test_every_malformed_entry_gets_a_named_error_or_runs_bounded(coarse_template: Case) -> None:
    entries = [entry for file in FILES
               for entry in numeric_entries((coarse_template / file).read_text(), file)]
    assert len(entries) >= 40, [e.path for e in entries]

    jobs = [(entry, variant) for entry in entries for variant in VARIANTS]
    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        outcomes = list(pool.map(lambda job: run_variant(coarse_template, job[0], *job[1]),
                                 enumerate(jobs)))

    symbols = {"named": "E", "legal": "ok", "other": "XX"}
    width = max(len(f"{e.file.split('/')[-1]}:{e.path}") for e in entries)
    print(f"\n{'entry':<{width}} " + " ".join(f"{v:>8}" for v in VARIANTS))
    for i, entry in enumerate(entries):
        row = outcomes[i * len(VARIANTS):(i + 1) * len(VARIANTS)]
        name = f"{entry.file.split('/')[-1]}:{entry.path}"
        print(f"{name:<{width}} " + " ".join(f"{symbols[o.result]:>8}" for o in row))
    totals = Counter(o.result for o in outcomes)
    print(f"tried {len(outcomes)} ({len(entries)} entries x {len(VARIANTS)} variants): "
          f"{totals['named']} named errors, {totals['legal']} legal runs, "
          f"{totals['other']} other")

    others = [f"{o.entry.path} = {o.variant}: {o.detail}" for o in outcomes if o.result == "other"]
    assert not others, "\n".join(others)


#: Entries each valid alone but inconsistent with the case: (entry, value,
#: texts the error must hold)
INCONSISTENT = [
    ("wireDroplets/position", "(0.007 0 -0.002)", ["position", "lies in metal"]),
    ("laser/position", "(0.05 0 0)", ["position", "outside the mesh"]),
    ("enthalpyPorosity/weldingSpeed", "constant 0.01", ["weldingSpeed", "substrateInlet"]),
    ("evaporation/boilingTemperature", "1700", ["boilingTemperature", "(1708"]),
]


@pytest.mark.parametrize("path,value,expected", INCONSISTENT, ids=[c[0] for c in INCONSISTENT])
def test_inconsistent_entries_get_their_own_error(coarse_template: Case, path: str, value: str,
                                                  expected: list[str]) -> None:
    case = Case(coarse_template.path.parent / ("inconsistent_" + path.replace("/", "_")))
    shutil.copytree(coarse_template, case, ignore=shutil.ignore_patterns("log.*", "postProcessing"))
    case.run(f"foamDictionary -entry '{path}' -set '{value}' constant/fvOptions",
             log_name="foamDictionary")
    result = case.run("ldnaFoam", check=False)
    error = result.output[result.output.find("FOAM FATAL IO ERROR"):]
    print(error[:500])
    assert result.returncode != 0 and "FOAM FATAL IO ERROR" in result.output
    for text in expected:
        assert text in error, f"'{text}' missing from the error"


def test_an_error_mid_run_leaves_the_last_written_time_restartable(coarse_template: Case) -> None:
    """A welding speed that turns negative at 0.5 ms stops the run there with
    the entry named; the last written time holds every field and the run
    restarts from it once the input is fixed."""
    case = Case(coarse_template.path.parent / "midRunError")
    shutil.copytree(coarse_template, case, ignore=shutil.ignore_patterns("log.*", "postProcessing"))
    case.set("system/controlDict", "endTime", "1e-3")
    case.set("system/controlDict", "writeControl", "timeStep")
    case.set("system/controlDict", "writeInterval", "1")
    porosity = "enthalpyPorosity/weldingSpeed"
    case.run(f"foamDictionary -entry {porosity} -set "
             "'table ((0 0.0075) (5e-4 0.0075) (5.0001e-4 -1) (1 -1))' constant/fvOptions",
             log_name="foamDictionary")

    failed = case.run("ldnaFoam", check=False)
    error = failed.output[failed.output.find("FOAM FATAL"):]
    print(error[:300])
    assert failed.returncode != 0 and "'weldingSpeed'" in error

    written = [t for t in case.times if float(t.name) > 0]
    assert written, "no time was written before the error"
    last = written[-1]
    assert 0 < float(last.name) <= 5.0001e-4 + 1e-12
    fields = {"alpha.metal", "T", "U", "p", "p_rgh"}
    assert fields <= {path.name for path in last.iterdir()}, sorted(p.name for p in last.iterdir())

    case.run(f"foamDictionary -entry {porosity} -set 'constant 0.0075' constant/fvOptions",
             log_name="foamDictionary.fix")
    case.set("system/controlDict", "startFrom", "latestTime")
    restarted = case.run("ldnaFoam", log_name="ldnaFoam.restart")
    assert f"Create mesh for time = {last.name}" in restarted.output
    assert "End" in restarted.output
    balances = case.balances()
    assert np.all(np.isfinite(balances["T_max"])) and np.all(np.isfinite(balances["metal_mass"]))
