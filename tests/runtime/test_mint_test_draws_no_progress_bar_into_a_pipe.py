"""``mint test`` draws its progress bar on a terminal only, as ``mint check`` does, whatever the colour.

``--color always`` (or ``FORCE_COLOR``, as CI logs set it) asks for colour, not for a terminal: standard
error into a pipe or a log file gets the tool's messages, never a bar redrawn with cursor codes.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest


@pytest.mark.parametrize(
    ("arguments", "environment"),
    [
        pytest.param(("--color", "always"), {}, id="color-always"),
        pytest.param((), {"FORCE_COLOR": "1"}, id="FORCE_COLOR"),
    ],
)
def test_standard_error_into_a_pipe_gets_no_progress_bar(
    tmp_path: Path, arguments: tuple[str, ...], environment: dict[str, str]
) -> None:
    (tmp_path / "passes.mnt").write_text("REM @expect a = 2\nDIM a = 2\n", encoding="utf-8")
    result = subprocess.run(
        [sys.executable, "-m", "mintlang", "test", "-j", "1", *arguments, str(tmp_path)],
        capture_output=True,
        text=True,
        env={**os.environ, **environment},
        timeout=120,
        check=False,
    )
    assert result.returncode == 0
    assert "passed" in result.stdout
    assert result.stderr == ""
