"""Reports people can act on: every change and every manual item carries its line in the
original file and in the migrated one, in JSON and in text; a manual item points at the line
it marks (the one below its ``REM MIGRATE:`` line), an application note at its own line; the
counts read "1 change", "2 changes"."""

from __future__ import annotations

import json
from itertools import takewhile
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command
from mintlang.migrate.context import MARKER_LINE, marks_line_above
from tests.migrate.golden import GOLDEN

SOURCE = "x = 1\nHMSPEED = 10\nLOAD 3\n"
# migrated with M-DIM, M-REN and X-HOST:
#   1 DIM x            <- inserted above original line 1
#   2 x = 1            (original 1)
#   3 HOMESPEED = 10   (original 2)
#   4 REM MIGRATE: X-HOST: ...
#   5 LOAD 3           (original 3)
RULES = ["--only", "M-DIM", "--only", "M-REN", "--only", "X-HOST"]


def run(tmp_path: Path, *arguments: str) -> tuple[int, str]:
    path = tmp_path / "prog.mnt"
    path.write_text(SOURCE)
    result = CliRunner().invoke(command, ["--controller", "mintdrive", *RULES, *arguments, str(path)])
    return result.exit_code, result.stdout


def test_json_items_carry_both_lines(tmp_path: Path) -> None:
    _, output = run(tmp_path, "--format", "json")
    row = json.loads(output)["files"][0]
    assert [(c["rule"], c["original_line"], c["migrated_line"]) for c in row["changes"]] == [
        ("M-DIM", 1, 1),
        ("M-REN", 2, 3),
    ]
    assert [(m["rule"], m["original_line"], m["migrated_line"], m["note"]) for m in row["manual"]] == [
        ("X-HOST", 3, 5, False)
    ]


def test_text_items_carry_both_lines(tmp_path: Path) -> None:
    _, output = run(tmp_path)
    assert f"{tmp_path / 'prog.mnt'}:5 (original line 3): X-HOST LOAD" in output
    assert "@@ -1,3 +1,5 @@" in output  # the diff gives the changes' lines in both files


def test_a_marker_above_a_statement_moved_off_the_auto_line_points_at_that_statement() -> None:
    result = migrate("", config="AUTO : ERRORIN = 1\n", only=["S-ERRORIN"]).configuration
    assert result is not None
    assert result.text.splitlines()[2] == "ERRORIN = 1"
    assert [(item.line, item.original_line) for item in result.manual] == [(3, 1)]


def test_application_notes_point_at_their_own_line() -> None:
    result = migrate("AXES[0]\nMOVEA = 10 : GO\n", controller="mintdrive", only=["S-PROLOGUE"])
    lines = result.text.splitlines()
    assert result.manual and all(item.note and item.original_line is None for item in result.manual)
    assert all(lines[item.line - 1].startswith(f"REM MIGRATE: S-PROLOGUE: {item.reason}") for item in result.manual)


@pytest.mark.parametrize(
    ("source", "summary"),
    [
        ("HMSPEED = 10\n", "1 file: 1 changed, 0 unchanged; 1 change, 0 manual items, 0 unreadable lines"),
        (
            "x = 1\nHMSPEED = 10\nLOAD 3\nLOAD 4\nPRINT x x\n",
            "1 file: 1 changed, 0 unchanged; 2 changes, 3 manual items, 1 unreadable line",
        ),
    ],
)
def test_counts_are_in_the_singular_for_one(tmp_path: Path, source: str, summary: str) -> None:
    path = tmp_path / "prog.mnt"
    path.write_text(source)
    result = CliRunner().invoke(
        command,
        [
            "--controller",
            "mintdrive",
            "--only",
            "M-REN",
            "--only",
            "M-DIM",
            "--only",
            "X-HOST",
            "--only",
            "X-COMMENTED",
            str(path),
        ],
    )
    assert summary in result.stdout


def _golden_reports() -> list[Path]:
    return sorted(GOLDEN.glob("*/expected-report.json"))


@pytest.mark.parametrize("report", _golden_reports(), ids=lambda path: path.parent.name)
def test_every_golden_item_points_at_its_lines(report: Path) -> None:
    for row in json.loads(report.read_text())["files"]:
        suffix = ".cfg" if row["role"] == "configuration" else ".mnt"
        original = (report.parent / f"input{suffix}").read_text().splitlines()
        migrated = (report.parent / f"expected{suffix}").read_text().splitlines()
        for change in row["changes"]:
            if change["original"].strip():
                assert change["original"].splitlines()[0].strip() in original[change["original_line"] - 1]
            replaced_later = any(
                other is not change
                and (other["original_line"], other["original"]) == (change["original_line"], change["original"])
                for other in row["changes"]
            )
            written = change["replacement"].strip().splitlines()[:1]
            if written and not replaced_later and not change["replacement"][0].isspace():
                assert written[0] in migrated[change["migrated_line"] - 1], change
        for item in row["manual"]:
            line = migrated[item["migrated_line"] - 1]
            if item["note"]:
                assert line.startswith(f"REM MIGRATE: {item['rule']}: "), item
                continue
            assert "REM MIGRATE:" not in line, item
            above = list(takewhile(_is_marker, reversed(migrated[: item["migrated_line"] - 1])))
            below = list(takewhile(_is_marker, migrated[item["migrated_line"] :]))
            # the markers above the line, and those below it that say they mark the line above (AUTO, PROTECT)
            block = [m for m in above if not marks_line_above(m)] + [m for m in below if marks_line_above(m)]
            assert any(marker.strip().startswith(f"REM MIGRATE: {item['rule']}:") for marker in block), item


def _is_marker(line: str) -> bool:
    return MARKER_LINE.match(line) is not None
