"""What a configuration file holds and the run never runs is said, at its file, line and column, not skipped in
silence.

A subroutine of the configuration file cannot be called from the program (000:1882, 11170), and an event
handler is such a subroutine (the reserved subroutine labels, 000:1886-1898): the run calls the configuration's
``#TIMER`` while the configuration runs (runtime/BEHAVIOUR.md, Handlers per file), never once the program runs.
A program with no handler of its own for that event then leaves it unhandled, which a reader of the
configuration would not guess. MintMT's Startup block is the code run at power-up (004:128-133) in the program;
the notes say nothing of one in a configuration file, and the run does not enter it.
"""

from __future__ import annotations

import json
from pathlib import Path

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.test_run_command import mint_run, write

# TIMEREVENT sets the period of #TIMER's calls (000:4994-5001); END in the configuration starts the program
# (000:9851-9852), which waits 100 ms with no #TIMER of its own.
_TIMED = "DIM n = 0\nTIMEREVENT = 10\nEND\n#TIMER\n  n = n + 1\nRETURN\n"
_WAITS = "WAIT = 100\nPRINT n\n"


def test_a_handler_of_the_configuration_file_the_program_lacks_is_named_at_its_label() -> None:
    result = run_source(_WAITS, config=_TIMED, config_name="cell.cfg", limits=Limits(until_ms=200))
    assert result.terminal.strip() == "0"  # the configuration's #TIMER never ran in the program
    [note] = result.not_run
    assert note.startswith("cell.cfg:4:1: #TIMER ")


def test_a_program_with_its_own_handler_has_nothing_to_say() -> None:
    program = _WAITS + "END\n#TIMER\nRETURN\n"
    assert run_source(program, config=_TIMED, limits=Limits(until_ms=200)).not_run == ()


def test_a_configuration_without_handlers_has_nothing_to_say() -> None:
    assert run_source(_WAITS, config="DIM n = 0\n", limits=Limits(until_ms=200)).not_run == ()


def test_a_mintmt_startup_block_in_the_configuration_file_is_named_at_its_opener() -> None:
    config = 'Print "cfg"\n  Startup\n  Print "cfg startup"\nEnd Startup\n'
    result = run_source('Print "main"\n', config=config, config_name="cell.cfg", dialect="mintmt")
    assert "cfg startup" not in result.terminal
    [note] = result.not_run
    assert note.startswith("cell.cfg:2:3: the Startup block ")


def test_mint_run_warns_on_stderr_and_in_its_report(tmp_path: Path) -> None:
    config = write(tmp_path, "cell.cfg", _TIMED)
    program = write(tmp_path, "main.mnt", _WAITS)
    result = mint_run(program, "--config", config, "--report", "json")
    assert f"warning: {config}:4:1: #TIMER " in result.stderr
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert len(report["not_run"]) == 1 and result.exit_code == 0
