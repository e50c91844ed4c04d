"""``mint check --select/--ignore`` with four-digit codes: a prefix selects one family only."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main

# On NextMove BX: line 1 is error 2 (axis 12 out of range), line 4 an ENDL without LOOP (error 2014)
# and line 5 a keyword the controller lacks (error 17).
PROGRAM = "SPEED.12 = 1\nLOOP\nENDL\nENDL\nDRIVEENABLESWITCH = 1\n"


def codes_found(tmp_path: Path, *options: str) -> list[str]:
    path = tmp_path / "axes.mnt"
    path.write_text(PROGRAM, encoding="utf-8")
    arguments = ["check", "--controller", "nextmove-bx", "--format", "json", *options, str(path)]
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code in (0, 1), result.output
    return [record["code"] for record in json.loads(result.stdout)]


def test_every_error_is_reported_in_four_digits(tmp_path: Path) -> None:
    assert codes_found(tmp_path) == ["E0002", "E2014", "E0017"]


@pytest.mark.parametrize(
    ("selection", "codes"),
    [
        ("E2", ["E2014"]),  # the compiler's E2000-E2021, not error 2
        ("E0002", ["E0002"]),
        ("E00", ["E0002", "E0017"]),
        ("E17", ["E0017"]),  # the short spelling where it begins no code
        ("E0002,E17", ["E0002", "E0017"]),
    ],
)
def test_select_takes_prefixes_of_four_digit_codes_and_short_spellings(
    tmp_path: Path, selection: str, codes: list[str]
) -> None:
    assert codes_found(tmp_path, "--select", selection) == codes


def test_ignore_reads_codes_as_select_does(tmp_path: Path) -> None:
    assert codes_found(tmp_path, "--ignore", "E17", "--ignore", "E2") == ["E0002"]


def test_a_code_that_selects_nothing_is_a_usage_error_in_one_line(tmp_path: Path) -> None:
    path = tmp_path / "axes.mnt"
    path.write_text(PROGRAM, encoding="utf-8")
    result = subprocess.run(
        [Path(sys.executable).with_name("mint"), "check", "--select", "E999", str(path)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert "'E999' is no code and begins none" in result.stderr
    assert "Traceback" not in result.stderr


def test_the_help_says_how_prefixes_and_short_spellings_combine() -> None:
    help_text = " ".join(CliRunner().invoke(main, ["check", "--help"]).output.split())
    assert "E2 is E2000-E2021" in help_text
    assert "E17 is E0017" in help_text


@pytest.mark.parametrize(
    ("options", "codes"),
    [
        ((), []),  # I201 is not among the codes checked by default (README, "Selecting codes")
        (("--select", "ALL"), ["I201"]),  # every code, as ruff's ALL
        (("--select", "all"), ["I201"]),
        (("--select", "ALL", "--ignore", "I"), []),
    ],
)
def test_select_all_checks_every_code(tmp_path: Path, options: tuple[str, ...], codes: list[str]) -> None:
    path = tmp_path / "hint.mnt"
    path.write_text("PRINT POS[1]\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["check", "--format", "json", *options, str(path)])
    assert result.exit_code == 0, result.output
    assert [record["code"] for record in json.loads(result.stdout)] == codes


def test_show_settings_names_all_as_written(tmp_path: Path) -> None:
    path = tmp_path / "hint.mnt"
    path.write_text("PRINT 1\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["check", "--select", "ALL", "--show-settings", str(path)])
    assert result.exit_code == 0, result.output
    assert [line.split()[:2] for line in result.stdout.splitlines() if line.split()[:1] == ["select"]] == [
        ["select", "ALL"]
    ]


@pytest.mark.parametrize(
    "options",
    [("--ignore", "E", "--select", "E0017"), ("--select", "ALL", "--ignore", "E", "--extend-select", "E17")],
)
def test_an_ignored_code_stays_ignored_however_narrowly_selected(options: tuple[str, ...], tmp_path: Path) -> None:
    """Unlike ruff, where the longer prefix wins (README, Selecting codes): every ignore applies."""
    assert codes_found(tmp_path, *options) == []
