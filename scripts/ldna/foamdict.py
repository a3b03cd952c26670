"""Minimal reading and editing of OpenFOAM dictionary files.

Only what the ldna tooling needs: top-level ``keyword value;`` entries of
case dictionaries such as ``system/caseParameters``.  Full parsing is left
to OpenFOAM's own ``foamDictionary``.
"""
from __future__ import annotations

import re
from pathlib import Path

_ENTRY = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s+([^;{}]+?)\s*;", re.MULTILINE)
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)


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


def set_entry(path: Path, keyword: str, value: str) -> None:
    """Replace the value of a top-level entry ``keyword value;`` in place."""
    path = Path(path)
    text = path.read_text()
    pattern = re.compile(rf"^(\s*{re.escape(keyword)}\s+)[^;]*;", re.MULTILINE)
    new_text, count = pattern.subn(lambda m: f"{m.group(1)}{value};", text, count=1)
    if count != 1:
        raise KeyError(f"entry '{keyword}' not found in {path}")
    path.write_text(new_text)
