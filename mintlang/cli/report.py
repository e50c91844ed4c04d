"""Rendering diagnostics: code frames for people, JSON, SARIF and GitHub annotations for tools."""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterator, Sequence
from pathlib import PurePath
from typing import IO, TYPE_CHECKING
from urllib.parse import quote

from mintlang import keyworddb
from mintlang.cli.terminal import Palette
from mintlang.codes import OWN_CODES
from mintlang.diagnostics import Diagnostic, Fix, LineIndex, Severity, Span
from mintlang.records import record

if TYPE_CHECKING:
    from rich.console import Console

# rich (for text), the rule documentation and the distribution's metadata (for SARIF) are imported
# where they are used: a check that writes JSON, or finds nothing to write, never pays for them.


@record
class FileReport:
    """The diagnostics of one file, with what is needed to show where they are."""

    path: str
    source: str
    diagnostics: tuple[Diagnostic, ...]
    left_out: tuple[tuple[tuple[str, str], str], ...] = ()  # findings whose fix --fix sets aside, and why (fixes)

    def located(self, index: LineIndex | None = None) -> Iterator[tuple[Diagnostic, int, int, int, int]]:
        """Each diagnostic with 1-based start line/column and end line/column (end exclusive), made as
        they are written: a list of them all was the largest part of a report's memory."""
        index = index or LineIndex(self.source)
        for diagnostic in self.diagnostics:
            start = index.position(diagnostic.span.start)
            end = index.position(diagnostic.span.end)
            yield diagnostic, start.line, start.column, end.line, end.column


_STYLE = {Severity.ERROR: "bold red", Severity.WARNING: "bold yellow", Severity.INFO: "bold cyan"}
_FIX_KIND = {True: "fix", False: "unsafe fix"}  # as ``--fix`` takes it: unasked, or with ``--unsafe-fixes``
_CONTEXT = 60  # characters shown either side of the marked text on a long line (and twice that marked)
# Control characters of the source are shown as their pictures (one cell each), never sent to the terminal.
_VISIBLE = {code: chr(0x2400 + code) for code in range(0x20)} | {0x7F: "\u2421", ord("\t"): " "}
_CONTROL = re.compile("[\x00-\x1f\x7f]")


def _visible(text: str) -> str:
    """``text`` with its control characters as pictures (a search first: most text has none to translate)."""
    return text.translate(_VISIBLE) if _CONTROL.search(text) else text


def _cells(text: str) -> int:
    if text.isascii():
        return len(text)
    from rich.cells import cell_len  # noqa: PLC0415 - see the imports

    return cell_len(text)


def _frame(text: str, start: int, end: int) -> tuple[str, int, int]:
    """The part of a source line to show, and the cells before and under the marked characters.

    Columns are characters; the terminal counts cells (CJK and emoji take two), so
    the caret is placed by cell width. A long line is cut to the marked text and
    some context either side.
    """
    end = min(end, start + 2 * _CONTEXT)  # a long marked stretch is cut too
    first, last = max(0, start - _CONTEXT), min(len(text), end + _CONTEXT)
    head, tail = ("…" if first > 0 else ""), ("…" if last < len(text) else "")
    visible = _visible(text[first:last])
    before = head + visible[: start - first]
    return head + visible + tail, _cells(before), _cells(visible[start - first : end - first])


def shortened(text: str) -> str:
    """``text`` (source, all of it meant) as a code frame shows it: a long one cut, control characters as pictures.

    For messages that quote a statement without a column, such as ``mint-run``'s stop line.
    """
    return _frame(text, 0, len(text))[0]


_FRAMES_WRITTEN_AT_ONCE = 4096  # few writes, and not the whole report of a file of broken lines in memory at once


