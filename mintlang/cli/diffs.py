"""The unified diff ``mint check --diff`` and ``mint-migrate`` print, one that ``patch`` applies."""

from __future__ import annotations

from mintlang.diagnostics import split_lines


def unified(before: str, after: str, fromfile: str, tofile: str) -> str:
    """``diff -u`` of two texts, as ``patch`` applies it: a line keeps its CRLF, and a last line without a
    line end is marked so. Lines end only where Mint's do (``split_lines``). A lone CR, which ``patch``
    does not take for a line end, is shown as a newline, so that the lines of such a file stay readable."""
    import difflib  # noqa: PLC0415 - imported for a diff alone

    lines = difflib.unified_diff(
        split_lines(before, keepends=True), split_lines(after, keepends=True), fromfile=fromfile, tofile=tofile
    )
    return "".join(_ended(line) for line in lines)


def _ended(line: str) -> str:
    if line.endswith("\n"):
        return line
    if line.endswith("\r"):
        return f"{line[:-1]}\n"
    return f"{line}\n\\ No newline at end of file\n"
