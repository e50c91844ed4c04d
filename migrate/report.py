"""The migration report: per-file status and counts, every change and manual item with its
line in the original and in the migrated file, per-rule counts.

One data shape (``report``) feeds both formats, so the JSON the golden tests
compare and the text a user reads always agree. Paths, reasons and errors quote
the user's files, so the text report escapes them: ``[/b]`` in a program is text,
not Rich markup.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from typing import Any

from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from mintlang.migrate.expected import DIFFERS
from mintlang.migrate.model import Change, ManualItem, MigrationFailed, MigrationResult
from mintlang.records import record


@record
class FileEntry:
    """A file of the run as the report names it: its migration, or why it has none."""

    path: str
    role: str  # "program" or "configuration"; "folder" for one that could not be listed
    result: MigrationResult | None
    failure: MigrationFailed | None = None
    written: bool = True  # False when ``--write`` could not replace the changed file

    @property
    def status(self) -> str:
        if self.result is None:
            return "failed"
        if self.result.already_v4:
            return "already v4"
        if self.result.already_mintmt:
            return "already mintmt"
        if not self.result.changed:
            return "unchanged"
        return "changed" if self.written else "not written"

    @property
    def problem(self) -> str | None:
        """The line saying why the file was not migrated, at ``path:line:column`` when the failure has a place."""
        if self.failure is None:
            return None
        position = self.failure.position
        place = self.path if position is None else f"{self.path}:{position.line}:{position.column}"
        return f"{place}: {self.failure}; left as it was"


def entries(path: str, result: MigrationResult, config_path: str | None = None) -> list[FileEntry]:
    """The report entries of one migration: the configuration file (if any) first."""
    found = []
    if result.configuration is not None and config_path is not None:
        found.append(FileEntry(config_path, "configuration", result.configuration))
    if path:
        found.append(FileEntry(path, "program", result))
    return found


def plural(count: int, noun: str) -> str:
    """``1 change``, ``2 changes``."""
    return f"{count} {noun}{'' if count == 1 else 's'}"


def report(files: Iterable[FileEntry], controller: str, *, to: str = "v4") -> dict[str, Any]:
    """The report as plain data (what ``--format json`` prints); a migration ``to`` MintMT says so
    (``"to": "mintmt"``) and counts the files left as they were for being MintMT already (as any run
    that left one does)."""
    rows = [_file(entry) for entry in files]
    rules: Counter[str] = Counter()
    for row in rows:
        rules.update(row["rules"])
    statuses = Counter(row["status"] for row in rows)
    target = {"to": to} if to != "v4" else {}
    already = {"already_mintmt": statuses["already mintmt"]} if to != "v4" or statuses["already mintmt"] else {}
    return {
        **target,
        "controller": controller,
        "files": rows,
        "totals": {
            "changed": statuses["changed"],
            "unchanged": statuses["unchanged"],
            "already_v4": statuses["already v4"],
            **already,
            "failed": statuses["failed"],
            "not_written": statuses["not written"],
            "changes": sum(len(row["changes"]) for row in rows),
            "manual_items": sum(len(row["manual"]) for row in rows),
            "errors": sum(len(row["errors"]) for row in rows),
        },
        "rules": dict(sorted(rules.items())),
    }


def _file(entry: FileEntry) -> dict[str, Any]:
    result = entry.result
    row: dict[str, Any] = {"path": entry.path, "role": entry.role, "status": entry.status}
    if result is None:
        failure = entry.failure
        row["failure"] = _failure(failure) if failure is not None else None
        return {**row, "changed": False, "changes": [], "manual": [], "errors": [], "rules": {}}
    return {
        **row,
        "changed": result.changed,
        "changes": [_change(change) for change in result.changes],
        "manual": [_manual(item) for item in result.manual],
        "errors": sorted(result.errors, key=_line),
        "rules": dict(result.rule_counts),
    }


def _change(change: Change) -> dict[str, Any]:
    """A change; one whose rule keeps v3's formula but not its exact values says what differs."""
    differs = DIFFERS.get(change.rule)
    return {
        "rule": change.rule,
        "original_line": change.line,
        "migrated_line": change.migrated_line,
        "original": change.original,
        "replacement": change.replacement,
        **({"differs": differs} if differs is not None else {}),
    }


def _failure(failure: MigrationFailed) -> dict[str, Any]:
    """The rule that failed and why; where in the file, for a file that is not Mint text."""
    where = {} if failure.position is None else {"line": failure.position.line, "column": failure.position.column}
    return {"rule": failure.rule, "reason": failure.reason, **where}


