"""Running ``mint-run`` through click's test runner on files a test writes."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.runtime.cli import run


def mint_run(*arguments: str | Path) -> Result:
    return CliRunner().invoke(run, [str(argument) for argument in arguments])


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(text, encoding="utf-8")
    return path
