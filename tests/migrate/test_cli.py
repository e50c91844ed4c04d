"""``mint-migrate`` and ``mint migrate``: modes, report formats, exit codes, atomic writes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main as mint
from mintlang.migrate import rules
from mintlang.migrate.cli import migrate

V3 = "REM demo\r\nHMSPEED = 10 : REM fast\r\nx = 1\r\n"
V4 = "REM demo\r\nDIM x\r\nHOMESPEED = 10 : REM fast\r\nx = 1\r\n"


@pytest.fixture
def program(tmp_path: Path) -> Path:
    path = tmp_path / "demo.mnt"
    path.write_bytes(V3.encode("cp1252"))
    return path


def run(*arguments: str) -> tuple[int, str]:
    result = CliRunner().invoke(migrate, ["--controller", "mintdrive", *arguments])
    return result.exit_code, result.output


def test_dry_run_prints_a_diff_and_writes_nothing(program: Path) -> None:
    code, output = run(str(program))
    assert code == 0
    assert "-HMSPEED = 10 : REM fast" in output and "+HOMESPEED = 10 : REM fast" in output
    assert "1 file: 1 changed, 0 unchanged; 2 changes, 0 manual items, 0 unreadable lines" in output
    assert program.read_bytes() == V3.encode("cp1252")


def test_write_rewrites_in_place_keeping_encoding_and_newlines(program: Path) -> None:
    program.write_bytes(V3.replace("demo", "Größe").encode("cp1252"))
    code, _ = run("--write", str(program))
    assert code == 0
    assert program.read_bytes() == V4.replace("demo", "Größe").encode("cp1252")
    assert [p.name for p in program.parent.iterdir()] == ["demo.mnt"]  # no temporary file left


def test_check_exits_1_when_changes_are_pending(program: Path) -> None:
    assert run("--check", str(program))[0] == 1
    program.write_bytes(V4.encode())
    assert run("--check", str(program))[0] == 0


def test_manual_items_are_reported_and_fail_only_with_fail_on_manual(tmp_path: Path) -> None:
    path = tmp_path / "load.mnt"
    path.write_text("LOAD 3\n")
    code, output = run(str(path))
    assert code == 0
    assert f"{path}:2 (original line 1): X-HOST LOAD" in output
    assert run("--fail-on", "manual", str(path))[0] == 1


def test_stdout_prints_the_migrated_text(program: Path) -> None:
    result = CliRunner().invoke(migrate, ["--controller", "mintdrive", "--stdout", str(program)])
    assert result.exit_code == 0
    assert result.stdout_bytes == V4.encode("cp1252")


def test_json_report(program: Path) -> None:
    code, output = run("--format", "json", str(program))
    data = json.loads(output)
    assert code == 0
    assert data["totals"] == {
        "changed": 1,
        "unchanged": 0,
        "already_v4": 0,
        "failed": 0,
        "not_written": 0,
        "changes": 2,
        "manual_items": 0,
        "errors": 0,
    }
    assert data["rules"] == {"M-DIM": 1, "M-REN": 1}
    assert data["files"][0]["status"] == "changed"
    assert data["files"][0]["changes"][0] == {
        "rule": "M-REN",
        "original_line": 2,
        "migrated_line": 3,  # below the DIM x the migration adds
        "original": "HMSPEED",
        "replacement": "HOMESPEED",
    }


def test_config_and_program_migrate_together(tmp_path: Path) -> None:
    config = tmp_path / "app.cfg"
    config.write_text("AUTO\nspeed1 = 5\n")
    program = tmp_path / "app.mnt"
    program.write_text("JOG = speed1\n")
    # the prologue and default notes a jog earns are left out: this is about the two files together
    code, _ = run("--write", "--skip", "S-PROLOGUE", "--skip", "S-DEFAULTS", "--config", str(config), str(program))
    assert code == 0
    assert config.read_text() == "AUTO\nDIM speed1\nspeed1 = 5\n"
    assert program.read_text() == "JOG = speed1\n"


def test_only_and_skip(program: Path) -> None:
    assert "+DIM x" not in run("--skip", "M-DIM", str(program))[1]
    assert "HOMESPEED" not in run("--only", "M-DIM", str(program))[1]


def test_list_rules_lists_every_rule() -> None:
    code, output = run("--list-rules")
    assert code == 0
    assert all(info.id in output for info in rules())


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (["missing.mnt"], "no such file or directory: missing.mnt"),
        (["--only", "M-NOPE", "x.mnt"], "unknown rule: M-NOPE"),
        (["--stdout", "a.mnt", "b.mnt"], "--stdout prints one file"),
    ],
)
def test_usage_errors_exit_2_with_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, arguments: list[str], message: str
) -> None:
    monkeypatch.chdir(tmp_path)
    for name in ("x.mnt", "a.mnt", "b.mnt"):
        Path(name).write_text("x = 1\n")
    result = CliRunner().invoke(migrate, arguments)
    assert result.exit_code == 2
    assert message in result.output and "Traceback" not in result.output
    assert len(result.output.strip().splitlines()) == 1


def test_mint_migrate_subcommand(program: Path) -> None:
    result = CliRunner().invoke(mint, ["migrate", "--controller", "mintdrive", "--check", str(program)])
    assert result.exit_code == 1