def render_text(
    reports: Sequence[FileReport], stream: IO[str], console: Console | None = None, *, summary: bool = True
) -> None:
    """rustc/ruff-style code frames and, with ``summary``, a closing count, written to ``stream``; in
    colour where ``console`` (one for ``stream``) shows it.

    Written straight to the stream with the escape codes of the console's palette:
    ``Console.print`` parses and measures every line, a hundred times the cost.
    The source, messages and paths are shown as they are (never read as markup),
    with their control characters as pictures.
    """
    palette = Palette.for_console(console, {*_STYLE.values(), "blue", "bold"}) if console is not None else Palette({})
    counts = dict.fromkeys(Severity, 0)
    bar, arrow, equals = (palette.paint("blue", mark) for mark in ("|", "-->", "="))
    for report in reports:
        index = LineIndex(report.source)
        path = _visible(report.path)
        frames: list[str] = []
        for diagnostic, line, column, end_line, end_column in report.located(index):
            counts[diagnostic.severity] += 1
            style = _STYLE[diagnostic.severity]
            text = index.line_text(line)
            gutter = " " * len(str(line))
            end = end_column if end_line == line else len(text) + 1
            shown, before, marked = _frame(text, column - 1, max(column, end) - 1)
            heading = palette.paint(style, f"{diagnostic.severity.value}[{diagnostic.code}]")
            frames.append(
                f"{heading}: {_visible(diagnostic.message)}\n"
                f"  {arrow} {path}:{line}:{column}\n"
                f"  {gutter} {bar}\n"
                f"  {palette.paint('blue', f'{line} |')} {shown}\n"
                f"  {gutter} {bar} {' ' * before}{palette.paint(style, '^' * max(1, marked))}\n"
            )
            frames.extend(
                f"  {gutter} {equals} {_FIX_KIND[fix.safe]}: {_visible(fix.title)}\n" for fix in diagnostic.fixes
            )
            frames.append("\n")
            if len(frames) >= _FRAMES_WRITTEN_AT_ONCE:
                stream.write("".join(frames))
                frames.clear()
        stream.write("".join(frames))
    if summary:
        stream.write(_checked(len(reports), counts, palette))
    stream.flush()


def render_concise(
    reports: Sequence[FileReport], stream: IO[str], console: Console | None = None, *, summary: bool = True
) -> None:
    """One line a finding, ``path:line:column: CODE message`` (ruff's concise format, what an editor's
    quickfix list and a compiler-output parser read), and with ``summary`` the closing count."""
    palette = Palette.for_console(console, {*_STYLE.values(), "bold"}) if console is not None else Palette({})
    counts = dict.fromkeys(Severity, 0)
    for report in reports:
        path = _visible(report.path)
        lines = []
        for diagnostic, line, column, _, _ in report.located():
            counts[diagnostic.severity] += 1
            code = palette.paint(_STYLE[diagnostic.severity], diagnostic.code)
            lines.append(f"{path}:{line}:{column}: {code} {_visible(diagnostic.message)}\n")
        stream.write("".join(lines))
    if summary:
        stream.write(_checked(len(reports), counts, palette))
    stream.flush()


def _checked(files: int, counts: dict[Severity, int], palette: Palette) -> str:
    """The closing line: how many files were checked, and the findings of each severity."""
    total = ", ".join(f"{counts[s]} {s.value}{'s' if counts[s] != 1 else ''}" for s in Severity)
    noun = "file" if files == 1 else "files"
    return f"{palette.paint('bold', f'{files} {noun} checked:')} {total}\n"


def _region(index: LineIndex, span: Span) -> tuple[int, int, int, int]:
    """1-based start line and column, end line and column (end exclusive) of ``span``."""
    start, end = index.position(span.start), index.position(span.end)
    return start.line, start.column, end.line, end.column


def _dumps(value: object) -> str:
    """``value`` as indented JSON; ``json`` is imported only here: a text report, most checks', needs none."""
    import json  # noqa: PLC0415

    return json.dumps(value, indent=2, ensure_ascii=False)


def _json_fix(fix: Fix, index: LineIndex) -> dict[str, object]:
    """A fix as JSON: each edit replaces the text between two positions with ``text``."""
    edits = [
        dict(zip(("line", "column", "end_line", "end_column"), _region(index, edit.span), strict=True))
        | {"text": edit.text}
        for edit in fix.edits
    ]
    return {"title": fix.title, "safe": fix.safe, "edits": edits}


def as_json(reports: Sequence[FileReport]) -> str:
    records = []
    for report in reports:
        index = LineIndex(report.source)
        records.extend(
            {
                "path": report.path,
                "code": diagnostic.code,
                "mint_error": diagnostic.mint_error,
                "severity": diagnostic.severity.value,
                "message": diagnostic.message,
                "line": line,
                "column": column,
                "end_line": end_line,
                "end_column": end_column,
                "fixes": [_json_fix(fix, index) for fix in diagnostic.fixes],
            }
            for diagnostic, line, column, end_line, end_column in report.located()
        )
    return _dumps(records)


