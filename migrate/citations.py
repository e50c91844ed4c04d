"""Citing the manuals by section, as a reader of the printed guides can look them up.

The rules cite lines of the manuals' text extractions (``v4:3046``), which only
this project has. What a person is shown names the section instead,
``v4 guide §6.7``, and inside a keyword chapter the keyword's entry as well,
``v4 guide §10.3 ACCEL`` (``mintlang.manual`` knows the sections); a line before
the first heading is cited as the guide alone.
"""

from __future__ import annotations

import re

from mintlang.manual.places import section

_LINES = r"\d+(?:-\d+)?"
_RUN = re.compile(rf"\bv[34]:{_LINES}(?:, (?:v[34]:)?{_LINES})*")  # "v3:5662, 5728, v4:6178-6180"


def cite(text: str) -> str:
    """``text`` with every ``v3:LINE`` and ``v4:LINE`` (a range cites its first line; a bare
    number after one is the same guide's) as the guide and section; a run of them names each
    guide once and each place once."""
    return _RUN.sub(lambda run: _run(run.group()), text)


def in_file(text: str) -> str:
    """``text`` as a migrated file holds it: ASCII, so an ASCII or cp1252 listing keeps its encoding
    and the controller's tools show it as written (``section 6.7`` for ``§6.7``)."""
    return text.replace("§", "section ")


def _run(run: str) -> str:
    places: list[tuple[str, str]] = []
    dialect = ""
    for reference in run.split(", "):
        dialect, _, line = reference.rpartition(":") if ":" in reference else (dialect, ":", reference)
        place = (dialect, section(dialect, int(line.split("-")[0])))
        if place not in places:
            places.append(place)
    cited = []
    for number, (dialect, where) in enumerate(places):
        same_guide = number > 0 and places[number - 1][0] == dialect
        cited.append(where if same_guide and where else f"{dialect} guide {where}".rstrip())
    return ", ".join(cited)
