"""``PRINT CHR(n)`` reaches ``mint-run``'s standard output as text in that output's encoding.

CHR sends a character the terminal shows (000:8129-8135); the runtime takes the code's low byte as the
Latin-1 character (BEHAVIOUR.md, NM-5 / PR-4). A terminal or pipe in UTF-8 gets its two bytes, one in
Latin-1 the controller's own byte, and one whose encoding lacks it a '?', never a traceback.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest


def printed(tmp_path: Path, text: str, encoding: str) -> subprocess.CompletedProcess[bytes]:
    program = tmp_path / "chr.mnt"
    program.write_text(text, encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "mintlang.runtime", "-q", "--no-config", str(program)],
        capture_output=True,
        timeout=120,
        check=False,
        env={**os.environ, "PYTHONIOENCODING": encoding},
    )


@pytest.mark.parametrize(
    ("encoding", "output"),
    [
        ("utf-8", b"\xc3\xa9\nA\n"),  # e acute, code 233, in UTF-8
        ("latin-1", b"\xe9\nA\n"),  # the one byte 233 the controller sends
        ("ascii", b"?\nA\n"),  # no e acute in ASCII: a '?', and the run goes on
    ],
)
def test_chr_233_is_written_in_the_encoding_of_standard_output(tmp_path: Path, encoding: str, output: bytes) -> None:
    result = printed(tmp_path, "PRINT CHR(233)\nPRINT CHR(65)\n", encoding)
    assert result.returncode == 0, result.stderr
    assert b"Traceback" not in result.stderr
    assert result.stdout == output


def test_a_code_cp1252_leaves_undefined_is_a_question_mark(tmp_path: Path) -> None:
    result = printed(tmp_path, "PRINT CHR(129)\n", "cp1252")  # 0x81: a hole in Windows' code page
    assert result.returncode == 0, result.stderr
    assert result.stdout.replace(b"\r", b"") == b"?\n"
