"""The one dictionary editor (``ldna.foamdict``, behind ``Case.set``): it
edits entries in place at any depth, keeps comments and macros, and says
when an entry is not there instead of adding it unasked."""
from __future__ import annotations

from pathlib import Path

import pytest

from ldna.case import Case
from ldna.foamdict import block_names, entry_text, keep_blocks, set_entry
from solver_cases import TEMPLATE

#: A dictionary with what the template's files hold: an #include, #eval
#: entries whose braces open no sub-dictionary, ${...} macros, a code
#: block, comments naming the entries, a keyword that is also a value (in
#: a list, too)
DICTIONARY = """\
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
#include "caseParameters"
// endTime 9; (a comment, not the entry)
endTime         0.5;
phases          (functions gas);
type            wall;
functions
{
    metrics
    {
        type            meltPoolMetrics;
        beadSection     #eval{ 1e-3*($processPosition + ${beadSectionDistance}) };
        writeControl    timeStep;   /* every few steps */
        code            #{ if (x) { y(); } #};
    }
    wall
    {
        type            patch;
    }
}
"""


@pytest.fixture
def dictionary(tmp_path: Path) -> Path:
    path = tmp_path / "controlDict"
    path.write_text(DICTIONARY)
    return path


def test_entries_are_set_in_place_at_any_depth(dictionary: Path) -> None:
    set_entry(dictionary, "endTime", "2")
    set_entry(dictionary, "functions/metrics/writeControl", "writeTime")
    set_entry(dictionary, "functions/wall/type", "wall")
    expected = (DICTIONARY.replace("endTime         0.5;", "endTime         2;")
                .replace("writeControl    timeStep;", "writeControl    writeTime;")
                .replace("type            patch;", "type            wall;"))
    assert dictionary.read_text() == expected


def test_macros_are_read_and_kept_as_written(dictionary: Path) -> None:
    assert entry_text(dictionary, "functions/metrics/beadSection") == (
        "#eval{ 1e-3*($processPosition + ${beadSectionDistance}) }")
    set_entry(dictionary, "functions/metrics/beadSection", "0.02")
    text = dictionary.read_text()
    assert "beadSection     0.02;" in text
    assert '#include "caseParameters"' in text and "#{ if (x) { y(); } #}" in text


def test_a_sub_dictionary_is_replaced_whole(dictionary: Path) -> None:
    set_entry(dictionary, "functions/wall", "{ type symmetry; }")
    assert entry_text(dictionary, "functions/wall") == "{ type symmetry; }"
    assert entry_text(dictionary, "functions/metrics/type") == "meltPoolMetrics"


def test_a_missing_entry_is_an_error_unless_asked_to_add_it(dictionary: Path) -> None:
    with pytest.raises(KeyError, match="no entry 'functions/metrics/writeInterval'"):
        set_entry(dictionary, "functions/metrics/writeInterval", "1")
    with pytest.raises(KeyError, match="no sub-dictionary 'probes'"):
        set_entry(dictionary, "functions/probes/type", "probes", create=True)
    assert dictionary.read_text() == DICTIONARY
    set_entry(dictionary, "functions/metrics/writeInterval", "1", create=True)
    set_entry(dictionary, "deltaT", "1e-4", create=True)
    assert entry_text(dictionary, "functions/metrics/writeInterval") == "1"
    assert entry_text(dictionary, "deltaT") == "1e-4"


def test_blocks_are_kept_by_name(dictionary: Path) -> None:
    assert block_names(dictionary) == ["functions"]
    keep_blocks(dictionary, [])
    assert "metrics" not in dictionary.read_text()
    assert dictionary.read_text().startswith("FoamFile")


def test_the_template_split_follows_the_number_of_ranks(tmp_path: Path) -> None:
    """decomposePar needs the hierarchical split to have as many parts as
    ranks: the template's split is written from the number and stays so."""
    case = Case.copy_of(TEMPLATE, tmp_path / "ldna")
    case.set_ranks(3)
    parameters = "system/decomposeParDict"
    assert case.written(parameters, "numberOfSubdomains") == "3"
    assert case.written(parameters, "coeffs/n") == "($numberOfSubdomains 1 1)"
