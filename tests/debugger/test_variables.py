"""What the Variables view shows of the paused controller, and what the editor may set there."""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug

MOVE = """\
DIM n
DIM table(300)
table(101) = 7
OUT.1 = 1
MOVEA.0 = 10 : GO.0
PAUSE IDLE.0
n = POS.0
PRINT n
"""


def test_each_axis_shows_what_the_program_would_read_of_it(debug: Debug) -> None:
    client = debug(MOVE, breakpoints=(7,), drives="enabled")
    client.stopped()
    axes = client.body("variables", {"variablesReference": client.scope("Axes")})["variables"]
    assert axes[0]["name"] == "axis 0"
    axis = client.variables(axes[0]["variablesReference"])
    assert (axis["POS"], axis["VEL"], axis["IDLE"], axis["AXISERROR"]) == ("10", "0", "1", "0")
    assert client.evaluate("POS.0 * 2") == "20"


@pytest.mark.parametrize("frame", [pytest.param(0, id="zero"), pytest.param(2, id="past-the-program")])
def test_scopes_of_a_frame_the_stop_does_not_have_fail(debug: Debug, frame: int) -> None:
    # stopped in the program with no call open, the stack holds one frame, id 1 (DAP: a frameId from stackTrace)
    client = debug(MOVE, breakpoints=(7,), drives="enabled")
    client.stopped()
    response = client.request("scopes", {"frameId": frame})
    assert (response["success"], response["message"]) == (False, f"no frame {frame} at this stop")


def test_arrays_page_their_elements_from_one(debug: Debug) -> None:
    client = debug(MOVE, breakpoints=(7,), drives="enabled")
    client.stopped()
    (table,) = client.body("variables", {"variablesReference": client.scope("Arrays")})["variables"]
    assert (table["name"], table["value"], table["indexedVariables"]) == ("table", "array(300)", 300)
    assert client.variables(table["variablesReference"], start=99, count=3) == {
        "(100)": "0",
        "(101)": "7",
        "(102)": "0",
    }


FILTERS = [
    pytest.param("indexed", ["(1)", "(2)", "(3)"], [], id="indexed: an array's elements, no variable"),
    pytest.param("named", [], ["n"], id="named: no element of an array, each variable"),
]


@pytest.mark.parametrize(("kind", "elements", "variables"), FILTERS)
def test_a_filter_lists_only_the_children_of_its_kind(
    debug: Debug, kind: str, elements: list[str], variables: list[str]
) -> None:
    """DAP's ``variables`` filter: an array's children are indexed, a scope of variables' are named."""
    client = debug(MOVE, breakpoints=(7,), drives="enabled")
    client.stopped()
    (table,) = client.body("variables", {"variablesReference": client.scope("Arrays")})["variables"]
    listed = client.body("variables", {"variablesReference": table["variablesReference"], "filter": kind, "count": 3})
    assert [variable["name"] for variable in listed["variables"]] == elements
    scalars = client.body("variables", {"variablesReference": client.scope("Variables"), "filter": kind})
    assert [variable["name"] for variable in scalars["variables"]] == variables


def test_the_io_scope_shows_outputs_as_a_bank(debug: Debug) -> None:
    client = debug(MOVE, breakpoints=(7,), drives="enabled")
    client.stopped()
    io = client.variables(client.scope("I/O"))
    assert io["OUT"].endswith("10 (2)")
    assert io["IN"].endswith("0 (0)")


def test_the_io_scope_shows_an_analog_input_turned_off_at_the_value_adc_reads(debug: Debug) -> None:
    # 000:6456-6457: a channel turned off (ADCMODE 4) reads the last value read while it was on
    source = "REM @sim adc 0 50 at 10\nREM @sim adc 0 25 at 30\nWAIT = 20\nADCMODE.0 = 4\nWAIT = 20\nPRINT ADC.0\n"
    client = debug(source, breakpoints=(6,))
    client.stopped()
    assert client.variables(client.scope("I/O"))["ADC.0"] == "50"


def test_setting_an_element_and_a_comms_value_changes_what_the_program_reads(debug: Debug) -> None:
    client = debug("DIM t(3)\nDIM s\ns = t(2) + COMMS(5)\nPRINT s\n", breakpoints=(3,))
    client.stopped()
    (array,) = client.body("variables", {"variablesReference": client.scope("Arrays")})["variables"]
    client.body("setVariable", {"variablesReference": array["variablesReference"], "name": "(2)", "value": "1.5"})
    client.body("setVariable", {"variablesReference": client.scope("Comms"), "name": "(5)", "value": "2 * 10"})
    assert client.evaluate("COMMS(5)") == "20"
    client.step("next")
    assert client.values()["s"] == "21.5"


