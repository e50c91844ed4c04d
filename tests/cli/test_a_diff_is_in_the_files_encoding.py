"""A diff written for ``patch`` is in the encoding of the file it changes.

Programs saved by old Windows tools are cp1252 (``mintlang/source.py`` reads them so and writes them
back byte for byte). ``patch`` matches bytes: the diff of such a program written in UTF-8 has
context lines that are not in the file, and does not apply. So ``mint check --diff`` and
``mint-migrate``'s dry run write a file's diff in its own encoding when the output is not a
terminal (the tests' output is not).
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main

DEGREES = b"REM caf\xe9 at 20 \xb0C\n"  # cp1252: not UTF-8


def test_mint_migrates_diff_of_a_cp1252_program_is_cp1252(tmp_path: Path) -> None:
    program = tmp_path / "old.mnt"
    program.write_bytes(DEGREES + b"AC = 100\n")
    result = CliRunner().invoke(main, ["migrate", str(program), "-q", "--exit-zero"])
    assert b"\n " + DEGREES + b"-AC = 100\n" in result.stdout_bytes


def test_mint_checks_diff_of_a_cp1252_program_is_cp1252(tmp_path: Path) -> None:
    program = tmp_path / "quotes.mnt"
    program.write_bytes(DEGREES + b"PRINT \x93hot\x94\n")  # cp1252's curly quotes, W101's safe fix
    result = CliRunner().invoke(main, ["check", "--diff", str(program)])
    assert b"\n " + DEGREES + b'-PRINT \x93hot\x94\n+PRINT "hot"\n' in result.stdout_bytes
