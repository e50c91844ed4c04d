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
