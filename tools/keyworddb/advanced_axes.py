"""Axis addressing for the Advanced-guide keywords the v4 guide shows belong to an axis.

An entry that defers to the Advanced guide ("This is an advanced Mint feature") prints no format and no dot
parameters, which is where the addressing is read from (``formats.addressing``), so such a keyword would be
addressed by nothing: ``SRAMP = 50;`` after ``AXES[1,2]`` would go to axis 0 alone and ``SRAMP.13`` would
name no axis. The guide shows each of these belongs to an axis elsewhere, and the runtime keeps one value per
axis for each.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from types import MappingProxyType

from mintlang.keyworddb.model import Addressing, Keyword

AXIS_ADDRESSED: Mapping[str, str] = MappingProxyType(
    {
        "ERRORINPUTMODE": "the action of an axis's external error input (000:4667-4671)",
        "FOLERRORMODE": "FOLERRORMODE[2] = 0 (000:7280)",
        "HOMEPOS": "the axis position before homing cleared it (000:3436-3438, 17640)",
        "IDLEPOS": "an axis variable DEFAULT[axes] resets (000:8983, 9036)",
        "IDLEVEL": "an axis variable DEFAULT[axes] resets (000:8983, 9037)",
        "KACCEL": "a term of an axis's servo loop beside KPROP (000:427-434)",
        "KINTMODE": "a term of an axis's servo loop beside KINTLIMIT (000:440-442)",
        "MOVEBUFFERFREE": "PRINT MOVEBUFFERFREE.5 (000:2982)",
        "MOVEBUFFERSIZE": "each axis has its own move buffer, of a size the user sets (000:2870-2871)",
        "SRAMP": "smooths the move profile of an axis, as ACCEL and DECEL shape it (000:2833-2838)",
    }
)
"""Keyword -> where the guide shows it belongs to an axis."""


def with_advanced_axes(keywords: Mapping[str, Keyword]) -> dict[str, Keyword]:
    """``keywords`` with the ``AXIS_ADDRESSED`` ones addressed by axis, as their formats would show."""
    return {
        name: replace(keyword, addressing=Addressing.AXIS) if name in AXIS_ADDRESSED else keyword
        for name, keyword in keywords.items()
    }
