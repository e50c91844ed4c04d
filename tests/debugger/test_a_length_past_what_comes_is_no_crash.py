"""A Content-Length larger than what the client sends, or negative, gets no traceback.

Bad requests get error responses, never a crash (README.md, "Debugging": an editor talks to mint-dap
on stdin and stdout). A header claiming 99,999,999,999 bytes made mint-dap allocate them before reading
any, and it died with a MemoryError; a negative one was reported as a missing header.
"""

from __future__ import annotations

import subprocess

from tests.debugger.client import TIMEOUT_S, adapter_command


def _adapter(given: bytes) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(adapter_command(), input=given, capture_output=True, timeout=TIMEOUT_S, check=False)


def test_a_length_past_the_end_of_the_input_ends_the_session_quietly() -> None:
    ran = _adapter(b"Content-Length: 99999999999\r\n\r\n{}")
    assert (ran.returncode, ran.stderr) == (0, b"")


def test_a_negative_length_is_reported_as_one() -> None:
    ran = _adapter(b"Content-Length: -5\r\n\r\n")
    assert ran.returncode == 0
    assert b"Content-Length is not a length in bytes: b'-5'" in ran.stdout
