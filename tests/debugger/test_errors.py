"""Run-time errors stop the debugger where they happen; a request it cannot serve gets an error response."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.debugger.client import DapClient
from tests.debugger.conftest import Debug

UNHANDLED = """\
DIM t(2)
DIM x
x = 1
x = t(5)
PRINT "never"
"""

HANDLED = """\
DIM x
DIM y
x = POS.12
END
#ONERROR
  x = ERR
RETURN
"""


def test_an_error_that_ends_the_run_stops_at_its_line_before_the_run_ends(debug: Debug) -> None:
    client = debug(UNHANDLED)
    stop = client.stopped()
    assert stop["reason"] == "exception"
    assert "2016" in stop["description"]
    assert client.line() == 4
    assert client.values()["x"] == "1"
    client.body("continue", {"threadId": 1})
    assert client.event("exited")["body"]["exitCode"] == 1
    client.event("terminated")
    assert "never" not in client.output()


def test_stepping_back_from_the_error_that_ended_the_run_goes_to_the_statement_before(debug: Debug) -> None:
    client = debug(UNHANDLED)
    client.stopped()
    client.step("stepBack")
    assert client.line() == 4  # the failing statement, about to run
    client.step("stepBack")
    assert (client.line(), client.values()["x"]) == (3, "0")


def test_with_every_error_chosen_an_error_onerror_handles_stops_before_the_handler_runs(debug: Debug) -> None:
    client = debug(HANDLED, stopOnEntry=True)
    client.stopped()
    client.body("setExceptionBreakpoints", {"filters": ["errors", "unhandled"]})
    client.body("continue", {"threadId": 1})
    stop = client.stopped()
    assert (stop["reason"], client.line()) == ("exception", 3)
    client.step("next")  # axis 12 is invalid: the system error 2, after which the program goes on (000:4616-4618)
    assert client.line() == 4
    assert client.values()["x"] == "2"


@pytest.mark.parametrize(
    ("failing", "err"),
    [
        pytest.param("POS.12", "2", id="invalid-axis"),  # 000:9953-9956: an axis the controller lacks is error 2
        pytest.param("t(5)", "2016", id="index-past-the-array"),
    ],
)
def test_at_the_stop_on_an_error_err_and_erl_already_name_it(debug: Debug, failing: str, err: str) -> None:
    # ERR is the last error that occurred and ERL its line (000:9884-9886, 9904, 9923): at the stop the error
    # has occurred, though #ONERROR has not run yet
    client = debug(HANDLED.replace("POS.12", failing).replace("DIM y", "DIM t(2)"), stopOnEntry=True)
    client.stopped()
    assert (client.evaluate("ERR"), client.evaluate("ERL")) == ("-1", "0")  # no error yet (000:18510)
    client.body("setExceptionBreakpoints", {"filters": ["errors"]})
    client.body("continue", {"threadId": 1})
    assert (client.stopped()["reason"], client.line()) == ("exception", 3)
    assert (client.evaluate("ERR"), client.evaluate("ERL"), client.values()["x"]) == (err, "3", "0")


def test_an_interpreter_error_stops_again_where_it_ends_the_run_once_onerror_returns(debug: Debug) -> None:
    # 000:4614-4619: #ONERROR runs for the invalid index, then the program terminates on it
    client = debug(HANDLED.replace("POS.12", "t(5)").replace("DIM y", "DIM t(2)"), stopOnEntry=True)
    client.stopped()
    client.body("setExceptionBreakpoints", {"filters": ["errors", "unhandled"]})
    client.body("continue", {"threadId": 1})
    assert (client.stopped()["reason"], client.line()) == ("exception", 3)
    stop = client.step("next")
    assert (stop["reason"], client.line(), client.values()["x"]) == ("exception", 3, "2016")
    assert "2016" in stop["description"]
    client.body("continue", {"threadId": 1})
    assert client.event("exited")["body"]["exitCode"] == 1


def test_without_the_unhandled_filter_the_run_just_ends(debug: Debug) -> None:
    client = debug(UNHANDLED, stopOnEntry=True)
    client.stopped()
    client.body("setExceptionBreakpoints", {"filters": []})
    client.body("continue", {"threadId": 1})
    assert client.event("exited")["body"]["exitCode"] == 1
    ending = [body["output"] for body in client.outputs() if body["category"] == "console"]
    assert any(line.startswith("error after") and "line 4" in line for line in ending)


def test_requests_that_need_a_paused_program_are_refused_while_it_runs(debug: Debug) -> None:
    client = debug("LOOP\nENDL\n")
    for command, arguments in [("stackTrace", {"threadId": 1}), ("evaluate", {"expression": "1"}), ("next", {})]:
        response = client.request(command, arguments)
        assert not response["success"]
        assert response["message"] == "the program is not paused"


def test_an_unknown_request_and_one_before_launch_get_error_responses() -> None:
    client = DapClient()
    client.body("initialize", {"adapterID": "mint"})
    unknown = client.request("goto", {"threadId": 1, "targetId": 1})
    assert not unknown["success"] and "not supported" in unknown["message"]
    early = client.request("setBreakpoints", {"source": {"path": "x.mnt"}, "breakpoints": []})
    assert not early["success"] and early["message"] == "launch a program first"
    assert "Traceback" not in client.close()


def test_a_launch_after_an_initialize_counting_lines_from_0_is_refused(tmp_path: Path) -> None:
    # mint-dap counts lines from 1, as the guide numbers them (ERL): a client counting from 0 would be one off
    program = tmp_path / "p.mnt"
    program.write_text("DIM x\n", encoding="utf-8")
    client = DapClient()
    refused = client.request("initialize", {"adapterID": "mint", "linesStartAt1": False})
    assert not refused["success"]
    launch = client.request("launch", {"program": str(program)})
    assert (launch["success"], launch["message"]) == (
        False,
        "no initialize has succeeded: send initialize, counting lines from 1, first",
    )
    assert "Traceback" not in client.close()


def test_a_launch_it_cannot_start_says_why(tmp_path: Path) -> None:
    program = tmp_path / "p.mnt"
    program.write_text("DIM x\n", encoding="utf-8")
    client = DapClient()
    client.body("initialize", {"adapterID": "mint"})
    problems = {
        "no program": client.request("launch", {}),
        "missing": client.request("launch", {"program": str(tmp_path / "absent.mnt")}),
        "dialect": client.request("launch", {"program": str(program), "dialect": "v5"}),
        "controller": client.request("launch", {"program": str(program), "controller": "euroservo"}),
        "stimulus": client.request("launch", {"program": str(program), "stimulus": [str(tmp_path / "none.toml")]}),
        # drives takes "enabled", as mint-run --drives enabled; stopOnEntry and noConfig are true or false
        "drives": client.request("launch", {"program": str(program), "drives": True}),
        "stopOnEntry": client.request("launch", {"program": str(program), "stopOnEntry": "false"}),
        "noConfig": client.request("launch", {"program": str(program), "noConfig": "yes"}),
        "nul": client.request("launch", {"program": str(program), "stimulus": ["a\0.toml"]}),
    }
    assert not any(response["success"] for response in problems.values())
    assert "'program'" in problems["no program"]["message"]
    assert "cannot read the program" in problems["missing"]["message"]
    assert "'v5' is not one of" in problems["dialect"]["message"]
    assert "controller of the Mint v3 guide" in problems["controller"]["message"]
    assert "none.toml" in problems["stimulus"]["message"]
    assert (
        problems["drives"]["message"]
        == "'drives' is \"enabled\" (every drive enabled at the start) or absent, not True"
    )
    assert problems["stopOnEntry"]["message"] == "'stopOnEntry' is true or false, not 'false'"
    assert problems["noConfig"]["message"] == "'noConfig' is true or false, not 'yes'"
    assert problems["nul"]["message"] == "'stimulus' 'a\\x00.toml' holds a NUL character: it is no file's path"
    assert "Traceback" not in client.close()


def test_a_malformed_request_is_refused_with_what_it_should_have_been(debug: Debug) -> None:
    # DAP: a stack trace's startFrame and levels are numbers; breakpoints a list; a variables filter named or
    # indexed (a bad line fails its breakpoint alone: test_breakpoints)
    client = debug("DIM x\nx = 1\n", stopOnEntry=True)
    client.stopped()
    source = {"path": str(client.program)}
    refused = {
        "list": client.request("setBreakpoints", {"source": source, "breakpoints": "2"}),
        "source": client.request("setBreakpoints", {"source": "p.mnt", "breakpoints": []}),
        "filters": client.request("setExceptionBreakpoints", {"filters": "errors"}),
        "filter names": client.request("setExceptionBreakpoints", {"filters": [["errors"]]}),
        "filter name": client.request("setExceptionBreakpoints", {"filters": ["all"]}),
        "objects": client.request("setFunctionBreakpoints", {"breakpoints": ["TIMER"]}),
        "startFrame": client.request("stackTrace", {"threadId": 1, "startFrame": "x"}),
        "start": client.request("variables", {"variablesReference": 1, "start": "first"}),
        "filter": client.request("variables", {"variablesReference": 1, "filter": "all"}),
        "reference": client.request("setVariable", {"variablesReference": "x", "name": "x", "value": "2"}),
    }
    assert {name: response["message"] for name, response in refused.items()} == {
        "list": "'breakpoints' is a list",
        "source": '\'source\' is an object, such as {"path": "cell.mnt"}',
        "filters": "'filters' is a list",
        "filter names": "'filters' is a list of names: errors, unhandled",
        "filter name": "no exception filter all: use errors or unhandled",
        "objects": "'breakpoints' is a list of objects",
        "startFrame": "'startFrame' is a whole number, 0 or more, not 'x'",
        "start": "'start' is a whole number, 0 or more, not 'first'",
        "filter": "'filter' is named or indexed, not 'all'",
        "reference": "'variablesReference' is a whole number, 0 or more, not 'x'",
    }
    assert client.line() == 1


@pytest.mark.parametrize(
    ("body", "report"),
    [
        pytest.param(b"hello", "the message body is not JSON", id="not-json"),
        pytest.param(b"[" * 100_000 + b"]" * 100_000, "the message body is nested too deeply to read", id="deep"),
    ],
)
def test_a_message_that_is_not_dap_is_reported_and_the_session_goes_on(body: bytes, report: str) -> None:
    client = DapClient()
    assert client.process.stdin is not None
    client.process.stdin.write(b"Content-Length: %d\r\n\r\n%s" % (len(body), body))
    client.process.stdin.flush()
    assert report in client.event("output")["body"]["output"]
    assert client.body("initialize", {"adapterID": "mint"})["supportsStepBack"]
    assert "Traceback" not in client.close()


def test_a_program_blocked_for_ever_stops_where_it_waits(debug: Debug) -> None:
    client = debug("DIM a\nPAUSE IN.3\na = 1\n")
    stop = client.stopped()
    assert stop["reason"] == "exception"
    assert "blocked" in stop["description"]
    assert client.line() == 2
