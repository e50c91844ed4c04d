"""``mint-migrate --to mintmt``: the same modes, report and exit codes as the v3 → v4 migration, on v4
files; ``--to v4`` (the default) is today's migration."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate

V4 = "REM demo\r\nMOVER.0 = 10 : REM load\r\nGO.0\r\n"
MINTMT = "' demo\r\nMOVER(0) = 10 : ' load\r\nGO(0)\r\n"


@pytest.fixture
def program(tmp_path: Path) -> Path:
    path = tmp_path / "demo.mnt"
    path.write_bytes(V4.encode("cp1252"))
    return path


def run(*arguments: str) -> tuple[int, str]:
    result = CliRunner().invoke(migrate, ["--to", "mintmt", *arguments])
    return result.exit_code, result.output


def test_write_rewrites_in_place_keeping_line_breaks(program: Path) -> None:
    assert run("--write", str(program))[0] == 0
    assert program.read_bytes() == MINTMT.encode("cp1252")


def test_dry_run_prints_a_diff_and_the_report(program: Path) -> None:
    code, output = run(str(program))
    assert code == 0
    assert "-MOVER.0 = 10 : REM load" in output and "+MOVER(0) = 10 : ' load" in output
    assert "mint-migrate (to mintmt)" in output
    assert "1 file: 1 changed, 0 unchanged; 4 changes, 0 manual items, 0 unreadable lines" in output
    assert program.read_bytes() == V4.encode("cp1252")


def test_stdout_prints_the_migrated_text(program: Path) -> None:
    result = CliRunner().invoke(migrate, ["--to", "mintmt", "--stdout", str(program)])
    assert result.exit_code == 0
    assert result.stdout_bytes == MINTMT.encode("cp1252")


def test_json_report_says_to_mintmt_and_counts_files_already_mintmt(program: Path, tmp_path: Path) -> None:
    already = tmp_path / "mt.mnt"
    already.write_text("MOVER(0) = 10 ' load\n")
    code, output = run("--format", "json", str(program), str(already))
    data = json.loads(output)
    assert code == 0
    assert data["to"] == "mintmt"
    assert [row["status"] for row in data["files"]] == ["changed", "already mintmt"]
    assert data["totals"]["already_mintmt"] == 1
    assert {change["rule"] for change in data["files"][0]["changes"]} == {"MT-COMMENT", "MT-ADDRESS"}


def test_check_exits_1_until_the_file_is_migrated(program: Path) -> None:
    assert run("--check", str(program))[0] == 1
    program.write_bytes(MINTMT.encode())
    assert run("--check", str(program))[0] == 0


def test_list_rules_lists_the_mintmt_rewrites_and_checks() -> None:
    code, output = run("--list-rules")
    assert code == 0
    assert [line.split()[0] for line in output.splitlines()] == [
        "MT-COMMENT",
        "MT-CHARACTER",
        "MT-ADDRESS",
        "MT-BLOCK",
        "MT-EVENT",
        "MT-NAME",
        "MT-LENGTH",
        "MT-PLATFORM",
    ]


@pytest.mark.parametrize("option", [["--only", "S-RENAME"], ["--skip", "S-RENAME"], ["--v3-controller", "euroservo"]])
def test_options_about_a_v3_original_are_refused(program: Path, option: list[str]) -> None:
    result = CliRunner().invoke(migrate, ["--to", "mintmt", *option, "--verify", str(program)])
    assert result.exit_code == 2
    assert f"{option[0]}: only when migrating from Mint v3 (--to v4)" in result.output


def test_verify_compares_the_v4_run_with_the_mintmt_run(tmp_path: Path) -> None:
    path = tmp_path / "move.mnt"
    path.write_text("MOVER.0 = 10 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n")
    code, output = run("--verify", "--drives", "enabled", "--format", "json", str(path))
    data = json.loads(output)
    application = data["applications"][0]
    assert code == 0
    assert application["verdict"] == "equivalent"
    assert (application["v4_controller"], application["mintmt_controller"]) == ("nextmove-pci", "nextmove-pci")
    assert set(application["stopped"]) == {"v4", "mintmt"}


def test_verify_names_the_runs_v4_and_mintmt_in_text(tmp_path: Path) -> None:
    path = tmp_path / "late.mnt"
    path.write_text("PRINT 1\nEND\n#TIMER\nPRINT 2\nRETURN\n")  # the handler is flagged, kept: both print 1
    code, output = run("--verify", str(path))
    assert code == 0
    assert "equivalent" in output
    assert "not verified:" in output and "MT-EVENT" in output


def test_verify_of_two_runs_that_both_stop_on_an_error_at_once_is_incomplete(tmp_path: Path) -> None:
    # README, --verify: agreeing that both fail at 0 ms (here the drive a controller powers up with disabled,
    # error 40) verifies nothing; the v3 -> v4 verification says so, exit status 2
    path = tmp_path / "move.mnt"
    path.write_text("MOVER.0 = 10 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n")
    code, output = run("--verify", str(path))
    assert code == 2
    assert output.startswith(f"{path}: incomplete: both runs stopped on an error at 0 ms (R0040: ")


def test_default_is_the_v3_migration(program: Path) -> None:
    program.write_text("HMSPEED = 10\n")
    result = CliRunner().invoke(migrate, ["--controller", "mintdrive", "--stdout", str(program)])
    assert result.stdout == "HOMESPEED = 10\n"
