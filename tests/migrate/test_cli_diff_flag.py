"""``--diff`` names mint-migrate's default mode, as ``mint check --diff`` and ruff spell it.

A user of those tools types ``--diff`` for a dry run; it prints the same unified diff and report
as no mode at all, writes nothing, and is a mode like the others: ``--diff --write`` is refused.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate

V3 = "HMSPEED = 10 : REM fast\n"  # v3's HMSPEED is v4's HOMESPEED (000:11356-11357)


def run(*arguments: str) -> tuple[int, str]:
    result = CliRunner().invoke(migrate, ["--controller", "mintdrive", *arguments])
    return result.exit_code, result.output


def test_diff_prints_what_the_default_prints_and_writes_nothing(tmp_path: Path) -> None:
    program = tmp_path / "demo.mnt"
    program.write_text(V3)
    asked = run("--diff", str(program))
    assert asked == run(str(program))
    assert asked[0] == 0
    assert "-HMSPEED = 10 : REM fast" in asked[1] and "+HOMESPEED = 10 : REM fast" in asked[1]
    assert program.read_text() == V3


def test_diff_with_another_mode_is_a_usage_error(tmp_path: Path) -> None:
    program = tmp_path / "demo.mnt"
    program.write_text(V3)
    code, output = run("--diff", "--write", str(program))
    assert code == 2
    assert "--write, --diff: choose one of these modes" in output
    assert program.read_text() == V3
