"""Join the v3 keywords with their v4 fate: the migration spec's §8 table, else the v4 data.

The spec (written from both guides) is where the migration classes are
defined, so its table is the authority for status and class; keywords it
does not list fall back to what the v4 guide itself says.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from mintlang.keyworddb.model import Keyword, MigrationClass, Rename, V3Keyword
from tools.keyworddb.renames import resolve_v4_name
from tools.keyworddb.v3_keywords import V3Entry

MIGRATION_SPEC = "migration-v3-to-v4.md"
_STATUS = {
    "same": "same",
    "same_changed": "changed",
    "renamed": "renamed",
    "replaced_other": "replaced",
    "not_available": "removed",
    "advanced": "changed",
    "can_guide": "changed",
}
"""Spec status -> ``V3Keyword.status``; "absent" depends on whether a replacement exists."""


@dataclass(frozen=True)
class SpecRow:
    replacement: str
    status: str
    migration: MigrationClass


def _cells(line: str) -> list[str]:
    return [cell.strip().replace("\\|", "|") for cell in re.split(r"(?<!\\)\|", line.strip())[1:-1]]


def _family(name: str) -> list[str]:
    """``IN0..7`` -> IN0 ... IN7; ``LOOP .. ENDL`` -> LOOP; ``#IN0..7`` -> #IN0 ... #IN7."""
    if match := re.fullmatch(r"(?P<prefix>#?[A-Z]+)(?P<first>\d+)\.\.(?P<last>\d+)", name):
        return [f"{match['prefix']}{n}" for n in range(int(match["first"]), int(match["last"]) + 1)]
    return [name.split(" .. ", maxsplit=1)[0]]


def spec_rows(spec_dir: Path) -> dict[str, SpecRow]:
    """v3 keyword -> its row of the keyword-by-keyword table (§8)."""
    text = (spec_dir / MIGRATION_SPEC).read_text(encoding="utf-8")
    section = text.split("## 8. Keyword-by-keyword table", 1)[1].split("\n### ", 1)[0]
    rows: dict[str, SpecRow] = {}
    for line in section.splitlines():
        cells = _cells(line) if line.startswith("| ") else []
        if len(cells) < 6 or cells[0] in {"v3 keyword", "---"} or set(cells[0]) == {"-"}:
            continue
        row = SpecRow(cells[2], cells[4], MigrationClass(cells[5]))
        for name in _family(cells[0]):
            rows.setdefault(name, row)
    return rows


def _v4_names(entry: V3Entry, row: SpecRow, keywords: dict[str, Keyword]) -> tuple[str, ...]:
    if row.replacement.startswith("same"):
        return (entry.name,) if entry.name in keywords else ()
    replacement = re.sub(r"\([^)]*\)", "", row.replacement)  # "(NOT STEPPERIO)" is commentary
    words = re.findall(r"(?<!\w)(#?[A-Z][A-Z0-9]+)[nx]?\b", replacement)  # "INn", "#INn" name families
    return tuple(dict.fromkeys(name for word in words if (name := resolve_v4_name(word, keywords))))


def _from_v4(
    entry: V3Entry, keywords: dict[str, Keyword], renames: dict[str, Rename]
) -> tuple[tuple[str, ...], str, MigrationClass]:
    """Fallback when the spec has no row: unchanged if v4 has the name, else the v4 rename entry."""
    if entry.name in keywords:
        return (entry.name,), "same", MigrationClass.NONE
    if (rename := renames.get(entry.name)) is not None:
        return rename.new, rename.status, MigrationClass.MANUAL if not rename.new else MigrationClass.SEMI
    return (), "removed", MigrationClass.MANUAL


def build_v3_keywords(
    entries: list[V3Entry], keywords: dict[str, Keyword], renames: list[Rename], spec_dir: Path
) -> list[V3Keyword]:
    rows = spec_rows(spec_dir)
    by_old = {rename.old: rename for rename in renames}
    records = []
    for entry in entries:
        if (row := rows.get(entry.name)) is not None:
            v4_names = _v4_names(entry, row, keywords)
            status = _STATUS.get(row.status) or ("replaced" if v4_names else "removed")
            migration = row.migration
        else:
            v4_names, status, migration = _from_v4(entry, keywords, by_old)
        records.append(
            V3Keyword(
                name=entry.name,
                abbreviations=(entry.abbreviation,) if entry.abbreviation else (),
                read=entry.read,
                write=entry.write,
                command=entry.command,
                addressing=entry.addressing,
                function=entry.function,
                v4_names=v4_names,
                status=status,
                migration=migration,
                line=entry.line,
                formats=entry.formats,
            )
        )
    return records
