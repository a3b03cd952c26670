"""Reading and editing OpenFOAM dictionary files as text.

The one dictionary editor of the ldna tools.  It edits the file's text in
place, so comments, ``#include`` and ``#eval`` stay as written; OpenFOAM's
``foamDictionary -set`` would write the file with every macro expanded,
and foamlib 1.7.10 cannot parse the v1912 ``#eval{ ... }`` entries of the
template (``constant/fvOptions``, ``system/blockMeshDict``,
``system/controlDict``).  Entries are named as foamDictionary names them,
scoped with slashes (``coeffs/n``, ``functions/meltPoolMetrics/writeControl``).
An entry that is not there is an error unless the caller asks to add it
(``create=True``): nothing falls back silently.  Reading a value as OpenFOAM
expands it is ``Case.value`` (foamDictionary ``-value``).
"""
from __future__ import annotations

import re
from itertools import accumulate
from pathlib import Path

_ENTRY = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s+([^;{}]+?)\s*;", re.MULTILINE)
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
#: What may come before an entry's keyword on its line: the start of a
#: statement (a keyword after any other character is a value: ``type wall;``)
_STATEMENT_END = "{};"


def read_entries(path: Path) -> dict[str, str]:
    """Return the top-level ``keyword value;`` entries of a dictionary file."""
    text = _COMMENT.sub("", Path(path).read_text())
    return {key: value.strip() for key, value in _ENTRY.findall(text)}


def read_scalars(path: Path) -> dict[str, float]:
    """Return the entries of a dictionary file whose value is one number."""
    scalars: dict[str, float] = {}
    for key, value in read_entries(path).items():
        try:
            scalars[key] = float(value)
        except ValueError:
            continue
    return scalars


_CODE = re.compile(r"#\{.*?#\}", re.DOTALL)
_EXPRESSION = re.compile(r"(#eval\s*|\$)\{")


def _expression_braces_blanked(text: str) -> str:
    """``text`` with the braces of ``#eval{ ... }`` and ``${ ... }`` (and any
    nested in them) replaced by blanks."""
    chars = list(text)
    for match in _EXPRESSION.finditer(text):
        opening = match.end() - 1
        if chars[opening] != "{":
            continue
        level = 0
        for i in range(opening, len(chars)):
            if chars[i] == "{":
                level += 1
            elif chars[i] == "}":
                level -= 1
            else:
                continue
            chars[i] = " "
            if level == 0:
                break
    return "".join(chars)


class _Text:
    """A dictionary file's text with its comments blanked out (same
    offsets) and the brace depth before each character."""

    def __init__(self, text: str) -> None:
        self.text = text
        blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))  # noqa: E731
        masked = _COMMENT.sub(blank, text)
        # Braces that open no sub-dictionary: #eval{ ... }, ${ ... }, #{ ... #}
        masked = _CODE.sub(blank, masked)
        self.masked = _expression_braces_blanked(masked)
        self.depth = [0, *accumulate((c == "{") - (c == "}") for c in self.masked)]

    def closing(self, opening: int) -> int:
        """Offset of the brace that closes the one at ``opening``."""
        level = self.depth[opening]
        for i in range(opening + 1, len(self.masked)):
            if self.masked[i] == "}" and self.depth[i] == level + 1:
                return i
        raise ValueError("unbalanced braces")

    def find(self, keyword: str, lo: int, hi: int, level: int) -> tuple[int, int, int] | None:
        """The entry ``keyword`` at brace depth ``level`` within [lo, hi):
        (start of the keyword, start of its value, end of the entry: after
        its ``;`` or its block's closing brace); None if it is not there."""
        pattern = re.compile(rf"(?<![\w.\"$#]){re.escape(keyword)}(?=[\s{{])")
        for match in pattern.finditer(self.masked, lo, hi):
            start = match.start()
            if self.depth[start] != level:
                continue
            before = self.masked[:start].rstrip(" \t")
            if before and before[-1] != "\n" and before[-1] not in _STATEMENT_END:
                continue
            value = match.end()
            while value < hi and self.masked[value].isspace():
                value += 1
            if value < hi and self.masked[value] == "{":
                return start, value, self.closing(value) + 1
            end = self.masked.find(";", value, hi)
            if end < 0 or "{" in self.masked[value:end] or "}" in self.masked[value:end]:
                continue
            return start, value, end + 1
        return None


