"""``mint-migrate`` on awkward input: every problem is one line with exit status 2, and
nothing is written that should not be (links, read-only files, binaries, half-done batches)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.migrate import cli as migrate_cli
from mintlang.migrate import migrate

V3 = "DIM a\nPRINT a\nEND\n"
V4 = "AXES[0,1,2]\nDIM a\nPRINT a\nEND\n"


def run(*arguments: object) -> Result:
    return CliRunner().invoke(migrate_cli.migrate, [str(argument) for argument in arguments])


def program(directory: Path, name: str, text: str = V3) -> Path:
    path = directory / name
    path.write_text(text)
    return path


def one_line_usage_error(result: Result) -> str:
    assert result.exit_code == 2
    assert "Traceback" not in result.output and len(result.stderr.strip().splitlines()) == 1
    return result.stderr.strip()


@pytest.mark.parametrize("name", ["demo.mnt", "x[/v3].mnt"])
def test_markup_in_a_program_or_its_path_is_printed_as_text(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("x[").mkdir()
    program(Path(), name, 'DIM x\nPRINT x "[/b]"\nEND\n')
    result = run(name)
    assert result.exit_code == 1  # a manual item, not a crash
    assert f"{name}:4: X-COMMENTED not valid Mint v3 either (Syntax error: unexpected '\"[/b]\"')" in result.output
    assert any(line.startswith(f" {name} ") and "program" in line for line in result.output.splitlines())


def test_with_takes_optional_rules_only() -> None:
    message = one_line_usage_error(run("--with", "M-ABBR", "unused.mnt"))
    assert "not an optional rule: M-ABBR" in message and "M-BIT" in message and "S-IDLEAXES" in message


def test_a_byte_order_mark_stays_first(tmp_path: Path) -> None:
    path = tmp_path / "bom.mnt"
    path.write_bytes(b"\xef\xbb\xbfREM x\nDIM a\nPRINT a\nEND\n")
    assert run("--write", path).exit_code == 0
    assert path.read_bytes() == b"\xef\xbb\xbfREM x\nAXES[0,1,2]\nDIM a\nPRINT a\nEND\n"


def test_a_byte_order_mark_does_not_move_the_changes() -> None:
    result = migrate("\ufeffHMSPEED = 10\n", controller="mintdrive", only=["M-REN"])
    assert result.text == "\ufeffHOMESPEED = 10\n"
    change = result.changes[0]
    assert result.source[change.span.start : change.span.end] == change.original == "HMSPEED"
