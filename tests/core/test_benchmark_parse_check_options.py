"""``benchmarks/parse_check.py`` refuses --lines too few for its --names, rather than ending in a traceback."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "parse_check.py"


@pytest.mark.parametrize(
    ("lines", "names"),
    [pytest.param(300, 500, id="declarations past the cut"), pytest.param(1011, 500, id="one line short")],
)
def test_too_few_lines_for_the_names_is_a_usage_error(lines: int, names: int) -> None:
    arguments = ["--lines", str(lines), "--names", str(names), "--repeat", "1"]
    done = subprocess.run([sys.executable, SCRIPT, *arguments], capture_output=True, text=True, check=False)
    assert done.returncode == 2
    assert f"--lines {lines} leaves no room for the loop after --names {names}" in done.stderr
    assert "Traceback" not in done.stderr