def _locate(text: _Text, entry: str, path: Path) -> tuple[int, int, int, str]:
    """Where the scoped ``entry`` is or goes: (lo, hi, level) of the
    innermost block that holds it, and its keyword; KeyError if a block on
    the way is not there."""
    *blocks, keyword = entry.split("/")
    lo, hi, level = 0, len(text.text), 0
    for name in blocks:
        found = text.find(name, lo, hi, level)
        if found is None or text.masked[found[1]] != "{":
            raise KeyError(f"no sub-dictionary '{name}' of '{entry}' in {path}")
        lo, hi, level = found[1] + 1, found[2] - 1, level + 1
    return lo, hi, level, keyword


def entry_text(path: Path, entry: str) -> str:
    """The value of a (scoped) entry as written in the file (macros as
    they are; a sub-dictionary with its braces); KeyError if absent."""
    path = Path(path)
    text = _Text(path.read_text())
    lo, hi, level, keyword = _locate(text, entry, path)
    found = text.find(keyword, lo, hi, level)
    if found is None:
        raise KeyError(f"no entry '{entry}' in {path}")
    _, value, end = found
    return text.text[value:end].rstrip(";").strip()


def set_entry(path: Path, entry: str, value: str, create: bool = False) -> None:
    """Set the (scoped) ``entry`` of a dictionary file to ``value`` in place.

    ``value`` is the text after the keyword: ``1e-3``, ``(3 1 1)``, or a
    sub-dictionary ``{ type zeroGradient; }``.  An entry that is not there
    raises KeyError, or with ``create`` is added at the top of its
    sub-dictionary (or at the end of the file); the rest of the file stays
    as written.
    """
    path = Path(path)
    text = _Text(path.read_text())
    lo, hi, level, keyword = _locate(text, entry, path)
    value = value.strip()
    statement = value if value.startswith("{") else f"{value};"
    found = text.find(keyword, lo, hi, level)
    if found is not None:
        _, start, end = found
        new = text.text[:start] + statement + text.text[end:]
    elif not create:
        raise KeyError(f"no entry '{entry}' in {path} (create=True adds it)")
    elif level == 0:
        new = text.text.rstrip("\n") + f"\n\n{keyword} {statement}\n"
    else:
        indent = "    " * level
        new = text.text[:lo] + f"\n{indent}{keyword} {statement}" + text.text[lo:]
    path.write_text(new)


def _top_level_blocks(text: str) -> list[tuple[str, int, int]]:
    """Return (name, start, end) of each top-level ``name { ... }`` block:
    ``start`` is the beginning of the line holding the name, ``end`` just
    after the closing brace."""
    parsed = _Text(text)
    head = re.compile(r"([A-Za-z_][A-Za-z0-9_.]*)\s*$")
    blocks = []
    for opening, char in enumerate(parsed.masked):
        if char != "{" or parsed.depth[opening] != 0:
            continue
        match = head.search(parsed.masked, 0, opening)
        if match is None:
            continue
        start = text.rfind("\n", 0, match.start(1)) + 1
        blocks.append((match.group(1), start, parsed.closing(opening) + 1))
    return blocks


def block_names(path: Path) -> list[str]:
    """Return the names of the top-level sub-dictionaries of a file."""
    return [name for name, _, _ in _top_level_blocks(Path(path).read_text())
            if name != "FoamFile"]


def remove_blocks(path: Path, names: list[str]) -> None:
    """Remove top-level sub-dictionaries by name, leaving the rest as written
    (``#include`` and ``#eval`` lines as they are)."""
    path = Path(path)
    text = path.read_text()
    blocks = {name: (start, end) for name, start, end in _top_level_blocks(text)}
    missing = [name for name in names if name not in blocks]
    if missing:
        raise KeyError(f"no sub-dictionary {missing} in {path}")
    for start, end in sorted((blocks[name] for name in names), reverse=True):
        text = text[:start] + text[end:].lstrip("\n")
    path.write_text(text)


def keep_blocks(path: Path, names: list[str]) -> None:
    """Keep only the named top-level sub-dictionaries (and FoamFile)."""
    remove_blocks(path, [name for name in block_names(path) if name not in names])
