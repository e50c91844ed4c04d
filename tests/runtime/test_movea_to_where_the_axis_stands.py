"""MOVEA to the position an axis already stands at generates no move (000:14524-14525): nothing takes a place in
its move buffer (000:2978-2983), so loading it again never waits for room (000:14525-14527)."""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate


def test_a_movea_to_the_axis_position_leaves_its_buffer_free() -> None:
    # a buffer of 2 with nothing in it keeps both places
    assert simulate("MOVEBUFFERSIZE.0 = 2\nMOVEA.0 = 0\nPRINT MOVEBUFFERFREE.0\n").terminal == "2\n"


def test_loading_it_more_often_than_the_buffer_holds_does_not_wait() -> None:
    source = 'MOVEBUFFERSIZE.0 = 2\nMOVEA.0 = 0\nMOVEA.0 = 0\nMOVEA.0 = 0\nPRINT "loaded"\n'
    result = simulate(source)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "loaded\n"


def test_after_a_move_the_axis_stands_at_its_end() -> None:
    # MOVER 100 then GO: at rest on 100 (000:14605-14611), so MOVEA 100 generates nothing
    source = "MOVER.0 = 100 : GO.0\nPAUSE IDLE.0\nMOVEA.0 = 100\nPRINT MOVEBUFFERFREE.0; AXISMODE.0\n"
    assert simulate(source).terminal == "2       0\n"


def test_only_the_axis_already_there_has_no_move() -> None:
    # axis 0 stands at 0 and generates nothing; axis 1 loads its move and GO runs it to 10
    source = "MOVEA[0,1] = 0, 10\nPRINT MOVEBUFFERFREE.0; MOVEBUFFERFREE.1\nGO[0,1]\nPAUSE IDLE[0,1]\nPRINT POS.1\n"
    assert simulate(source).terminal == "2       1\n10\n"


def test_mintmt_reads_it_so_too() -> None:
    # MintMT's buffer is v4's (004:63-65, 004:93); MOVEBUFFERFREE counts the free places (004:93)
    source = "MOVEBUFFERSIZE(0) = 2\nMOVEA(0) = 0\nPrint MOVEBUFFERFREE(0)\n"
    result = run_source(source, dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=1000))
    assert result.terminal == "2\n"


def test_a_buffer_made_smaller_than_what_it_holds_has_no_free_place() -> None:
    # MOVEBUFFERFREE is the number of free places (000:2978-2983): none, not a negative count, once
    # MOVEBUFFERSIZE is set below the moves loaded (the guide says nothing more of shrinking a buffer)
    source = "MOVEBUFFERSIZE.0 = 4\nMOVER.0 = 10\nMOVER.0 = 10\nMOVER.0 = 10\nMOVEBUFFERSIZE.0 = 2\n"
    source += "PRINT MOVEBUFFERFREE.0\n"
    assert simulate(source).terminal == "0\n"
