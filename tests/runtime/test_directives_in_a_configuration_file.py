"""``REM @sim`` and ``REM @expect`` are read from the program only; in its configuration file each is a warning.

A scenario is written in a TOML file or "in the program itself" (runtime/scenario/README.md, the two
places a scenario can be written), and directives exist so that "a mistyped check never passes
unnoticed" (its "Directives in the program"). One written in the configuration file is not applied,
and mint-run says so at its file, line and column (that of its ``@``, from 1, counted by hand).
"""

from __future__ import annotations

import json
from pathlib import Path

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.test_run_command import mint_run, write

_CONFIG = "RESETALL\nREM @sim drives enabled\nRESETALL : REM @expect a = 2\nREM @author the cell's builder\n"


def test_a_directive_in_the_configuration_is_not_applied_and_is_named_at_its_place() -> None:
    result = run_source("DIM a = 1\n", config=_CONFIG, config_name="cell.cfg", limits=Limits(until_ms=100))
    assert result.outcomes == ()
    assert [note.split(": ")[0] for note in result.ignored_directives] == ["cell.cfg:2:5", "cell.cfg:3:16"]


def test_a_configuration_with_plain_comments_has_nothing_ignored() -> None:
    result = run_source("DIM a = 1\n", config="REM the cell\nRESETALL\n", limits=Limits(until_ms=100))
    assert result.ignored_directives == ()


def test_the_program_s_own_directives_are_still_read() -> None:
    result = run_source("DIM a = 1\nREM @expect a = 1\n", config=_CONFIG, limits=Limits(until_ms=100))
    assert [outcome.held for outcome in result.outcomes] == [True]


def test_mint_run_warns_on_stderr_and_in_its_report(tmp_path: Path) -> None:
    config = write(tmp_path, "cell.cfg", "REM @expect a = 2\n")
    program = write(tmp_path, "main.mnt", "DIM a = 1\n")
    result = mint_run(program, "--config", config, "--report", "json")
    assert f"warning: {config}:1:5: @expect is read only from the program" in result.stderr
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert len(report["ignored_directives"]) == 1 and result.exit_code == 0
