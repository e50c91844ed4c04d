"""``mint check`` reports the errors and warnings; the hints (I…) only with ``--select`` (issue 17, item 8)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main

HINTED = "DIM b\nb = POS[1]\nPRINT b\n"  # POS.1 is the faster spelling: I201 at line 2


def codes(*arguments: str) -> list[str]:
    result = CliRunner().invoke(main, ["check", "--format", "json", *arguments])
    return [record["code"] for record in json.loads(result.stdout)]


def test_a_hint_is_not_reported_by_default(tmp_path: Path) -> None:
    program = tmp_path / "hinted.mnt"
    program.write_text(HINTED)
    assert codes(str(program)) == []


def test_select_turns_the_hints_on(tmp_path: Path) -> None:
    program = tmp_path / "hinted.mnt"
    program.write_text(HINTED)
    assert codes("--select", "I", str(program)) == ["I201"]
    assert codes("--select", "E,W,I201", str(program)) == ["I201"]


def test_the_installed_command_leaves_hints_out_and_exits_0(tmp_path: Path) -> None:
    program = tmp_path / "hinted.mnt"
    program.write_text(HINTED)
    mint = Path(sys.executable).with_name("mint")
    run = subprocess.run([mint, "check", str(program)], capture_output=True, text=True, check=False)
    assert run.returncode == 0 and "I201" not in run.stdout and "0 infos" in run.stdout
