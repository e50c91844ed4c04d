"""Keys piped to ``mint-run``'s standard input answer ``INPUT`` and ``INKEY``, as an operator's typing would.

INPUT reads a number typed at the terminal; a non-numeric entry is asked for again, and a bare
return keeps the variable's value (000:12202-12220). INKEY returns 0 when no key waits, else the
key's code, with a-z upper-cased (000:12165-12171); ``PAUSE INKEY`` waits for a key
(000:1683-1689). A program still waiting for keys once standard input has ended is a deadlock.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest


def mint_run(program: Path, keys: bytes) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "mintlang.runtime", "-q", str(program)],
        input=keys,
        capture_output=True,
        timeout=120,
        check=False,
    )


def program(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "keys.mnt"
    path.write_text(text, encoding="utf-8")
    return path


SUM = 'DIM a = 5\nDIM b\nINPUT "a? ", a\nINPUT "b? ", b\nPRINT a + b\n'


@pytest.mark.parametrize(
    ("keys", "total"),
    [
        (b"12.5\n7\n", "19.5"),  # 12.5 + 7
        (b"12.5\r\n7\r\n", "19.5"),  # CR LF is one line end
        (b"abc\n2\n3\n", "5"),  # abc is refused and asked again: a = 2, b = 3
        (b"\n4\n", "9"),  # a bare return keeps a = 5
        (b"1\n2", "3"),  # the last line counts without its line end
    ],
)
def test_input_reads_the_numbers_piped_in(tmp_path: Path, keys: bytes, total: str) -> None:
    result = mint_run(program(tmp_path, SUM), keys)
    assert result.returncode == 0, result.stderr
    assert result.stdout.decode().splitlines()[-1] == total


def test_inkey_reads_each_key_upper_cased_and_pause_inkey_waits_for_one(tmp_path: Path) -> None:
    text = "DIM k\nPAUSE INKEY\nk = INKEY\nPRINT k\nk = INKEY\nPRINT k\n"
    result = mint_run(program(tmp_path, text), b"xa")  # PAUSE INKEY takes x; a is 65; then none is 0
    assert result.returncode == 0, result.stderr
    assert result.stdout.decode().split() == ["65", "0"]


def test_a_byte_above_127_is_one_key_with_its_own_code(tmp_path: Path) -> None:
    text = "DIM k\nPAUSE INKEY\nk = INKEY\nPRINT k\nk = INKEY\nPRINT k\n"
    result = mint_run(program(tmp_path, text), b"x\xe9\xff")  # no A-Z to upper-case: the codes as they are
    assert result.stdout.decode().split() == ["233", "255"]


def test_an_input_left_waiting_when_standard_input_ends_is_a_deadlock_that_says_so(tmp_path: Path) -> None:
    result = mint_run(program(tmp_path, SUM), b"1\n")
    assert result.returncode == 1
    stderr = result.stderr.decode()
    assert "deadlock" in stderr and "line 4" in stderr
    assert "standard input, which has ended" in stderr


def test_waiting_on_a_standard_input_that_never_ends_stops_at_the_wall_clock_limit(tmp_path: Path) -> None:
    arguments = [sys.executable, "-m", "mintlang.runtime", "-q", "--max-wall-s", "1", str(program(tmp_path, SUM))]
    with subprocess.Popen(arguments, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as running:
        try:
            running.wait(timeout=120)  # stdin stays open, with nothing written
        finally:
            running.kill()
        assert running.stderr is not None
        stderr = running.stderr.read().decode()
    assert running.returncode == 1
    assert "wall-limit" in stderr and "waiting for keys" in stderr


def test_a_cr_lf_split_between_two_writes_is_still_one_line_end(tmp_path: Path) -> None:
    arguments = [sys.executable, "-m", "mintlang.runtime", "-q", str(program(tmp_path, SUM))]
    with subprocess.Popen(arguments, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as running:
        assert running.stdin is not None
        running.stdin.write(b"1\r")
        running.stdin.flush()
        assert running.stdout is not None
        assert running.stdout.read(len(b"a? 1\nb? ")) == b"a? 1\nb? "  # a = 1 taken, b asked, before the LF
        stdout, _ = running.communicate(b"\n2\r\n", timeout=120)  # the late LF ends a's line, not b's
    assert stdout.decode().splitlines()[-1] == "3"  # 1 + 2


def test_a_number_too_large_even_for_a_double_is_asked_again(tmp_path: Path) -> None:
    result = mint_run(program(tmp_path, SUM), b"9" * 400 + b"\n3\n4\n")  # 10^400 is no binary32: a = 3, b = 4
    assert result.returncode == 0, result.stderr
    assert result.stdout.decode().splitlines()[-1] == "7"
