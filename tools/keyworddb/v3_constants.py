"""The v3 predefined constants (v3 guide §4.3.1) and their v4 counterparts.

Values come from the v3 guide's table; the v4 name comes from the v3
language spec (§2.6), which pairs each with a v4 constant where one exists.
A row the spec maps to a combination or to "no equivalent" gets no v4 name.
"""

from __future__ import annotations

import re
from pathlib import Path

from mintlang.keyworddb.model import V3Constant
from tools.keyworddb.seeds import Seed

LANGUAGE_SPEC = "v3-language.md"
_ROW = re.compile(r"^<code>(?P<name>_\w+)</code>\s+(?P<value>-?\d+)")
_CONFIG_ROW = re.compile(r"^(?P<value>\d+)\s+<code>(?P<name>_\w+)</code>")
_BACKTICKED = re.compile(r"`(_\w+)`")


def _v4_names(spec_dir: Path, v4_constants: set[str]) -> dict[str, str | None]:
    """v3 constant -> v4 constant from the spec's §2.6 table."""
    text = (spec_dir / LANGUAGE_SPEC).read_text(encoding="utf-8")
    section = text.split("### 2.6 Pre-defined constants", 1)[1].split("\n### ", 1)[0]
    names: dict[str, str | None] = {}
    for line in section.splitlines():
        cells = [cell.strip() for cell in re.split(r"(?<!\\)\|", line)[1:-1]]
        if len(cells) < 4 or not cells[0].startswith("`_"):
            continue
        olds = _BACKTICKED.findall(cells[0])
        news = [name for name in _BACKTICKED.findall(cells[3]) if name in v4_constants]
        combined = re.search(r"`\s*\\?[|+]\s*`", cells[3]) or cells[3].startswith(("—", "**no", "none"))
        for position, old in enumerate(olds):
            paired = news[position] if len(news) >= len(olds) else None
            names[old] = None if combined else paired
    return names


def build_v3_constants(seed: Seed, spec_dir: Path, v4_constants: set[str]) -> list[V3Constant]:
    """The constant table of §4.3.1 plus the CONFIG value table's ``_inverter``."""
    start = seed.find(r"^4\.3\.1 Pre-defined Constant Keywords\s*$")  # not the contents line
    end = seed.find(r"^4\.4 ", start)
    found = {
        match["name"]: V3Constant(match["name"], float(match["value"]), None, number)
        for number in range(start, end)
        if (match := _ROW.match(seed.stripped(number)))
    }
    for number in range(end, len(seed.lines) + 1):
        match = _CONFIG_ROW.match(seed.stripped(number))
        if match and match["name"] not in found:
            found[match["name"]] = V3Constant(match["name"], float(match["value"]), None, number)
    v4_names = _v4_names(spec_dir, v4_constants)
    return [
        V3Constant(c.name, c.value, v4_names.get(c.name), c.line) for c in sorted(found.values(), key=lambda c: c.name)
    ]
