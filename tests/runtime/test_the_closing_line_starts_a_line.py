"""``mint-run``'s closing line starts on a line of its own where it shares a screen or log with the program's output.

A program whose last ``PRINT`` ends with ``,`` leaves the cursor after its text (000:15300-15313); the
closing line, on standard error, would follow on the same line (``abcend after 0 ms``) where both streams reach
one terminal, file or pipe. The program's own output is never changed: alone in its pipe it ends where it ended.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

_PROGRAM = 'PRINT "abc",\n'


def _run(tmp_path: Path, *, shared: bool) -> subprocess.CompletedProcess[str]:
    program = tmp_path / "open_line.mnt"
    program.write_text(_PROGRAM, encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "mintlang.runtime", "--no-config", "--color", "never", str(program)],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT if shared else subprocess.PIPE,
        text=True,
        timeout=120,
        check=False,
    )


def test_the_closing_line_goes_under_a_line_left_open(tmp_path: Path) -> None:
    result = _run(tmp_path, shared=True)
    assert result.stdout.startswith("abc\nend after 0 ms at program line 1: ")


def test_the_programs_output_alone_is_as_printed(tmp_path: Path) -> None:
    result = _run(tmp_path, shared=False)
    assert result.stdout == "abc"
    assert result.stderr.startswith("end after 0 ms at program line 1: ")