def _line(error: str) -> int:
    """The line of an error of the original's reader, written by ``model.unreadable``."""
    return int(error.removeprefix("line ").partition(":")[0])


def _unreadable_lines(errors: Iterable[str]) -> int:
    """How many lines the v3 reader could not read: a line with two errors is one line."""
    return len({_line(error) for error in errors})


def _manual(item: ManualItem) -> dict[str, Any]:
    return {
        "rule": item.rule,
        "original_line": item.original_line,
        "migrated_line": item.line,
        "note": item.note,
        "reason": item.reason,
    }


def render_text(data: Mapping[str, Any], console: Console, *, quiet: bool = False, verbose: bool = False) -> None:
    """The report for a person: one table of files, the manual items, the lines whose values differ, the rule
    counts, the totals.

    ``quiet`` leaves out all but the manual items and the unreadable lines; ``verbose`` adds every change.
    """
    reader = "v4" if "to" in data else "v3"  # the dialect of the files migrated: to MintMT, Mint v4
    if not quiet:
        _files_table(data, console)
    for row in data["files"]:
        path = escape(row["path"])
        for item in row["manual"]:
            console.print(f"{_place(path, item)}: [bold]{item['rule']}[/bold] {escape(item['reason'])}")
        for error in row["errors"]:
            console.print(f"{path}: unreadable {reader} {escape(error)}")
        for line in () if quiet else _differing(path, row["changes"]):
            console.print(line)
        for change in row["changes"] if verbose else ():
            place = f"{path}:{change['migrated_line']} (original line {change['original_line']})"
            console.print(f"{place}: [bold]{change['rule']}[/bold]")
    if quiet:
        return
    if data["rules"]:
        console.print("rules: " + ", ".join(f"{rule} {count}" for rule, count in data["rules"].items()))
    console.print(summary(data["totals"], sum(_unreadable_lines(row["errors"]) for row in data["files"])))


def _differing(path: str, changes: Iterable[Mapping[str, Any]]) -> list[str]:
    """One line per rule whose changes keep v3's formula but not its values: the lines, and what differs."""
    lines: dict[str, dict[int, int]] = {}  # rule -> migrated line -> original line
    for change in changes:
        if "differs" in change:
            lines.setdefault(change["rule"], {})[change["migrated_line"]] = change["original_line"]
    told = []
    for rule, places in lines.items():
        where = ", ".join(f"{migrated} (original {original})" for migrated, original in sorted(places.items()))
        told.append(f"{path}: [bold]{rule}[/bold] on lines {where}: {escape(DIFFERS[rule])}")
    return told


def _files_table(data: Mapping[str, Any], console: Console) -> None:
    target = f"to {data['to']}" if "to" in data else data["controller"]
    files = Table(title=f"mint-migrate ({target})", show_edge=False)
    # a path cut short with an ellipsis names no file in a CI log: the path takes what the counts leave, folded
    files.add_column("file", overflow="fold", ratio=1)
    for column in ("role", "status", "changes", "manual", "unreadable"):  # counts: items, lines (the summary's)
        files.add_column(column, no_wrap=True)
    for row in data["files"]:
        counts = (len(row["changes"]), len(row["manual"]), _unreadable_lines(row["errors"]))
        files.add_row(Text(row["path"]), row["role"], row["status"], *(str(count) for count in counts))
    console.print(files)


def _place(path: str, item: Mapping[str, Any]) -> str:
    """``path:line`` in the migrated file, and where the line came from."""
    if item["note"]:
        where = "note for the application"
    elif item["original_line"] is None:
        where = "a line mint-migrate wrote"
    else:
        where = f"original line {item['original_line']}"
    return f"{path}:{item['migrated_line']} ({where})"


def summary(totals: Mapping[str, int], unreadable_lines: int) -> str:
    """``2 files: 1 changed, 1 unchanged; 3 changes, 1 manual item, 0 unreadable lines`` (the totals
    count the errors of the v3 reader, two on one line among them)."""
    others = ("already_v4", "already_mintmt", "failed", "not_written")
    files = sum(totals.get(status, 0) for status in ("changed", "unchanged", *others))
    statuses = [f"{totals['changed']} changed", f"{totals['unchanged']} unchanged"]
    statuses += [f"{totals[key]} {key.replace('_', ' ')}" for key in others if totals.get(key)]
    counts = [
        plural(totals["changes"], "change"),
        plural(totals["manual_items"], "manual item"),
        plural(unreadable_lines, "unreadable line"),
    ]
    return f"{plural(files, 'file')}: {', '.join(statuses)}; {', '.join(counts)}"
