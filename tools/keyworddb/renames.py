"""The old keywords the v4 guide keeps as "replaced by ..." / "not available" entries."""

from __future__ import annotations

import re

from mintlang.keyworddb.model import Keyword, Rename
from tools.keyworddb.entries import EntryKind, v4_entries
from tools.keyworddb.seeds import Seed
from tools.keyworddb.v4_keywords import canonical_name

_REPLACED_BY = re.compile(r"replaced by\s+(?P<new>.+?)\s+in Mint v4")


def resolve_v4_name(word: str, keywords: dict[str, Keyword]) -> str | None:
    """A v4 keyword name as printed (``#FASTINx``, ``IN0``) -> its canonical entry, if any."""
    for candidate in (word, word.removesuffix("x"), re.sub(r"\d+$", "", word)):
        if candidate in keywords:
            return candidate
    return None


def build_renames(seed: Seed, keywords: dict[str, Keyword]) -> list[Rename]:
    """One record per retired name (77 in the guide), in page order."""
    renames = []
    for entry in v4_entries(seed):
        if entry.kind not in {EntryKind.REPLACED, EntryKind.REMOVED}:
            continue
        match = _REPLACED_BY.search(" ".join(entry.text("body")))
        printed = re.split(r"\s*(?:,|/|\band\b)\s*", match["new"]) if match else []
        new = tuple(name for word in printed if word and (name := resolve_v4_name(word, keywords)))
        renames.append(
            Rename(
                old=canonical_name(entry),
                old_abbreviation=entry.abbreviation,
                new=new,
                status="replaced" if entry.kind is EntryKind.REPLACED else "removed",
                line=entry.line,
            )
        )
    return renames
