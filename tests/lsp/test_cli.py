"""``mint-lsp``'s command line: ``--version`` and a session over ``--tcp``."""

from __future__ import annotations

import json
import socket
import subprocess
import sys
import time

SERVER = [sys.executable, "-m", "mintlang.lsp"]


def test_version():
    result = subprocess.run([*SERVER, "--version"], capture_output=True, text=True, check=True, timeout=30)
    assert result.stdout.startswith("mint-lsp, version")


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def _connect(port: int) -> socket.socket:
    deadline = time.monotonic() + 20
    while True:
        try:
            return socket.create_connection(("127.0.0.1", port), timeout=20)
        except ConnectionRefusedError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.1)


def test_tcp_session_on_localhost():
    port = _free_port()
    server = subprocess.Popen([*SERVER, "--tcp", str(port)], stderr=subprocess.DEVNULL)
    try:
        with _connect(port) as connection:
            body = json.dumps({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
            connection.sendall(f"Content-Length: {len(body)}\r\n\r\n{body}".encode())
            answer = b""
            while b"hoverProvider" not in answer:
                chunk = connection.recv(65536)
                assert chunk, "the server closed the connection"
                answer += chunk
        assert b'"name":"mint-lsp"' in answer.replace(b" ", b"")
    finally:
        server.kill()
        server.wait(timeout=10)


def test_a_log_file_that_cannot_be_written_is_a_usage_error(tmp_path):
    missing = tmp_path / "no" / "such" / "server.log"
    result = subprocess.run(
        [*SERVER, "--log-file", str(missing)], capture_output=True, text=True, timeout=30, check=False
    )
    assert result.returncode == 2
    assert "cannot write" in result.stderr and "Traceback" not in result.stderr


def test_a_port_in_use_is_said_in_one_line():
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = subprocess.run([*SERVER, "--tcp", str(port)], capture_output=True, text=True, timeout=30, check=False)
    assert result.returncode == 2
    assert result.stderr.startswith(f"mint-lsp: cannot listen on 127.0.0.1:{port}")
    assert "Traceback" not in result.stderr
