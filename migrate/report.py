"""The migration report: per-file counts, per-rule counts and every manual item with its line.

One data shape (``report``) feeds both formats, so the JSON the golden tests
compare and the text a user reads always agree. Paths, reasons and errors quote
the user's files, so the text report escapes them: ``[/b]`` in a program is text,
not Rich markup.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from mintlang.migrate.model import MigrationResult


@dataclass(frozen=True, slots=True)
class FileEntry:
    """A migrated file as the report names it."""

    path: str
    role: str  # "program" or "configuration"
    result: MigrationResult


def entries(path: str, result: MigrationResult, config_path: str | None = None) -> list[FileEntry]:
    """The report entries of one migration: the configuration file (if any) first."""
    found = []
    if result.configuration is not None and config_path is not None:
        found.append(FileEntry(config_path, "configuration", result.configuration))
    if path:
        found.append(FileEntry(path, "program", result))
    return found


def report(files: Iterable[FileEntry], controller: str) -> dict[str, Any]:
    """The report as plain data (what ``--format json`` prints)."""
    rows = [_file(entry) for entry in files]
    rules: Counter[str] = Counter()
    for row in rows:
        rules.update(row["rules"])
    return {
        "controller": controller,
        "files": rows,
        "totals": {
            "changed": sum(row["changed"] for row in rows),
            "unchanged": sum(not row["changed"] for row in rows),
            "manual_items": sum(len(row["manual"]) for row in rows),
            "errors": sum(len(row["errors"]) for row in rows),
        },
        "rules": dict(sorted(rules.items())),
    }


def _file(entry: FileEntry) -> dict[str, Any]:
    result = entry.result
    return {
        "path": entry.path,
        "role": entry.role,
        "changed": result.changed,
        "changes": [
            {"rule": c.rule, "line": c.line, "original": c.original, "replacement": c.replacement}
            for c in result.changes
        ],
        "manual": [{"rule": m.rule, "line": m.line, "reason": m.reason} for m in result.manual],
        "errors": list(result.errors),
        "rules": dict(result.rule_counts),
    }


def render_text(data: Mapping[str, Any], console: Console) -> None:
    """The report for a person: one table of files, the manual items, the rule counts."""
    files = Table(title=f"mint-migrate ({data['controller']})", show_edge=False)
    for column in ("file", "role", "status", "changes", "manual items", "errors"):
        files.add_column(column)
    for row in data["files"]:
        status = "changed" if row["changed"] else "unchanged"
        files.add_row(
            Text(row["path"]),
            row["role"],
            status,
            str(len(row["changes"])),
            str(len(row["manual"])),
            str(len(row["errors"])),
        )
    console.print(files)
    for row in data["files"]:
        path = escape(row["path"])
        for item in row["manual"]:
            console.print(
                f"{path}:{item['line']}: [bold]{item['rule']}[/bold] {escape(item['reason'])}", highlight=False
            )
        for error in row["errors"]:
            console.print(f"{path}: unreadable v3 {escape(error)}", highlight=False)
    if data["rules"]:
        console.print(
            "rules: " + ", ".join(f"{rule} {count}" for rule, count in data["rules"].items()), highlight=False
        )
    totals = data["totals"]
    console.print(
        f"{totals['changed']} changed, {totals['unchanged']} unchanged, "
        f"{totals['manual_items']} manual items, {totals['errors']} errors",
        highlight=False,
    )
