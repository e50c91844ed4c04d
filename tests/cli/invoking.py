"""Running ``mint check`` through click's test runner on files a test writes."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main


def mint_check(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["check", *(str(argument) for argument in arguments)])


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def records(*arguments: str | Path) -> list[dict]:
    """The JSON records of a check that ran (exit 0 or 1)."""
    result = mint_check("--format", "json", *arguments)
    assert result.exit_code in (0, 1), result.output
    return json.loads(result.stdout)


def numbered(code: str) -> str:
    """A code with the controller's error number as a number: E8 and E0008 alike are E8."""
    return f"E{int(code[1:])}" if code.startswith("E") else code