def test_values_show_the_shortest_decimal_of_the_binary32_the_controller_holds(debug: Debug) -> None:
    client = debug("DIM x\nx = 0.1\nx = x * 3\nPRINT x\n", breakpoints=(3,))
    client.stopped()
    assert client.values()["x"] == "0.1"
    client.step("next")
    assert client.values()["x"] == "0.3"  # binary32 0.1 * 3 rounds to binary32 0.3


def test_a_value_that_is_not_an_element_or_not_a_number_is_refused(debug: Debug) -> None:
    client = debug("DIM t(3)\nDIM s\ns = 1\n", breakpoints=(3,))
    client.stopped()
    (array,) = client.body("variables", {"variablesReference": client.scope("Arrays")})["variables"]
    refused = client.request(
        "setVariable", {"variablesReference": array["variablesReference"], "name": "(4)", "value": "1"}
    )
    assert not refused["success"] and "outside 1 to 3" in refused["message"]
    refused = client.request(
        "setVariable", {"variablesReference": client.scope("Variables"), "name": "s", "value": "x +"}
    )
    assert not refused["success"] and "Syntax error" in refused["message"]
    refused = client.request(
        "setVariable", {"variablesReference": client.scope("Axes"), "name": "axis 0", "value": "1"}
    )
    assert not refused["success"]


BUFFERED = """\
MOVEBUFFERSIZE.0 = 3
MOVEA.0 = 10 : GO.0
MOVEA.0 = 20
MOVEA.0 = 5
PAUSE IDLE.0
"""


def _move_buffer(client) -> dict:
    axes = client.body("variables", {"variablesReference": client.scope("Axes")})["variables"]
    values = client.body("variables", {"variablesReference": axes[0]["variablesReference"]})["variables"]
    (buffer,) = [value for value in values if value["name"] == "move buffer"]
    return buffer


def test_each_axis_shows_its_move_running_and_those_loaded_behind_it(debug: Debug) -> None:
    client = debug(BUFFERED, breakpoints=(5,), drives="enabled")
    client.stopped()
    assert _move_buffer(client)["value"] == "no move running, 3 loaded"  # GO starts it at the next profiler tick
    client.body("runFor", {"ms": 4})
    client.stopped()
    buffer = _move_buffer(client)
    assert buffer["value"] == "a move running, 2 loaded"
    moves = client.variables(buffer["variablesReference"])
    assert list(moves) == ["running", "(1)", "(2)"]
    assert moves["(1)"].endswith("axes [0], to 20") and moves["(2)"].endswith("axes [0], to 5")


def test_an_empty_move_buffer_offers_nothing_to_expand(debug: Debug) -> None:
    client = debug("DIM x\nx = 1\n", breakpoints=(2,))
    client.stopped()
    buffer = _move_buffer(client)
    assert buffer["value"] == "no move running, 0 loaded" and buffer["variablesReference"] == 0


SPELLED = [
    pytest.param("REM the count of boxes\nDIM Count\nCount = 1\nPRINT Count\n", "v4", id="a REM comment before it"),
    pytest.param('PRINT "count"\nDIM Count\nCount = 1\nPRINT Count\n', "v4", id="a string before it"),
    pytest.param("' the count of boxes\nDim Count\nCount = 1\nPrint Count\n", "mintmt", id="a MintMT ' comment"),
]


@pytest.mark.parametrize(("source", "dialect"), SPELLED)
def test_a_name_is_shown_as_the_code_spells_it_not_as_a_comment_or_string_does(
    debug: Debug, source: str, dialect: str
) -> None:
    client = debug(source, breakpoints=(4,), dialect=dialect)
    client.stopped()
    assert client.values() == {"Count": "1"}


def test_a_mintmt_events_frame_is_named_as_its_event_line_spells_it(debug: Debug) -> None:
    source = "' the timer ticks\nDim ticks\nTIMEREVENT = 10\nPause ticks >= 1\n\nEvent TIMER\n  ticks = 1\nEnd Event\n"
    client = debug(source, breakpoints=(7,), dialect="mintmt")
    client.stopped()
    assert [frame["name"] for frame in client.frames()] == ["#TIMER", "program"]


BOTH = """\
DIM t(3) = 1,2,3
DIM u(2)
DIM k
t = 5
k = t + t(2)
PRINT k
"""


def test_an_arrays_name_the_program_uses_as_a_variable_is_a_variable_too(debug: Debug) -> None:
    # 000:1086-1087: an array's name is also a variable of its own; u is never used as one
    client = debug(BOTH, breakpoints=(5,))
    client.stopped()
    assert client.values() == {"k": "0", "t": "5"}
    (t, _) = client.body("variables", {"variablesReference": client.scope("Arrays")})["variables"]
    assert client.variables(t["variablesReference"]) == {"(1)": "1", "(2)": "2", "(3)": "3"}
    client.body("setVariable", {"variablesReference": client.scope("Variables"), "name": "t", "value": "10"})
    client.step("next")
    assert client.values() == {"k": "12", "t": "10"}
