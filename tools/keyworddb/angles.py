"""Keywords whose table ticks "Scaled" but whose entry gives the value in degrees.

The scale factor turns user units into counts (SCALE); an angle in degrees is no
position, and CONTOURANGLE's entry says its value lies between 0 and 180 degrees
(000:8524-8533) while its table ticks Scaled. The stated range is a fact of the
manual the table's tick cannot override, so such a keyword is read as unscaled
and its range is checked as printed; each case is recorded as a conflict.
"""

from __future__ import annotations

import re
from dataclasses import replace

from mintlang.keyworddb.model import Attributes
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.entries import Entry

_IN_DEGREES = re.compile(r"\bspecified in degrees\b")


def unscaled_angles(
    name: str, entry: Entry, rows: tuple[Attributes, ...]
) -> tuple[tuple[Attributes, ...], list[Conflict]]:
    """``rows`` unscaled when the entry gives the value in degrees, with the conflict this settles."""
    if not any(row.scaled for row in rows) or not _IN_DEGREES.search(" ".join(entry.text("description"))):
        return rows, []
    detail = (
        f"{name}: its attributes table (entry line {entry.line}) ticks Scaled, its description gives the value "
        "in degrees; the description is followed and the range is checked unscaled"
    )
    return tuple(replace(row, scaled=False) for row in rows), [
        conflict("scaled", name, detail, (entry.line,), keywords=[name])
    ]
