"""The text report's closing count says how many findings ``--fix`` would fix, and ``--fix`` leaves a
configuration file as it is (README, Fixes): a finding with a fix in a configuration file is reported,
with its fix, and not counted, or the count would promise what ``--fix`` then does not do."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main

# An unused suppression (W117, a safe fix) in each file: AUTO first, as a configuration file opens.
CONFIGURATION = "AUTO\nDIM g = 1 : REM mint: ignore[W111]\n"
PROGRAM = "PRINT g : REM mint: ignore[W111]\nEND\n"


def mint_check(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["check", "--controller", "nextmove-bx", *map(str, arguments)])


def test_a_fix_in_the_configuration_file_is_not_counted(tmp_path: Path) -> None:
    (tmp_path / "cell.cfg").write_text(CONFIGURATION, encoding="utf-8")
    program = tmp_path / "cell.mnt"
    program.write_text("PRINT g\nEND\n", encoding="utf-8")
    result = mint_check(program)
    assert "warning[W117]" in result.stdout and "fix: Remove the suppression comment" in result.stdout
    assert "fixable with --fix" not in result.stdout


def test_the_program_s_fixes_are_counted_beside_it(tmp_path: Path) -> None:
    (tmp_path / "cell.cfg").write_text(CONFIGURATION, encoding="utf-8")
    program = tmp_path / "cell.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    assert mint_check(program).stdout.endswith(
        "2 files checked: 0 errors, 2 warnings, 0 infos\n1 finding fixable with --fix.\n"
    )
    fixed = mint_check("--fix", program)
    assert program.read_text(encoding="utf-8") == "PRINT g\nEND\n"
    assert (tmp_path / "cell.cfg").read_text(encoding="utf-8") == CONFIGURATION
    assert fixed.stdout.endswith("Fixed 1 finding in 1 file (1 W117).\n")


def test_a_program_that_looks_like_mintmt_is_not_counted(tmp_path: Path) -> None:
    # Read as v4 by default, a MintMT program is left as it is by --fix (README, mint check): its findings,
    # here the typographic quotes of W101 (a safe fix), are reported and not promised to --fix
    program = tmp_path / "buffer.mnt"
    program.write_text("PRINT \u201cx\u201d\nIf 1 Then\nEnd If\n", encoding="utf-8")
    result = mint_check(program)
    assert "warning[W101]" in result.stdout and "looks like MintMT" in result.stderr
    assert "fixable with --fix" not in result.stdout
    assert mint_check("--fix", program).stdout.endswith("Nothing to fix.\n")


# 'the' is offered THEN, which only follows an IF's condition (000:1570-1577): --fix sets that fix aside rather
# than write a syntax error (000:18920-18923); the typographic quotes' fix (W101, safe) it applies.
SET_ASIDE = "DIM a\nthe a = 1\nPRINT \u201cx\u201d, a\n"


def test_a_fix_that_would_add_a_syntax_error_is_not_counted_and_is_named_at_its_finding(tmp_path: Path) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text(SET_ASIDE, encoding="utf-8")
    assert mint_check(program).stdout.endswith(
        "1 finding fixable with --fix.\n"
        f"Set aside by --fix, as the fix would add a syntax error: {program}:2:1 E3007.\n"
    )


def test_what_fix_fixes_is_what_was_counted_and_it_says_what_it_set_aside(tmp_path: Path) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text(SET_ASIDE, encoding="utf-8")
    fixed = mint_check("--fix", "--unsafe-fixes", program)
    assert program.read_text(encoding="utf-8") == 'DIM a\nthe a = 1\nPRINT "x", a\n'
    assert fixed.stdout.endswith(
        "Fixed 1 finding in 1 file (1 W101).\n"
        f"Set aside by --fix, as the fix would add a syntax error: {program}:2:1 E3007.\n"
    )
    again = mint_check("--fix", "--unsafe-fixes", program)
    assert "Nothing to fix.\n" in again.stdout and "fixable with" not in again.stdout


def test_after_the_safe_fixes_a_fix_left_to_unsafe_fixes_is_counted_as_it_would_apply(tmp_path: Path) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text(SET_ASIDE + "prnt a\n", encoding="utf-8")  # 'prnt' respelt PRINT: unsafe, and sound
    fixed = mint_check("--fix", program)
    assert fixed.stdout.endswith(
        "Fixed 1 finding in 1 file (1 W101).\n"
        "1 finding fixable with --fix --unsafe-fixes.\n"
        f"Set aside by --fix, as the fix would add a syntax error: {program}:2:1 E3007.\n"
    )


def test_a_selection_without_the_syntax_errors_does_not_let_fix_write_one(tmp_path: Path) -> None:
    # --select E3007 reports no 2006, but THEN written for 'the' is one all the same (000:1570-1577): --fix sets
    # it aside as it does with every code selected, and reports only what was selected
    program = tmp_path / "cell.mnt"
    program.write_text(SET_ASIDE, encoding="utf-8")
    for selection in (["--select", "E3007"], ["--ignore", "E2"]):
        fixed = mint_check(*selection, "--fix", "--unsafe-fixes", program)
        assert program.read_text(encoding="utf-8").startswith("DIM a\nthe a = 1\n")
        assert f"Set aside by --fix, as the fix would add a syntax error: {program}:2:1 E3007.\n" in fixed.stdout
        assert "E2006" not in fixed.stdout
