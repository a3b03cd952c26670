"""Minimal reading and editing of OpenFOAM dictionary files.

Only what the ldna tooling needs: top-level ``keyword value;`` entries of
case dictionaries such as ``system/caseParameters``.  Full parsing is left
to OpenFOAM's own ``foamDictionary``.
"""
from __future__ import annotations

import re
from itertools import accumulate
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
    """Replace the value of a top-level entry ``keyword value;`` in place
    (one outside every sub-dictionary); comments and macros stay."""
    path = Path(path)
    text = path.read_text()
    depth_at = list(accumulate((c == "{") - (c == "}") for c in _COMMENT.sub(
        lambda m: " " * len(m.group(0)), text)))
    pattern = re.compile(rf"^(\s*{re.escape(keyword)}\s+)[^;]*;", re.MULTILINE)
    for match in pattern.finditer(text):
        if depth_at[match.start()] == 0:
            path.write_text(text[:match.start()] + f"{match.group(1)}{value};"
                            + text[match.end():])
            return
    raise KeyError(f"entry '{keyword}' not found in {path}")


def _top_level_blocks(text: str) -> list[tuple[str, int, int]]:
    """Return (name, start, end) of each top-level ``name { ... }`` block.

    ``start`` is the beginning of the line holding the name and ``end`` is
    just after the closing brace.  Comments are skipped when counting braces.
    """
    blocks: list[tuple[str, int, int]] = []
    depth = 0
    i = 0
    opened: tuple[str, int] | None = None
    # A block's name stands alone on its line, or before the brace on it
    head = re.compile(r"(?:^|\n)[ \t]*([A-Za-z_][A-Za-z0-9_.]*)\s*$")
    while i < len(text):
        if text.startswith("//", i):
            end = text.find("\n", i)
            i = len(text) if end < 0 else end
            continue
        if text.startswith("/*", i):
            i = text.find("*/", i) + 2
            continue
        char = text[i]
        if char == "{":
            if depth == 0:
                match = head.search(text, 0, i)
                opened = (match.group(1), text.rfind("\n", 0, match.start(1)) + 1) \
                    if match else None
            depth += 1
        elif char == "}":
            depth -= 1
            if depth == 0 and opened is not None:
                blocks.append((opened[0], opened[1], i + 1))
                opened = None
        i += 1
    return blocks


def block_names(path: Path) -> list[str]:
    """Return the names of the top-level sub-dictionaries of a file."""
    return [name for name, _, _ in _top_level_blocks(Path(path).read_text())
            if name != "FoamFile"]


def remove_blocks(path: Path, names: list[str]) -> None:
    """Remove top-level sub-dictionaries by name, leaving the rest as written.

    Unlike ``foamDictionary -remove``, this keeps ``#include`` and ``#eval``
    lines as they are (foamDictionary writes the expanded dictionary).
    """
    path = Path(path)
    text = path.read_text()
    blocks = {name: (start, end) for name, start, end in _top_level_blocks(text)}
    missing = [name for name in names if name not in blocks]
    if missing:
        raise KeyError(f"no sub-dictionary {missing} in {path}")
    for start, end in sorted((blocks[name] for name in names), reverse=True):
        text = text[:start] + text[end:].lstrip("\n")
    path.write_text(text)


def set_block_entry(path: Path, block: str, keyword: str, value: str) -> None:
    """Set ``keyword value;`` directly inside the top-level sub-dictionary ``block``.

    An existing entry of the block is replaced, otherwise the entry is added
    after the opening brace; the rest of the file (``#include``, ``#eval``,
    comments) stays as written.
    """
    path = Path(path)
    text = path.read_text()
    spans = {name: (start, end) for name, start, end in _top_level_blocks(text)}
    if block not in spans:
        raise KeyError(f"no sub-dictionary '{block}' in {path}")
    start, end = spans[block]
    body = text[start:end]
    opening = body.index("{") + 1
    # Only entries at the block's own level: none inside nested braces
    depth_at = list(accumulate((c == "{") - (c == "}") for c in body))
    pattern = re.compile(rf"^([ \t]*{re.escape(keyword)}\s+)[^;{{}}]*;", re.MULTILINE)
    for match in pattern.finditer(body):
        if depth_at[match.start()] == 1:
            body = body[:match.start()] + f"{match.group(1)}{value};" + body[match.end():]
            break
    else:
        body = body[:opening] + f"\n    {keyword} {value};" + body[opening:]
    path.write_text(text[:start] + body + text[end:])


def keep_blocks(path: Path, names: list[str]) -> None:
    """Keep only the named top-level sub-dictionaries (and FoamFile)."""
    remove_blocks(path, [name for name in block_names(path) if name not in names])
