"""The simulator never raises, whatever a compilable program asks of it.

Programs are generated from statements a Mint programmer writes every day -
moves, jogs, stops, homing, parameter writes with arbitrary values, loops,
events, PRINT - on random axes and with random numbers, so they hit range
errors, motion in progress, disabled drives, full buffers, deadlocks and
runaway loops. Every run must end with one of the documented endings; an
exception out of the simulator is a bug. ``MINT_FUZZ_SCALE=10`` runs more.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.fuzzing import examples

AXIS = st.integers(min_value=0, max_value=4)  # axis 4 is outside a NextMove BX's four servo axes
NUMBER = st.one_of(
    st.integers(min_value=-5000, max_value=5000),
    st.sampled_from([0, 1, -1, 0.5, 100000, 8388607, -8388608, 1e9]),
).map(str)
PARAMETER = st.sampled_from(
    ["SPEED", "ACCEL", "DECEL", "SCALE", "FOLERRORFATAL", "IDLEPOS", "SRAMP", "KPROP", "KVELFF", "HOMESPEED",
     "SOFTLIMITFORWARD", "SOFTLIMITMODE", "LIMITMODE", "STOPINPUT", "STOPINPUTMODE", "MOVEBUFFERSIZE",
     "CONTOURMODE", "FOLLOWMODE", "MASTERDISTANCE", "HOMEINPUT", "DRIVEENABLE", "TORQUE", "JOG"]
)  # fmt: skip


@st.composite
def statement(draw: st.DrawFn) -> str:
    axis, other, value, second = draw(AXIS), draw(AXIS), draw(NUMBER), draw(NUMBER)
    return draw(
        st.sampled_from(
            [
                f"{draw(PARAMETER)}.{axis} = {value}",
                f"MOVER.{axis} = {value} : GO.{axis}",
                f"MOVEA.{axis} = {value}",
                f"GO.{axis}",
                f"VECTORR[{axis},{other}] = {value}, {second} : GO.{axis}",
                f"CIRCLER[{axis},{other}] = {value}, {second}, 90 : GO.{axis}",
                f"INCR.{axis} = {value} : GO.{axis}",
                f"OFFSET.{axis} = {value} : GO.{axis}",
                f"JOG.{axis} = {value}",
                f"FOLLOW.{axis} = {draw(st.sampled_from(['0', '1', '-2', '0.5']))}",
                f"FLY.{axis} = {value} : GO.{axis}",
                f"HOME.{axis} = {draw(st.sampled_from(['0', '1', '4', '6']))}",
                f"STOP.{axis}",
                f"CANCEL.{axis}",
                f"RESET.{axis}",
                "ABORT",
                f"WAIT = {draw(st.integers(min_value=0, max_value=50))}",
                f"PAUSE IDLE.{axis} OR TIME > 200",
                f"PRINT POS.{axis}; VEL.{axis}; AXISMODE.{axis}; {value} / 3",
                f"OUT.{draw(st.integers(min_value=0, max_value=9))} = 1",
                f"x = x + {value} : IF x > 1000 THEN x = 0",
                f"TIMEREVENT = {draw(st.sampled_from(['0', '20', '3']))}",
                f"COMMS({draw(st.integers(min_value=0, max_value=101))}) = {value}",
                f"LIMITFORWARDINPUT.{axis} = 5",
                f"STOPINPUT.{axis} = 6 : STOPINPUTMODE.{axis} = {draw(st.sampled_from(['0', '1', '2', '3']))}",
                f"ERRORINPUT.{axis} = 7",
                "PAUSE IN.6 OR TIME > 300",
            ]
        )
    )


WORLD = st.sampled_from(
    [
        "REM @sim plant 0 torque",
        "REM @sim plant 1 stalled",
        "REM @sim plant 2 velamp 500",
        "REM @sim input 5 when enc 0 >= 300",
        "REM @sim input 6 1 at 120",
        "REM @sim input 6 0 at 250",
        "REM @sim input 7 1 at 200",
        "REM @sim index 0 every 1000 width 10",
        "REM @sim fastin 0 at 100",
        'REM @sim key "7\\r" at 50',
    ]
)


@st.composite
def program(draw: st.DrawFn) -> str:
    world = draw(st.lists(WORLD, max_size=4, unique=True))
    body = draw(st.lists(statement(), min_size=1, max_size=12))
    looped = draw(st.booleans())
    lines = [*world, "DIM x = 0", "RESET[0,1,2,3]", *(["LOOP"] if looped else []), *body, *(["ENDL"] if looped else [])]
    handlers = draw(
        st.sampled_from(
            ["", "#ONERROR\nPRINT ERR\nRETURN", "#TIMER\nx = x + 1\nRETURN", "#STOP\nPRINT 1\nRETURN", "#IN6\nRETURN"]
        )
    )
    return "\n".join([*lines, "END", handlers, ""])


@settings(max_examples=examples(300), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program())
def test_generated_programs_always_reach_a_documented_ending(source: str) -> None:
    result = run_source(source, controller="nextmove-bx", limits=Limits(until_ms=400, max_wall_s=10.0))
    assert result.stop.reason in set(StopReason)
