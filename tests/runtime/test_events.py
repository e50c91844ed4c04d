"""Event handlers run when and in the order a NextMove runs them (spec §7)."""

from __future__ import annotations

import pytest

from mintlang.runtime.comms.packets import ACK, encode_write
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.scenario.stimulus import HostPacket, Scenario
from tests.runtime.running import simulate


def test_the_timer_event_runs_every_timerevent_milliseconds() -> None:
    source = """DIM ticks = 0
TIMEREVENT = 100
WAIT = 1050
PRINT ticks
END
#TIMER
ticks = ticks + 1
RETURN
"""
    assert simulate(source).terminal == "10\n"


@pytest.mark.parametrize(
    ("controller", "source"),
    [
        pytest.param("nextmove-bx", "TIMEREVENT = 100\nPAUSE IN.1\n", id="written"),
        pytest.param("mintdrive", "REM TIMEREVENT is 10000 from power-up\nPAUSE IN.1\n", id="mintdrive power-up"),
    ],
)
def test_a_timer_without_a_handler_wakes_nothing(controller: str, source: str) -> None:
    # nothing drives input 1 and no #TIMER can change what PAUSE waits for: the program can never go on
    result = simulate(source, controller=controller, until_ms=None)
    assert (result.stop.reason, result.stop.line) == (StopReason.DEADLOCK, 2)


def test_timerevent_below_ten_is_rounded_up_and_odd_values_to_even() -> None:
    assert simulate("TIMEREVENT = 3\nPRINT TIMEREVENT\nTIMEREVENT = 25\nPRINT TIMEREVENT\n").terminal == "10\n26\n"


def test_a_level_input_calls_its_handler_while_active_and_an_edge_input_once() -> None:
    source = """REM @sim input 1 1 at 100
REM @sim input 1 0 at 105
REM @sim input 2 1 at 100
REM @sim input 2 0 at 105
DIM level = 0
DIM edge = 0
INPUTMODE = 4
INPUTPOSTRIGGER = 4
WAIT = 200
PRINT level, " ", edge
END
#IN1
level = level + 1
RETURN
#IN2
edge = edge + 1
RETURN
"""
    assert simulate(source).terminal == "5 1\n"


def test_eventdisable_keeps_the_event_pending_until_enabled() -> None:
    source = """REM @sim input 3 1 at 10
REM @sim input 3 0 at 12
INPUTMODE = 8
INPUTPOSTRIGGER = 8
EVENTDISABLE = 128
WAIT = 50
PRINT "pending ", EVENTPENDING
EVENTDISABLE = 0
WAIT = 2
PRINT "after ", EVENTPENDING
END
#IN3
PRINT "handled"
RETURN
"""
    assert simulate(source).terminal == "pending 128\nhandled\nafter 0\n"


def test_a_forced_input_event_runs_the_lowest_handler_not_a_label_with_a_leading_zero() -> None:
    # #IN01 is a plain label (the guide's handlers are #INx, 000:1894); forced, the input event runs #IN5
    source = 'EVENTPENDING = 128\nWAIT = 5\nEND\n#IN01\nPRINT "plain"\nRETURN\n#IN5\nPRINT "in5"\nRETURN\n'
    assert simulate(source).terminal == "in5\n"


def test_an_error_handler_preempts_a_lower_handler() -> None:
    source = """REM @sim input 0 1 at 10
REM @sim input 0 0 at 12
INPUTMODE = 1
INPUTPOSTRIGGER = 1
WAIT = 100
END
#IN0
PRINT "in0 start"
SCALE = -3
PRINT "in0 end"
RETURN
#ONERROR
PRINT "error ", ERR
RETURN
"""
    # SCALE = -3 is the system error 3 (000:4600-4604): the handler it interrupted goes on after it
    assert simulate(source).terminal == "in0 start\nerror 3\nin0 end\n"


def test_events_interrupt_a_wait_without_extending_it() -> None:
    source = """REM @sim input 4 1 at 100
REM @sim input 4 0 at 102
INPUTMODE = 16
INPUTPOSTRIGGER = 16
WAIT = 300
PRINT "woke at ", TIME
END
#IN4
PRINT "event at ", TIME
RETURN
"""
    assert simulate(source).terminal == "event at 100\nwoke at 300\n"


def test_a_host_write_to_comms_1_to_5_calls_its_comms_handler() -> None:
    packet = HostPacket(200, encode_write(2, 3, [42]))
    source = """PAUSE COMMS(3) = 42
PRINT "seen at ", TIME
WAIT = 10
END
#COMMS3
PRINT "event ", COMMS(3)
RETURN
"""
    result = simulate(source, scenario=Scenario(host_packets=(packet,)))
    assert result.terminal == "event 42\nseen at 200\n"
    assert result.host_replies == ((200, ACK),)


def test_a_program_write_to_comms_does_not_call_the_handler() -> None:
    source = 'COMMS(2) = 5\nWAIT = 10\nPRINT COMMS(2)\nEND\n#COMMS2\nPRINT "never"\nRETURN\n'
    assert simulate(source).terminal == "5\n"


def test_the_fast_input_latches_positions_for_its_handler() -> None:
    source = """REM @sim fastin 0 at 150
JOG.0 = 1000
WAIT = 300
END
#FASTIN0
PRINT FASTPOS.0
RETURN
"""
    result = simulate(source)
    assert result.stop.reason is StopReason.END
    assert 140 <= float(result.terminal) <= 150


