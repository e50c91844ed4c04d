"""Resolve abbreviations the v4 guide gives to more than one keyword.

The choice is written to ``conflicts.json`` (``resolved_to``), so the loader
applies exactly what the data documents.
"""

from __future__ import annotations

from mintlang.keyworddb.model import Keyword
from tools.keyworddb.conflicts import Conflict, conflict


def _priority(keyword: Keyword, abbreviation: str, chapter10: dict[str, str | None]) -> tuple[bool, bool, int]:
    """Documented entries first, then a chapter 10 heading over a chapter 11 row, then page order."""
    return (not keyword.documented, chapter10.get(keyword.name) != abbreviation, keyword.line)


def shared_abbreviations(keywords: dict[str, Keyword], chapter10: dict[str, str | None]) -> list[Conflict]:
    """One conflict per abbreviation claimed by several keywords, naming the one it resolves to.

    ``chapter10`` maps a keyword to the abbreviation its chapter 10 heading prints.
    """
    owners: dict[str, list[Keyword]] = {}
    for keyword in keywords.values():
        for abbreviation in keyword.abbreviations:
            owners.setdefault(abbreviation, []).append(keyword)
    conflicts = []
    for abbreviation, claimants in sorted(owners.items()):
        if len(claimants) < 2:
            continue
        ranked = sorted(claimants, key=lambda k: _priority(k, abbreviation, chapter10))
        names = [k.name for k in ranked]
        detail = (
            f"{abbreviation} is given to {', '.join(names)}; it resolves to {names[0]} "
            "(documented entry first, then chapter 10 over chapter 11, then page order)"
        )
        lines = (k.line for k in ranked)
        conflicts.append(conflict("abbreviation", abbreviation, detail, lines, keywords=names, resolved_to=names[0]))
    return conflicts
