"""The footnotes that widen a range for NextMove PCI with expansion cards.

An attributes row labelled "NextMove PCI10" points at footnote 10, which says
the range grows with one expansion card and again with two (000:9388-9389).
The checker accepts the largest configuration, as it does for I/O channels
(``mintlang.controllers``), so each such footnote's two-card maximum is kept.
"""

from __future__ import annotations

import re

from tools.keyworddb.seeds import Seed

_EXPANSION = re.compile(
    r"(?<!\d)(?P<number>\d+) ?If a NextMove PCI Expansion card is present, (?:then )?the range increases to \d+\. "
    r"With two Expansion cards, the range increases to (?P<maximum>\d+)\."
)


def expansion_maxima(seed: Seed) -> dict[int, float]:
    """Footnote number -> the range's maximum on NextMove PCI with two expansion cards."""
    text = re.sub(r"\s+", " ", " ".join(seed.lines))
    return {int(match["number"]): float(match["maximum"]) for match in _EXPANSION.finditer(text)}