def test_events_of_one_tick_run_in_nextmove_priority_order() -> None:
    # EV-2: #FASTINx before #TIMER before #INx, whatever order they were raised in
    source = """REM @sim input 5 1 at 100
REM @sim fastin 1 at 100
INPUTMODE = 32
INPUTPOSTRIGGER = 32
TIMEREVENT = 100
WAIT = 150
END
#IN5
PRINT "in5"
RETURN
#TIMER
PRINT "timer"
RETURN
#FASTIN1
PRINT "fastin1"
RETURN
"""
    assert simulate(source).terminal == "fastin1\ntimer\nin5\n"


PREEMPTION = """REM @sim input 2 1 at 100
REM @sim input 2 0 at 102
DIM fired = 0
INPUTMODE = 4
INPUTPOSTRIGGER = 4
TIMEREVENT = 110
WAIT = 200
END
#IN2
PRINT "in2 start"
WAIT = 30
PRINT "in2 end"
RETURN
#TIMER
IF fired = 0 THEN PRINT "timer"
fired = 1
RETURN
"""


def test_on_nextmove_a_higher_priority_event_preempts_a_running_handler() -> None:
    assert simulate(PREEMPTION, controller="nextmove-bx").terminal == "in2 start\ntimer\nin2 end\n"


def test_on_mintdrive_handlers_run_to_completion_before_the_next_event() -> None:
    # EV-3: MintDrive and ServoNode 51 do not pre-empt (only #ONERROR does)
    assert simulate(PREEMPTION, controller="mintdrive").terminal == "in2 start\nin2 end\ntimer\n"


def test_mintdrive_masks_events_with_handlerdisable_in_its_own_bit_layout() -> None:
    source = """REM @sim input 3 1 at 10
REM @sim input 3 0 at 12
INPUTMODE = 8
INPUTPOSTRIGGER = 8
HANDLERDISABLE = 64
WAIT = 50
PRINT "pending ", HANDLERPENDING
HANDLERDISABLE = 0
WAIT = 2
END
#IN3
PRINT "handled"
RETURN
"""
    assert simulate(source, controller="mintdrive").terminal == "pending 64\nhandled\n"


def test_exit_in_a_handler_cannot_leave_the_programs_loop() -> None:
    # NM-8: EXIT leaves a loop of its own handler; the program's LOOP is out of its reach
    source = """TIMEREVENT = 10
LOOP
  WAIT = 2
ENDL
#TIMER
EXIT
RETURN
"""
    result = simulate(source, until_ms=100)
    assert (result.stop.reason, result.stop.time_ms, result.err, result.erl) == (StopReason.ERROR, 10, 2003, 6)


def test_an_event_waits_while_the_gosub_stack_is_full() -> None:
    # EV-6: at the nesting limit (100 on a NextMove BX) the forced timer event runs once one level is released
    source = """DIM depth
GOSUB deep
END
#deep
depth = depth + 1
IF depth < 100 THEN GOSUB deep
IF depth = 100 THEN EVENTPENDING = 64 : WAIT = 5 : PRINT "full"
depth = 0
RETURN
#TIMER
PRINT "timer"
RETURN
"""
    assert simulate(source).terminal == "full\ntimer\n"


def test_eventdisable_stops_onerror_for_a_synchronous_error_which_then_ends_the_run() -> None:
    # EV-5: a set error bit stops #ONERROR being called, so the error is unhandled
    source = 'DIM a\nEVENTDISABLE = 2\na = 1 / a\nPRINT "continued"\nEND\n#ONERROR\nPRINT "handler"\nRETURN\n'
    result = simulate(source)
    assert (result.stop.reason, result.err, result.terminal) == (
        StopReason.ERROR,
        2021,
        "R2021: PROGRAM Divide by zero [line 3]\n",
    )


def test_each_file_is_served_by_its_own_event_handlers() -> None:
    # neither file can call the other's subroutines: the configuration's #ONERROR serves only the configuration
    config = 'DIM q\nRESETALL\nSCALE = -3\nPRINT "config goes on"\nEND\n#ONERROR\nPRINT "config handler"\nRETURN\n'
    program = 'q = 1 / q\nPRINT "never"\nEND\n'
    result = simulate(program, config=config)
    assert result.terminal == "config handler\nconfig goes on\nR2021: PROGRAM Divide by zero [line 1]\n"
    assert "R2021: PROGRAM" in result.stop.message and (result.err, result.erl) == (2021, 1)
    program_handler = 'PRINT "program"\nEND\n#ONERROR\nPRINT "program handler"\nRETURN\n'
    result = simulate(program_handler, config="DIM q\nRESETALL\nq = 1 / q\n")
    assert "R2021: CONFIGURATION" in result.stop.message
    assert result.terminal == "R2021: CONFIGURATION Divide by zero [line 3]\n"


def test_forcing_a_numbered_class_runs_its_lowest_numbered_handler() -> None:
    # EV-5: EVENTPENDING forces one event of the class; #COMMS0 and #IN0 do not exist here
    source = """EVENTPENDING = 256 + 128
WAIT = 2
PRINT EVENTPENDING
END
#COMMS4
PRINT "comms4"
RETURN
#COMMS2
PRINT "comms2"
RETURN
#IN7
PRINT "in7"
RETURN
"""
    assert simulate(source).terminal == "in7\ncomms2\n0\n"
