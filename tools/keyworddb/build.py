"""Run every extractor over the manuals and gather the JSON documents to write."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from mintlang.keyworddb.model import Constant, ErrorCode, Keyword
from tools.keyworddb.abbreviations import shared_abbreviations
from tools.keyworddb.access import apply_access_examples, apply_format_access
from tools.keyworddb.advanced_axes import with_advanced_axes
from tools.keyworddb.bit_ranges import with_bit_ranges
from tools.keyworddb.conflicts import Conflict, sort_key
from tools.keyworddb.constant_ranges import with_constant_ranges
from tools.keyworddb.constants import add_constant, error_constants, general_constants, keyword_constants
from tools.keyworddb.default_ranges import with_default_ranges
from tools.keyworddb.described_ranges import with_described_ranges
from tools.keyworddb.entries import EntryKind, v4_entries
from tools.keyworddb.errors import build_errors, shared_constants
from tools.keyworddb.migration import build_v3_keywords
from tools.keyworddb.renames import build_renames
from tools.keyworddb.seeds import V3_GUIDE, V4_GUIDE, Seed, read_seed
from tools.keyworddb.servonode import with_servonode_rows
from tools.keyworddb.summaries import with_summaries
from tools.keyworddb.v3_constants import build_v3_constants
from tools.keyworddb.v3_keywords import v3_entries
from tools.keyworddb.v4_keywords import build_keywords, canonical_name, chapter10_abbreviations


def _constants(
    seed: Seed, keywords: dict[str, Keyword], errors: dict[int, ErrorCode]
) -> tuple[dict[str, Constant], list[Conflict], dict[str, Keyword]]:
    """All v4 constants (entry tables first, then general and error ones) and keywords listing theirs."""
    entries = [e for e in v4_entries(seed) if e.kind is EntryKind.FULL]
    keyword_of = {e.line: canonical_name(e) for e in entries}
    constants, conflicts, owned = keyword_constants(entries, keyword_of, seed)
    for extra in (general_constants(seed), error_constants(errors.values())):
        for constant in extra.values():
            conflicts += add_constant(constants, constant)
    with_constants = {
        name: replace(keyword, constants=tuple(owned.get(name, ()))) for name, keyword in keywords.items()
    }
    return constants, conflicts, with_constants


def _with_notes(keywords: dict[str, Keyword], conflicts: list[Conflict]) -> dict[str, Keyword]:
    """Each keyword's notes gain the detail of every conflict that names it."""
    details: dict[str, list[str]] = {}
    for record in sorted(conflicts, key=sort_key):
        for name in record.get("keywords", ()):
            details.setdefault(name, []).append(record["detail"])
    return {
        name: replace(keyword, notes=tuple(dict.fromkeys((*keyword.notes, *details.get(name, ())))))
        for name, keyword in keywords.items()
    }


def build(seeds: Path, spec: Path) -> dict[str, Any]:
    """File name -> JSON document, for every file in ``mintlang/keyworddb/data``."""
    v4 = read_seed(seeds / V4_GUIDE)
    v3 = read_seed(seeds / V3_GUIDE)
    keywords, conflicts = build_keywords(v4)
    keywords = with_advanced_axes(keywords)
    conflicts += shared_abbreviations(keywords, chapter10_abbreviations(v4))
    errors = build_errors(v4)
    constants, constant_conflicts, keywords = _constants(v4, keywords, errors)
    keywords = with_constant_ranges(keywords, constants, v4)
    keywords = with_described_ranges(keywords, constants, v4)
    keywords, bit_conflicts = with_bit_ranges(keywords, constants, v4)
    keywords, default_conflicts = with_default_ranges(keywords)
    keywords, format_conflicts = apply_format_access(keywords)
    keywords, access_conflicts = apply_access_examples(v4, errors, keywords)
    keywords = with_servonode_rows(keywords)
    conflicts += (
        constant_conflicts
        + bit_conflicts
        + default_conflicts
        + shared_constants(errors)
        + format_conflicts
        + access_conflicts
    )
    keywords = with_summaries(_with_notes(keywords, conflicts))
    renames = build_renames(v4, keywords)
    return {
        "keywords_v4.json": sorted(keywords.values(), key=lambda k: k.name),
        "constants_v4.json": sorted(constants.values(), key=lambda c: c.name),
        "errors.json": sorted(errors.values(), key=lambda e: e.code),
        "conflicts.json": sorted(conflicts, key=sort_key),
        "keywords_v3.json": sorted(
            build_v3_keywords(v3_entries(v3), keywords, renames, spec), key=lambda k: (k.name, k.line)
        ),
        "constants_v3.json": build_v3_constants(v3, spec, set(constants)),
        "renames_v3_to_v4.json": sorted(renames, key=lambda r: r.line),
    }
