"""The dry run's unified diff is one ``patch`` applies: CRLF lines keep their CR, a missing last line end is marked.

A DOS editor wrote the v3 files with CRLF, and some end without a line end at all. The diff printed every
line with a bare newline and no "No newline at end of file" mark, so ``patch`` refused each hunk of such a
file ("different line endings", or no match for the last line), where ``--write`` gave the right file.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate


def _diff(path: Path) -> str:
    result = CliRunner().invoke(migrate, ["--controller", "mintdrive", "-q", "--color", "never", str(path)])
    assert result.exit_code == 0, result.output
    return result.stdout_bytes.decode()  # the bytes: ``output`` turns CRLF into LF


def test_a_crlf_file_has_crlf_lines_in_its_diff(tmp_path: Path) -> None:
    program = tmp_path / "demo.mnt"
    program.write_bytes(b"REM demo\r\nHMSPEED = 10\r\nx = 1\r\n")
    output = _diff(program)
    assert " REM demo\r\n-HMSPEED = 10\r\n+DIM x\r\n+HOMESPEED = 10\r\n x = 1\r\n" in output


def test_a_last_line_without_a_line_end_is_marked(tmp_path: Path) -> None:
    program = tmp_path / "demo.mnt"
    program.write_bytes(b"x = 1\nHMSPEED = 10")
    output = _diff(program)
    marker = "\\ No newline at end of file\n"
    assert f"-HMSPEED = 10\n{marker}+HOMESPEED = 10\n{marker}" in output
