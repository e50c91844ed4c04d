"""An INPUT no keys will ever answer is a deadlock whose message says it waits for keys.

INPUT reads a number typed at a terminal into a variable (000:12202-12216). In the
simulation keys come only from a scenario, so an INPUT with none to come blocks for
good (W-4); the message names the keys it waits for and where a scenario gives them.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.scenario import parse_directives
from tests.runtime.running import simulate

SOURCE = 'DIM q\nINPUT "qty? ", q\nPRINT q * 2\n'


def test_an_input_no_scenario_answers_is_a_deadlock_that_says_it_waits_for_keys() -> None:
    result = simulate(SOURCE)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 2)
    assert "INPUT waits for keys that no scenario types" in result.stop.message


def test_an_input_a_scenario_answers_reads_the_number() -> None:
    scenario, _ = parse_directives('REM @sim key "21\\r" at 10\n', "keys")
    result = simulate(SOURCE, scenario=scenario)
    assert (result.stop.reason, result.terminal) == (StopReason.END, "qty? 21\n42\n")
