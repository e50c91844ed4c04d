"""The bundled examples do what the README says a newcomer will see (issue 17, item 12).

Expected values are worked out from the programs: each MOVER of 500 counts moves
the filling cell's axis 500 further; the palletiser lays boxes 1 to 4.
"""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def mint(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, [str(argument) for argument in arguments])


def test_the_conveyor_has_one_deliberate_error_on_line_19_so_the_first_command_exits_with_1() -> None:
    result = mint("check", "--format", "json", EXAMPLES / "conveyor.mnt")
    assert result.exit_code == 1
    records = json.loads(result.stdout)
    assert [(r["severity"], r["line"], r["column"]) for r in records] == [("error", 19, 35)]
    assert "'targt'" in records[0]["message"]


def test_the_filling_cell_checks_clean_with_its_configuration_file() -> None:
    result = mint("check", EXAMPLES / "cell.mnt", "--config", EXAMPLES / "cell.cfg")
    assert result.exit_code == 0, result.output
    assert "2 files checked: 0 errors, 0 warnings, 0 infos" in result.stdout


def test_the_filling_cell_runs_after_its_configuration_file() -> None:
    result = mint("run", EXAMPLES / "cell.mnt", "--config", EXAMPLES / "cell.cfg")
    assert result.exit_code == 0, result.output
    assert result.stdout == "bottle 1 filled at 500\nbottle 2 filled at 1000\nbottle 3 filled at 1500\n"


def test_the_sorter_meets_every_expectation_of_its_scenario() -> None:
    assert mint("check", EXAMPLES / "sorter.mnt").exit_code == 0
    result = mint("run", EXAMPLES / "sorter.mnt", "--expect", EXAMPLES / "sorter.toml")
    assert result.exit_code == 0, result.output
    assert "All 5 expectations held." in result.stderr
    assert result.stdout.splitlines()[0].startswith("part 1 sorted at ")


def test_the_v3_palletiser_runs_as_v3_and_migrates_to_a_v4_program_that_checks_clean(tmp_path: Path) -> None:
    original = EXAMPLES / "palletiser_v3.mnt"
    boxes = "box 1\nbox 2\nbox 3\nbox 4\n"
    ran = mint("run", "--dialect", "v3", original)
    assert (ran.exit_code, ran.stdout) == (0, boxes)
    assert mint("migrate", "--check", original).exit_code == 1  # something to rewrite
    migrated = mint("migrate", "--stdout", original)
    assert migrated.exit_code == 0
    assert "HOMESPEED.0 = 20" in migrated.stdout and "HMSPEED" not in migrated.stdout
    program = tmp_path / "palletiser.mnt"
    program.write_text(migrated.stdout, encoding="utf-8")
    assert mint("check", program).exit_code == 0
    ran_v4 = mint("run", program)
    assert (ran_v4.exit_code, ran_v4.stdout) == (0, boxes)
