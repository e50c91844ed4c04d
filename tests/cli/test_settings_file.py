"""``mint check`` reads ``mint.toml`` or ``[tool.mint]`` of ``pyproject.toml``, the nearest above each file, under
the command line's options; ``--show-settings`` says what applies and why; a bad file is one line, exit 2."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, numbered, records, write

OUTPUT_20 = "OUT20 = 1\n"  # NextMove PCI has outputs 0 to 35, MintDrive 0 to 8: error 8 on MintDrive (v4 guide)
SPARE = "DIM spare\n"  # W103: declared, never used
LONG = "DIM a\na = 1\nPRINT a" + " " * 300 + "\n"  # W111: a line longer than the controller's editor takes


def findings(*arguments: str | Path) -> list[tuple[str, str]]:
    """(file name, code) of each finding."""
    return [(Path(r["path"]).name, numbered(r["code"])) for r in records(*arguments)]


# ------------------------------------------------------------------ discovery


def test_the_controller_of_mint_toml_applies_to_the_files_below_it(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    program = write(tmp_path / "cells" / "press" / "out.mnt", OUTPUT_20)
    assert findings(program) == [("out.mnt", "E8")]


def test_tool_mint_in_pyproject_applies(tmp_path: Path) -> None:
    write(tmp_path / "pyproject.toml", '[project]\nname = "line"\n\n[tool.mint]\ncontroller = "mintdrive"\n')
    assert findings(write(tmp_path / "out.mnt", OUTPUT_20)) == [("out.mnt", "E8")]


def test_a_pyproject_without_tool_mint_is_passed_over(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "sub" / "pyproject.toml", '[project]\nname = "sub"\n')
    assert findings(write(tmp_path / "sub" / "out.mnt", OUTPUT_20)) == [("out.mnt", "E8")]


def test_mint_toml_wins_over_pyproject_in_the_same_folder(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "pyproject.toml", '[tool.mint]\ncontroller = "nextmove-pci"\n')
    assert findings(write(tmp_path / "out.mnt", OUTPUT_20)) == [("out.mnt", "E8")]


def test_the_nearest_settings_file_wins_whole(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "bench" / "mint.toml", 'ignore = ["W103"]\n')  # says nothing of the controller: the default
    outer, inner = write(tmp_path / "out.mnt", OUTPUT_20), write(tmp_path / "bench" / "out.mnt", OUTPUT_20 + SPARE)
    assert findings(outer, inner) == [("out.mnt", "E8")]


def test_each_file_of_a_directory_run_has_its_own_settings(tmp_path: Path) -> None:
    write(tmp_path / "drive" / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "drive" / "a.mnt", OUTPUT_20)
    write(tmp_path / "card" / "b.mnt", OUTPUT_20)
    assert findings(tmp_path) == [("a.mnt", "E8")]


# ------------------------------------------------------------------ selection


def test_the_command_line_wins_over_the_file(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    assert findings("--controller", "nextmove-pci", write(tmp_path / "out.mnt", OUTPUT_20)) == []


def test_select_extend_select_and_ignore_of_the_file(tmp_path: Path) -> None:
    program = write(tmp_path / "p.mnt", SPARE + "DIM b\nb = POS[1]\n" + OUTPUT_20)  # W103, I201 (POS.1), no error
    write(tmp_path / "mint.toml", 'select = ["W"]\n')
    assert findings(program) == [("p.mnt", "W103")]
    write(tmp_path / "mint.toml", 'extend-select = ["I201"]\n')
    assert findings(program) == [("p.mnt", "W103"), ("p.mnt", "I201")]
    write(tmp_path / "mint.toml", 'extend-select = ["I"]\nignore = ["W103"]\n')
    assert findings(program) == [("p.mnt", "I201")]


def test_select_on_the_command_line_replaces_the_files_but_its_ignore_still_applies(tmp_path: Path) -> None:
    program = write(tmp_path / "p.mnt", SPARE + LONG)
    write(tmp_path / "mint.toml", 'select = ["E"]\nextend-select = ["I"]\nignore = ["W103"]\n')
    assert findings("--select", "W", program) == [("p.mnt", "W111")]
    assert findings("--select", "W", "--extend-select", "W103", program) == [("p.mnt", "W111")]


@pytest.mark.parametrize(
    ("options", "expected"),
    [
        pytest.param(("--extend-select", "I201"), ["W103", "I201"], id="--extend-select adds to the file's"),
        pytest.param(("--select", "E", "--extend-select", "I201"), ["I201"], id="--select replaces the file's"),
    ],
)
def test_extend_select_on_the_command_line(tmp_path: Path, options: tuple[str, ...], expected: list[str]) -> None:
    program = write(tmp_path / "p.mnt", SPARE + "DIM b\nb = POS[1]\n")  # W103, I201 (POS.1)
    write(tmp_path / "mint.toml", 'select = ["E"]\nextend-select = ["W103"]\n')
    assert [code for _, code in findings(*options, program)] == expected


def test_per_file_ignores_apply_to_the_files_their_glob_matches(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[per-file-ignores]\n"legacy/*.mnt" = ["W103"]\n"scratch.MNT" = ["W"]\n')
    old, new = write(tmp_path / "legacy" / "old.mnt", SPARE), write(tmp_path / "new.mnt", SPARE)
    scratch = write(tmp_path / "deep" / "scratch.mnt", SPARE)  # a name alone matches in any folder, any case
    assert findings(old, new, scratch) == [("new.mnt", "W103")]


@pytest.mark.parametrize(
    "glob",
    [
        pytest.param("**/legacy/*.mnt", id="a leading **/ matches no folder too"),
        pytest.param("legacy/**/*.mnt", id="an inner **/ matches no folder too"),
        pytest.param("**/legacy/**/*.mnt", id="each **/ matches no folder too"),
        pytest.param("./legacy/*.mnt", id="./ is the settings file's folder"),
    ],
)
def test_per_file_ignores_read_globs_as_ruff_does(tmp_path: Path, glob: str) -> None:
    write(tmp_path / "mint.toml", f'[per-file-ignores]\n"{glob}" = ["W103"]\n')
    old, deeper = write(tmp_path / "legacy" / "old.mnt", SPARE), write(tmp_path / "legacy" / "v2" / "old.mnt", SPARE)
    new = write(tmp_path / "new.mnt", SPARE)
    assert findings(old, deeper, new) == [("new.mnt", "W103")]


@pytest.mark.parametrize(
    ("glob", "expected"),
    [
        pytest.param("*.cfg", [("cell.mnt", "W103")], id="the configuration file's glob leaves out its finding"),
        pytest.param("*.mnt", [("cell.cfg", "W103")], id="the program's glob leaves the configuration's in"),
    ],
)
def test_per_file_ignores_follow_the_file_a_finding_is_in(
    tmp_path: Path, glob: str, expected: list[tuple[str, str]]
) -> None:
    """A configuration file is reported with its program, yet under its own settings, as ruff matches a
    per-file-ignores glob against the file a finding is in; whether found by a walk or named."""
    write(tmp_path / "mint.toml", f'[per-file-ignores]\n"{glob}" = ["W103"]\n')
    write(tmp_path / "cell.cfg", SPARE)
    write(tmp_path / "cell.mnt", "DIM other\n")
    assert findings(tmp_path) == expected
    assert findings(tmp_path / "cell.mnt", tmp_path / "cell.cfg") == expected


# ------------------------------------------------------------------ --show-settings


def test_show_settings_says_what_applies_and_where_it_came_from(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", '# the press line\ncontroller = "mintdrive"\n\nignore = ["W111"]\n')
    program = write(tmp_path / "press.mnt", OUTPUT_20)
    write(tmp_path / "PRESS.CFG", "DIM a\n")
    result = mint_check("--show-settings", "--select", "E", program)
    assert result.exit_code == 0, result.output
    rows = {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines()[1:]}
    assert result.stdout.splitlines()[0] == f"{program}:"
    assert rows["settings"] == ["file", str(settings.absolute())]
    assert rows["controller"] == ["mintdrive", f"{settings.absolute()}:2"]
    assert rows["ignore"] == ["W111", f"{settings.absolute()}:4"]
    assert rows["select"] == ["E", "--select"]
    assert rows["dialect"] == ["v4", "default"]
    assert rows["configuration"][:2] == ["file", str(tmp_path / "PRESS.CFG")]


def test_show_settings_without_a_settings_file_shows_the_defaults(tmp_path: Path) -> None:
    result = mint_check("--show-settings", write(tmp_path / "a.mnt", "PRINT 1\n"))
    rows = dict(re.split(r"\s{2,}", line.strip())[:2] for line in result.stdout.splitlines()[1:])
    assert rows["settings file"] == "none"
    assert rows["controller"] == "nextmove-pci"
    assert rows["exclude"] == "19 tools' folders (.git, build ...)"
    assert (rows["extend-exclude"], rows["force-exclude"]) == ("none", "false")


def test_show_settings_lists_what_is_excluded_and_where_it_was_set(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", 'extend-exclude = ["old/*.mnt", "tmp"]\nforce-exclude = true\n')
    result = mint_check("--show-settings", "--exclude", "x,y", write(tmp_path / "a.mnt", "PRINT 1\n"))
    rows = {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines()[1:]}
    assert rows["exclude"] == ["x,", "y", "--exclude"]
    assert rows["extend-exclude"] == ["old/*.mnt,", "tmp", f"{settings.absolute()}:1"]
    assert rows["force-exclude"] == ["true", f"{settings.absolute()}:2"]


def test_show_settings_of_a_path_that_is_not_there_says_so(tmp_path: Path) -> None:
    result = mint_check("--show-settings", tmp_path / "absent.mnt")
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr == f"mint check: no such file or directory: {tmp_path / 'absent.mnt'}\n"


# ------------------------------------------------------------------ bad files


@pytest.mark.parametrize(
    ("text", "line", "message"),
    [
        ('controller = "mintdrive"\ncolour = "red"\n', "2:1", "colour: unknown key (known: controller, dialect,"),
        ('\n\ncontroller = "nextmove-xyz"\n', "3:14", "controller: 'nextmove-xyz' is not one of nextmove-pci,"),
        ('select = ["E2", "X9"]\n', "1:10", "select: 'X9' is no code and begins none"),
        ('ignore = "W103"\n', "1:10", "ignore: must be a list of codes or code prefixes"),
        ('config-pairing = "cfg/<name>.cfg"\n', "1:18", "config-pairing: the configuration file is beside its program"),
        ('config-pairing = "setup.cfg"\n', "1:18", "config-pairing: 'setup.cfg' has no <name>: write false"),
        ('[per-file-ignores]\n"*.mnt" = ["Q1"]\n', "2:11", "per-file-ignores.\"*.mnt\": 'Q1' is no code"),
        ("per-file-ignores = 3\n", "1:20", "per-file-ignores: must be a table"),
        ('config = "cell\\u0000.cfg"\n', "1:10", "config: a path cannot hold a NUL character"),
        ('controller = "mintdrive"\nselect = [E]\n', "2:11", "not valid TOML: Invalid value"),  # at the E
        ('controller = "mintdrive"\nselect = [\n', "3:1", "not valid TOML: Invalid value (at the end of the file)"),
    ],
)
def test_a_bad_settings_file_is_one_line_naming_file_line_and_key(
    tmp_path: Path, text: str, line: str, message: str
) -> None:
    """Placed at its line and column: an unknown key at the key, a bad value at the value, TOML that cannot be
    read where its reading stopped."""
    settings = write(tmp_path / "mint.toml", text)
    result = mint_check(write(tmp_path / "a.mnt", "PRINT 1\n"))
    assert result.exit_code == 2
    assert result.stdout == ""
    [printed] = result.stderr.splitlines()
    assert printed.startswith(f"mint check: {settings.absolute()}:{line}: {message}")


def test_a_bad_key_in_pyproject_is_named_with_its_table(tmp_path: Path) -> None:
    settings = write(tmp_path / "pyproject.toml", '[project]\nname = "x"\n\n[tool.mint]\nselct = ["E"]\n')
    result = mint_check(write(tmp_path / "a.mnt", "PRINT 1\n"))
    assert result.exit_code == 2
    assert result.stderr.startswith(f"mint check: {settings.absolute()}:5:1: tool.mint.selct: unknown key")


def test_a_broken_settings_file_is_never_passed_over_for_one_further_up(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "sub" / "mint.toml", "controller = \n")
    assert mint_check(write(tmp_path / "sub" / "a.mnt", OUTPUT_20)).exit_code == 2


def test_the_real_command_reads_the_settings_of_the_files_folder(tmp_path: Path) -> None:
    write(tmp_path / "line" / "mint.toml", 'controller = "mintdrive"\n')
    write(tmp_path / "line" / "out.mnt", OUTPUT_20)
    mint = Path(sys.executable).with_name("mint")
    run = subprocess.run([mint, "check", "line"], cwd=tmp_path, capture_output=True, text=True, check=False)
    assert run.returncode == 1, run.stderr
    assert "out.mnt:1:" in run.stdout
    bad = write(tmp_path / "line" / "mint.toml", "controller = 1\n")
    run = subprocess.run([mint, "check", "line"], cwd=tmp_path, capture_output=True, text=True, check=False)
    assert (run.returncode, run.stdout) == (2, "")
    assert run.stderr == f"mint check: {bad.absolute()}:1:14: controller: 1 is not one of {_v4_controllers()}\n"
    assert "Traceback" not in run.stderr


def _v4_controllers() -> str:
    return "nextmove-pci, nextmove-pc, nextmove-bx, mintdrive, servonode51"
