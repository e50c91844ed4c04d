"""An element of an array the program does not declare is refused as a name the program lacks is: a condition
naming one leaves its breakpoint unverified when it is set, and a watch says so, as the compiler refuses it in a
line. An array is reserved by DIM before it is used (000:1074-1077); its name alone is also a variable
(000:1086-1087), but a variable is not an array.
"""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug

PROGRAM = """\
DIM s
DIM table(3) = 1, 2, 3
s = table(2)
PRINT s
"""

NO_ARRAYS = [
    pytest.param("nosuch(2) = 1", "nosuch is not an array of the program", id="a name the program does not declare"),
    pytest.param("s(1) > 0", "s is not an array of the program", id="a variable, not an array"),
]


@pytest.mark.parametrize(("condition", "why"), NO_ARRAYS)
def test_a_condition_on_an_element_of_no_array_leaves_the_breakpoint_unverified(
    debug: Debug, condition: str, why: str
) -> None:
    client = debug(PROGRAM)
    (placed,) = client.set_breakpoints({"line": 3, "condition": condition})
    assert not placed["verified"]
    assert why in placed["message"]


def test_a_watch_on_an_element_of_no_array_says_the_program_has_no_such_array(debug: Debug) -> None:
    client = debug(PROGRAM, breakpoints=(4,))
    client.stopped()
    response = client.request("evaluate", {"expression": "nosuch(1)", "context": "watch", "frameId": 1})
    assert not response["success"]
    assert response["message"] == "nosuch is not an array of the program"
    assert client.evaluate("table(2) + table") == "2"  # the array's element, and its name as a variable (0)
