"""A request naming a thread the program does not have fails, saying which thread there is.

The program is one thread (its threads response lists only it); the DAP specification has a request that cannot
be served answered with ``success`` false and a ``message``, as for any other argument that names nothing.
"""

from __future__ import annotations

import pytest

from tests.debugger.conftest import Debug


@pytest.mark.parametrize(
    ("command", "thread"),
    [
        pytest.param("stackTrace", 2, id="stack-trace-of-thread-2"),
        pytest.param("next", 0, id="next-on-thread-0"),
        pytest.param("continue", 7, id="continue-thread-7"),
        pytest.param("stepIn", "1", id="a-thread-named-as-text"),
    ],
)
def test_the_request_fails_and_the_program_stays_where_it_is(debug: Debug, command: str, thread: object) -> None:
    client = debug("DIM x\nx = 1\nx = 2\n", stopOnEntry=True)
    client.stopped()
    response = client.request(command, {"threadId": thread})
    assert not response["success"]
    assert response["message"] == f"there is no thread {thread!r}: the program is thread 1"
    assert client.line() == 1


def test_the_one_thread_is_served(debug: Debug) -> None:
    client = debug("DIM x\nx = 1\nx = 2\n", stopOnEntry=True)
    client.stopped()
    (thread,) = client.body("threads")["threads"]
    assert client.body("stackTrace", {"threadId": thread["id"]})["stackFrames"][0]["line"] == 1
