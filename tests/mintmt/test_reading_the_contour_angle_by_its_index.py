"""``CONTOURPARAMETER.axis.0`` reads the inter-vector angle it writes (004:223, 232; MT-11): v4's CONTOURANGLE,
15 degrees until written (000:8527). The note names no other index, so one is not guessed: reading it stops the run
as not simulated, as writing it does; without an index the read is the missing parameter mint check reports."""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source


def test_the_angle_reads_fifteen_degrees_before_it_is_written() -> None:
    assert (
        run_source('Print CONTOURPARAMETER(0,0), " ", CONTOURPARAMETER.1.0\n', dialect="mintmt").terminal == "15 15\n"
    )


def test_the_angle_reads_what_each_axis_was_given() -> None:
    source = (
        "CONTOURPARAMETER([0,1],0) = 10, 20;\nCONTOURANGLE(2) = 30\n"
        'Print CONTOURPARAMETER.1.0, " ", CONTOURPARAMETER(2,0)\n'
    )
    assert run_source(source, dialect="mintmt").terminal == "20 30\n"


def test_the_angle_read_in_an_expression() -> None:
    source = 'CONTOURPARAMETER.0.0 = 12\nIf CONTOURPARAMETER.0.0 + 3 = 15 Then Print "yes"\n'
    assert run_source(source, dialect="mintmt").terminal == "yes\n"


def test_an_index_the_note_does_not_name_is_not_simulated() -> None:
    stopped = run_source("Print CONTOURPARAMETER.0.1\n", dialect="mintmt").stop
    assert (stopped.reason, stopped.line) == (StopReason.ERROR, 1)
    assert "CONTOURPARAMETER (index 1) is not simulated" in stopped.message


def test_a_read_without_its_index_is_a_missing_parameter() -> None:
    assert run_source("Print CONTOURPARAMETER(0)\n", dialect="mintmt").err == 2001