def _title(code: str) -> str:
    if code.startswith("E"):
        record = keyworddb.database().errors.get(int(code[1:]))
        return record.title if record else code
    return OWN_CODES.get(code, code)


def _sarif_rule(code: str, base: str | None) -> dict[str, object]:
    """A SARIF rule: its title, and what it catches with a link to its page where it is documented."""
    from mintlang.ruledocs import find  # noqa: PLC0415 - see the imports
    from mintlang.ruledocs.links import rule_url  # noqa: PLC0415

    rule: dict[str, object] = {"id": code, "shortDescription": {"text": _title(code)}}
    documented = find(code)
    if documented is not None:
        rule["fullDescription"] = {"text": documented.catches}
        url = rule_url(code, base)
        if url is not None:
            rule["helpUri"] = url
    return rule


_SARIF_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def _sarif_region(index: LineIndex, span: Span) -> dict[str, int]:
    return dict(zip(("startLine", "startColumn", "endLine", "endColumn"), _region(index, span), strict=True))


def _sarif_fix(fix: Fix, index: LineIndex, uri: str) -> dict[str, object]:
    """A SARIF fix: the file's replacements; whether ``--fix`` applies it unasked is a property."""
    replacements = [
        {"deletedRegion": _sarif_region(index, edit.span), "insertedContent": {"text": edit.text}} for edit in fix.edits
    ]
    return {
        "description": {"text": fix.title},
        "artifactChanges": [{"artifactLocation": {"uri": uri}, "replacements": replacements}],
        "properties": {"safe": fix.safe},
    }


def as_sarif(reports: Sequence[FileReport]) -> str:
    """SARIF 2.1.0, the format code-scanning services read."""
    from importlib.metadata import version  # noqa: PLC0415 - see the imports

    from mintlang.ruledocs.links import configured_base  # noqa: PLC0415

    results = []
    codes: set[str] = set()
    for report in reports:
        index = LineIndex(report.source)
        uri = quote(PurePath(report.path).as_posix())  # a URI reference: "my cell.mnt" is my%20cell.mnt
        for diagnostic in report.diagnostics:
            codes.add(diagnostic.code)
            location = {"artifactLocation": {"uri": uri}, "region": _sarif_region(index, diagnostic.span)}
            result = {
                "ruleId": diagnostic.code,
                "level": _SARIF_LEVEL[diagnostic.severity],
                "message": {"text": diagnostic.message},
                "locations": [{"physicalLocation": location}],
            }
            if diagnostic.fixes:
                result["fixes"] = [_sarif_fix(fix, index, uri) for fix in diagnostic.fixes]
            results.append(result)
    rules = [_sarif_rule(code, configured_base()) for code in sorted(codes)]
    document = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [
            {
                "tool": {"driver": {"name": "mint check", "version": version("mintlang"), "rules": rules}},
                "results": results,
            }
        ],
    }
    return _dumps(document)


_GITHUB_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def as_github(reports: Sequence[FileReport]) -> str:
    """GitHub Actions workflow commands: one annotation a line."""

    def escape_data(text: str) -> str:
        return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")

    def escape_property(text: str) -> str:
        return escape_data(text).replace(":", "%3A").replace(",", "%2C")

    lines = []
    for report in reports:
        for diagnostic, line, column, end_line, end_column in report.located():
            properties = (
                f"file={escape_property(report.path)},line={line},col={column},"
                f"endLine={end_line},endColumn={end_column},title={escape_property(diagnostic.code)}"
            )
            lines.append(f"::{_GITHUB_LEVEL[diagnostic.severity]} {properties}::{escape_data(diagnostic.message)}")
    return "\n".join(lines)


def as_statistics(reports: Sequence[FileReport], output_format: str) -> str:
    """How many findings of each code, most first (then by code): a table, or JSON records."""
    counts = Counter(diagnostic.code for report in reports for diagnostic in report.diagnostics)
    ranked = sorted(counts.items(), key=lambda item: (-item[1], item[0]))
    if output_format == "json":
        return _dumps([{"code": code, "count": count, "title": _title(code)} for code, count in ranked])
    width = len(str(ranked[0][1])) if ranked else 1
    return "\n".join(f"{count:>{width}}  {code:<6} {_title(code)}" for code, count in ranked)
