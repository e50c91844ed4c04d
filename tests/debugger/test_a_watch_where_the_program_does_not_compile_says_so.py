"""Where the compiler refuses the program, the run stops on that error before anything runs: none of the program's
variables exist, so a watch or hover on one says that the program does not compile, and why, rather than that the
program has no such variable, which it declares (000:1074-1077). The controller's own values still read.
"""

from __future__ import annotations

from tests.debugger.conftest import Debug

REFUSED = """\
DIM x
x = 1
x = (x +
END
"""


def test_a_watch_on_a_declared_variable_names_the_compile_error(debug: Debug) -> None:
    client = debug(REFUSED)
    assert client.stopped()["reason"] == "exception"
    response = client.request("evaluate", {"expression": "x", "context": "hover", "frameId": 1})
    assert not response["success"]
    message = response["message"]
    assert "the program does not compile" in message
    assert "C2003: PROGRAM" in message and "[line 3]" in message
    assert client.evaluate("TIME") == "0"
