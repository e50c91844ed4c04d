"""A file saved with a UTF-8 byte order mark is reported as an editor shows it, and written back with its mark.

Windows editors (Notepad, older WorkBench exports) begin a UTF-8 file with the mark
EF BB BF, which no editor shows: the first character of line 1 is at column 1, where
an editor's cursor puts it and where the report must point.
"""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, records

MARK = b"\xef\xbb\xbf"


def test_a_finding_on_the_first_line_is_at_the_column_an_editor_shows(tmp_path: Path) -> None:
    path = tmp_path / "marked.mnt"
    path.write_bytes(MARK + b"PRINTT 1\n")
    (record,) = records(path)
    assert (record["line"], record["column"], record["end_column"]) == (1, 1, 7)


def test_the_text_report_underlines_the_word_itself(tmp_path: Path) -> None:
    path = tmp_path / "marked.mnt"
    path.write_bytes(MARK + b"PRINTT 1\n")
    lines = mint_check("--no-config", path).stdout.splitlines()
    shown = next(index for index, line in enumerate(lines) if line.endswith("| PRINTT 1"))
    assert lines[shown + 1].endswith("| ^^^^^^")


def test_fix_keeps_the_mark(tmp_path: Path) -> None:
    path = tmp_path / "marked.mnt"
    path.write_bytes(MARK + "PRINT “ready”\n".encode())
    mint_check("--fix", path)
    assert path.read_bytes() == MARK + b'PRINT "ready"\n'
