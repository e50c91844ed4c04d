"""A host packet addressed to a system element (100 to 255) is told how to check that element instead.

A host packet gives its comms address in two digits (000:2485-2487, 2522-2524), so elements 100 to 255, which
map system parameters such as the axes' positions (000:2566-2570), are out of its reach; what they show is
checked by an expectation of ``COMMS(n)``, which reads the mapped parameter. ``host read 130`` was told only
that 130 "does not fit two digits", at the directive's ``@``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.scenario import ScenarioError, load_scenario, parse_directives
from mintlang.runtime.scenario.problems import ScenarioFileError
from tests.runtime.invoking import mint_run, write

TOLD = "a host packet's address has two digits (0 to 99), so it cannot reach comms element {0}: " + (
    "to check that system element, expect COMMS({0})"
)


@pytest.mark.parametrize(("directive", "address"), [("host read 130 at 5", 130), ('host write 220 "1" at 5', 220)])
def test_a_directive_is_told_at_its_address(directive: str, address: int) -> None:
    _, problems = parse_directives(f"REM @sim {directive}\n")
    column = 1 + len(f"REM @sim {directive}".split(str(address))[0])
    assert problems == [ScenarioError("program", 1, TOLD.format(address), column)]


def test_a_scenario_file_is_told_at_its_address_key(tmp_path: Path) -> None:
    path = write(tmp_path, "cell.scenario.toml", "[[host]]\nat_ms = 5\nread = 100\n")
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    assert [str(error) for error in raised.value.errors] == [f"{path}:3: {TOLD.format(100)}"]


def test_the_expectation_it_is_told_of_reads_the_element(tmp_path: Path) -> None:
    """Element 130 is axis 2's position (000:2579, 2594): 500 after a move to 500."""
    program = write(
        tmp_path,
        "move.mnt",
        "REM @sim drives enabled\nREM @expect COMMS(130) = 500\nMOVEA.2 = 500 : GO.2 : PAUSE IDLE.2\n",
    )
    result = mint_run(program)
    assert result.exit_code == 0, result.output


def test_an_expectation_of_another_node_s_element_is_told_the_element_of_this_one() -> None:
    """``COMMS(node, index)`` reaches another node over CANopen (000:2553-2559), as the guide's ``comms(4,130)``
    (000:2670-2672); a run has one controller, and that spelling was told only that the run had no such thing."""
    _, problems = parse_directives("REM @expect COMMS(4,130) = 0\n")
    message = "COMMS(4,130) reads node 4 over the network, and a run simulates one controller: expect COMMS(130)"
    assert problems == [ScenarioError("program", 1, message, 13)]
