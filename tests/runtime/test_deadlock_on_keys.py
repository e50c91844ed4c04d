"""An INPUT or a PAUSE on INKEY that no key will ever answer is a deadlock whose message says it waits for keys.

INPUT reads a number typed at a terminal into a variable (000:12202-12216); ``PAUSE INKEY``
waits for any key press and ``PAUSE INKEY = 'y'`` for that key (000:1683-1689). In the
simulation keys come only from a scenario, so a program waiting on keys with none to come
blocks for good (W-4); the message names the keys it waits for and where a scenario gives them.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.scenario import parse_directives
from tests.runtime.invoking import mint_run, write
from tests.runtime.running import simulate

SOURCE = 'DIM q\nINPUT "qty? ", q\nPRINT q * 2\n'


def test_an_input_no_scenario_answers_is_a_deadlock_that_says_it_waits_for_keys() -> None:
    result = simulate(SOURCE)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 2)
    assert "INPUT waits for keys that no scenario types" in result.stop.message
    assert "mint-run" not in result.stop.message  # the editor's and the debugger's runs show it too


def test_an_input_no_scenario_answers_is_a_deadlock_with_a_timer_running_too() -> None:
    # the #TIMER events that fall due while INPUT waits stay pending until it has its line (000:4397-4399),
    # so the timer can change nothing the program waits on: the first one sets the flag, then it is blocked for good
    result = simulate("DIM q\nDIM n\nTIMEREVENT = 100\nINPUT q\nEND\n#TIMER\nn = n + 1\nRETURN\n")
    assert (result.stop.reason, result.stop.line, result.stop.time_ms) == (StopReason.DEADLOCK, 4, 100)
    assert "INPUT waits for keys that no scenario types" in result.stop.message


def test_mint_run_with_no_standard_input_to_read_tells_how_to_give_keys(tmp_path: Path) -> None:
    # keys come from a scenario, a pipe or a terminal; the test runner's input is none of these
    result = mint_run(write(tmp_path, "qty.mnt", SOURCE))
    assert result.exit_code == 1
    assert "hint: keys can be piped to standard input: printf '42\\n' | mint-run PROGRAM" in result.output


def test_an_input_a_scenario_answers_reads_the_number() -> None:
    scenario, _ = parse_directives('REM @sim key "21\\r" at 10\n', "keys")
    result = simulate(SOURCE, scenario=scenario)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "qty? 21\n42\n")


@pytest.mark.parametrize("condition", ["INKEY", "INKEY = 'Y'", "(INKEY.1 <> 0) AND a = 0"])
def test_a_pause_on_inkey_no_scenario_answers_says_it_waits_for_keys(condition: str) -> None:
    result = simulate(f"DIM a\nPRINT 1\nPAUSE {condition}\nPRINT 2\n")
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 3)
    assert "PAUSE reads INKEY, which waits for keys that no scenario types" in result.stop.message


def test_a_pause_on_a_variable_alone_does_not_blame_keys_after_a_pause_on_inkey() -> None:
    result = simulate(
        "DIM a\nPAUSE INKEY\nPAUSE a = 1\n", scenario=parse_directives('REM @sim key "y" at 5\n', "keys")[0]
    )
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 3)
    assert "INKEY" not in result.stop.message


def test_a_pause_on_inkey_passes_on_the_key_a_scenario_types() -> None:
    scenario, _ = parse_directives('REM @sim key "y" at 10\n', "keys")
    result = simulate("PAUSE INKEY = 'Y'\nPRINT 2\n", scenario=scenario)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "2\n")
