"""S-IN: beside ``#INn`` handlers the inputs are read with INSTATE, which gives their state as v3 IN did.

v3 IN, INn and IN.n give the present state of the inputs (001:4288-4317, 001:8927-8947); ``#INn`` is
called on the falling edge (001:2525). S-INEDGE makes each handler's input edge triggered and negative
edge active in v4, and for such an input v4 IN and IN.n give the latched edge instead, clearing it when
read (000:11976-11978, 000:11985-11988, 000:11995-11996). INSTATE gives the state of every input, edge triggered or not,
and clears no latch (000:12487-12536): the v3 door handler ``PAUSE IN1 = 1`` waits for the door again.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import rewritten

HANDLER = "END\n#IN1\nRETURN\n"


@pytest.mark.parametrize(
    ("read", "state"),
    [
        ("PAUSE IN1 = 1", "PAUSE INSTATE.1 = 1"),  # the handler's own input
        ("x = in.1", "x = instate.1"),
        ("x = IN.a", "x = INSTATE.a"),  # any input, the handler's among them
        ("x = IN", "x = (INSTATE & 255)"),  # inputs 0..7, as v3 read them (001:8927-8947)
        ("b = IN & 15", "b = INSTATE & 15"),
        ("PAUSE IN AND 12", "PAUSE INSTATE AND 12"),
    ],
)
def test_beside_a_handler_an_input_is_read_by_its_state(read: str, state: str) -> None:
    assert rewritten("S-IN", f"{read}\n{HANDLER}") == f"{state}\n{HANDLER}"


@pytest.mark.parametrize("read", ["PAUSE IN2 = 1", "x = IN.2"])
def test_an_input_with_no_handler_stays_level_triggered_and_is_kept(read: str) -> None:
    assert rewritten("S-IN", f"{read}\n{HANDLER}") == f"{read}\n{HANDLER}"


def test_the_handlers_wait_for_its_input_is_a_wait_on_the_state() -> None:
    door = '#IN1\n  PRINT "door open"\n  PAUSE IN1 = 1\n  PRINT "door closed"\nRETURN\n'
    result = migrate("LOOP\nENDL\n" + door, controller="servonode51")
    assert "INPUTMODE = INPUTMODE | 2\n" in result.text  # S-INEDGE: input 1 is edge triggered
    assert "  PAUSE INSTATE.1 = 1\n" in result.text
    assert [item.rule for item in result.manual if item.rule == "S-IN"] == []


def test_migrating_the_output_again_changes_nothing() -> None:
    """INSTATE is a v4 word the v3 reader takes for a name; the migration only reads it, and v3 declares a
    name by assigning it (001:1352-1367), so it is no user's variable to rename on a second run."""
    source = "PAUSE (IN & 4) = 0\nSERVON\nEND\n#IN1\n  PAUSE IN1 = 1\nRETURN\n"  # SERVON: left for a person
    first = migrate(source)
    assert "PAUSE (INSTATE & 4) = 0\n" in first.text
    assert migrate(first.text).text == first.text
