"""A diff of a file whose lines end with a lone CR keeps each CR, as ``ruff format --diff`` and ``difflib`` do.

Old Macintosh editors and some controller uploads end lines with a CR alone, which Mint reads as a line end
(the lexer's ``split_lines``). The diffs of ``mint check --diff``, ``mint format --diff`` and ``mint-migrate``
printed such lines with a newline in place of the CR, so the diff showed a file that is not the one changed:
a line the change ends with a newline among lines that end with a CR looked like the others. Each diff line
now ends as the line it shows does: ruff's diff (the ``similar`` crate) and ``difflib.unified_diff`` take a
lone CR for a line end and keep it. On a terminal a line break follows the CR, or the terminal would write the
next line over it.
"""

from __future__ import annotations

import io
from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from mintlang.cli.diffs import write_diff


def _diff(*arguments: str) -> bytes:
    return CliRunner().invoke(main, [*arguments, "-q"]).stdout_bytes


def test_mint_check_s_diff_keeps_the_lone_crs(tmp_path: Path) -> None:
    program = tmp_path / "quotes.mnt"
    program.write_bytes("DIM a\rPRINT \u201cx\u201d\rPRINT a\r".encode())  # W101's safe fix: plain quotes
    expected = ' DIM a\r-PRINT \u201cx\u201d\r+PRINT "x"\r PRINT a\r'
    assert _diff("check", "--diff", str(program)).endswith(expected.encode())


def test_mint_format_s_diff_keeps_the_lone_crs(tmp_path: Path) -> None:
    program = tmp_path / "lower.mnt"
    program.write_bytes(b"dim a\rprint a\r")
    assert _diff("format", "--diff", str(program)).endswith(b"-dim a\r-print a\r+DIM a\r+PRINT a\r")


def test_mint_migrate_s_diff_keeps_the_lone_crs(tmp_path: Path) -> None:
    program = tmp_path / "demo.mnt"
    program.write_bytes(b"REM demo\rHMSPEED = 10\rx = 1\r")
    output = _diff("migrate", "--controller", "mintdrive", "--color", "never", str(program))
    assert b" REM demo\r-HMSPEED = 10\r+DIM x\r+HOMESPEED = 10\r x = 1\r" in output


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_on_a_terminal_a_line_break_follows_each_lone_cr() -> None:
    terminal = _Terminal()
    write_diff(terminal, "--- a\n+++ a\n@@ -1 +1 @@\n-dim a\r+DIM a\r", "utf-8")
    assert terminal.getvalue() == "--- a\n+++ a\n@@ -1 +1 @@\n-dim a\r\n+DIM a\r\n"
