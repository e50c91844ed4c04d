"""MintMT keywords that take an index after their axes must be given it.

The move buffer note loads output moves as ``MOVEOUT(axis, bank)``, ``MOVEOUTX(axis, channel)`` and
``MOVEPULSEOUTX(axis, channel)`` (004:293-301), each on the one axis whose buffer holds it, and sets the
inter-vector angle with ``CONTOURPARAMETER(axes, 0)`` (004:223, 232). Written without that index
(``MOVEOUT(0) = 7``, a bank-less write to axis 0) it is a missing parameter (#2001, at the brackets), in
``mint check`` and when the line runs in ``mint-run``; an output move listing two axes is #2017. So is
such a keyword written bare (``MOVEOUT = 7``: the default axes stand for its axes, nothing for its index),
and ``OUTX``, one output channel (004:148), written without its channel: mint check let both pass.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("MOVEOUT(0) = 7\n", [("E2001", 1, 8)], id="moveout-without-bank"),
        pytest.param("MOVEOUT.0 = 7\n", [("E2001", 1, 8)], id="moveout-v4-dot-without-bank"),
        pytest.param("MOVEOUTX(1) = 0\n", [("E2001", 1, 9)], id="moveoutx-without-channel"),
        pytest.param("MOVEPULSEOUTX(0) = 100\n", [("E2001", 1, 14)], id="movepulseoutx-without-channel"),
        pytest.param("CONTOURPARAMETER(0) = 10\n", [("E2001", 1, 17)], id="contourparameter-without-index"),
        pytest.param("CONTOURPARAMETER([0,1]) = 10;\n", [("E2001", 1, 17)], id="axis-list-without-index"),
        pytest.param("MOVEOUTX(0,1,3) = 1\n", [("E2017", 1, 9)], id="output-move-on-two-axes"),
        pytest.param("MOVEOUT = 7\n", [("E2001", 1, 1)], id="moveout-bare"),
        pytest.param("CONTOURPARAMETER = 10\n", [("E2001", 1, 1)], id="contourparameter-bare"),
        pytest.param("OUTX = 1\n", [("E2001", 1, 1)], id="outx-written-without-channel"),
        pytest.param("PRINT OUTX\n", [("E2001", 1, 7)], id="outx-read-without-channel"),
    ],
)
def test_a_missing_index_or_a_second_axis_is_an_error(source: str, expected: list[tuple[str, int, int]]) -> None:
    assert placed_codes(source, "mintmt") == expected


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("MOVEOUT(0,0) = 7\n", id="moveout-as-the-note-writes-it"),
        pytest.param("MOVEOUTX(2,1) = 0\n", id="moveoutx-on-axis-2"),
        pytest.param("MOVEPULSEOUTX(0,3) = 100\n", id="movepulseoutx"),
        pytest.param("CONTOURPARAMETER([0,1],0) = 10;\n", id="contourparameter-on-two-axes"),
    ],
)
def test_the_notes_forms_are_clean(source: str) -> None:
    assert placed_codes(source, "mintmt") == []


@pytest.mark.parametrize("line", ["MOVEOUT = 7", "OUTX = 1", "PRINT OUTX"])
def test_running_it_bare_is_the_same_missing_parameter(line: str) -> None:
    result = run_source(f"REM @sim drives enabled\nMOVEBUFFERSIZE(0) = 2\n{line}\n", dialect="mintmt")
    assert (result.err, result.erl, result.stop.line) == (2001, 3, 3)


def test_running_an_output_move_without_its_bank_is_a_missing_parameter() -> None:
    result = run_source("REM @sim drives enabled\nMOVEBUFFERSIZE(0) = 2\nMOVEOUT(0) = 7\n", dialect="mintmt")
    assert (result.err, result.erl, result.stop.line) == (2001, 3, 3)
