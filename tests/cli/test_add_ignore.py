"""``mint check --add-ignore`` (ruff's ``--add-noqa``): silence what a program has today, report only what is new.

Each line with findings gets a ``REM mint: ignore[...]`` comment naming its codes (README, "Suppression
comments"); the files are written as ``--fix`` writes them; a configuration file's findings are silenced as its
programs see them; the codes silenced are those the run selects.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from tests.cli.invoking import mint_check, write

# Line 1: W103 (never used). Line 3: E3001 (x undeclared) and W101 (typographic quotes).
PROGRAM = "DIM spare\nDIM a\nx = a : PRINT “a”\nPRINT a\n"
SILENCED = "DIM spare : REM mint: ignore[W103]\nDIM a\nx = a : PRINT “a” : REM mint: ignore[E3001, W101]\nPRINT a\n"


def program(folder: Path, text: str = PROGRAM) -> Path:
    return write(folder / "cell.mnt", text)


def test_every_finding_is_silenced_on_its_line_and_the_next_check_is_clean(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check("--add-ignore", tmp_path)
    assert result.exit_code == 0
    assert path.read_text(encoding="utf-8") == SILENCED
    assert "Silenced 3 findings in 1 file (1 E3001, 1 W101, 1 W103)." in result.stdout
    again = mint_check(tmp_path)
    assert (again.exit_code, again.stdout) == (0, "1 file checked: 0 errors, 0 warnings, 0 infos\n")


def test_add_noqa_is_the_same_option_under_ruffs_name(tmp_path: Path) -> None:
    path = program(tmp_path)
    assert mint_check("--add-noqa", path).exit_code == 0
    assert path.read_text(encoding="utf-8") == SILENCED


def test_only_the_selected_codes_are_silenced(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check("--add-ignore", "--select", "W1", path)
    assert path.read_text(encoding="utf-8") == (
        "DIM spare : REM mint: ignore[W103]\nDIM a\nx = a : PRINT “a” : REM mint: ignore[W101]\nPRINT a\n"
    )
    assert "Silenced 2 findings in 1 file (1 W101, 1 W103)." in result.stdout


def test_a_second_run_silences_nothing(tmp_path: Path) -> None:
    path = program(tmp_path, SILENCED)
    result = mint_check("--add-ignore", path)
    assert (result.exit_code, path.read_text(encoding="utf-8")) == (0, SILENCED)
    assert "Nothing to silence." in result.stdout


def test_what_cannot_be_silenced_is_still_reported(tmp_path: Path) -> None:
    # 248 characters: a comment would take the line past the 255 a v4 controller reads (000:255)
    line = f"PRINT “{'a' * 240}”\n"
    path = program(tmp_path, line)
    result = mint_check("--add-ignore", path)
    assert path.read_text(encoding="utf-8") == line
    assert result.exit_code == 0 and "W101" in result.stdout and "Nothing to silence." in result.stdout


def test_a_configuration_file_is_silenced_as_its_programs_see_it(tmp_path: Path) -> None:
    # the configuration's undeclared name is E3001 for the program that sees it; its setting, used by the
    # program, is no W103 (a name is unused only if no program uses it)
    configuration = write(tmp_path / "cell.cfg", "DIM speed_setting\nspare = 1\n")
    program(tmp_path, "PRINT speed_setting\n")
    result = mint_check("--add-ignore", tmp_path)
    assert configuration.read_text(encoding="utf-8") == "DIM speed_setting\nspare = 1 : REM mint: ignore[E3001]\n"
    assert "Silenced 1 finding in 1 file (1 E3001)." in result.stdout
    assert mint_check(tmp_path).stdout == "2 files checked: 0 errors, 0 warnings, 0 infos\n"


def test_a_configuration_file_named_alone_is_silenced(tmp_path: Path) -> None:
    configuration = write(tmp_path / "axes.cfg", "spare = 1\n")
    result = mint_check("--add-ignore", configuration)
    assert configuration.read_text(encoding="utf-8") == "spare = 1 : REM mint: ignore[E3001]\n"
    assert result.stdout == "1 file checked: 0 errors, 0 warnings, 0 infos\nSilenced 1 finding in 1 file (1 E3001).\n"


def test_it_goes_with_neither_fixes_nor_standard_input(tmp_path: Path) -> None:
    path = program(tmp_path)
    for extra in (["--fix"], ["--diff"], ["--unsafe-fixes"]):
        result = mint_check("--add-ignore", *extra, path)
        assert result.exit_code == 2 and "--add-ignore writes comments into the programs" in result.output
    result = CliRunner().invoke(main, ["check", "--add-ignore", "-"], input=PROGRAM)
    assert result.exit_code == 2
    assert path.read_text(encoding="utf-8") == PROGRAM
