"""A loop compiled whole into generated Python runs exactly as the interpreter runs it statement by statement.

``runtime/interpreter/compiled_loops.py`` runs the passes of loops whose bodies
only do arithmetic on variables as one generated Python function. Nothing a run
shows may change: the variables, the terminal, the tick at which each statement
runs (20 statements a 1 ms tick), the errors and the lines they name. The
properties run random small loops of every kind with the compiled loops and
with the interpreter alone, ticks run alone and every tick processed whole;
the examples below pin the cases worked out by hand.
"""

from __future__ import annotations

import struct
from dataclasses import replace

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from mintlang.runtime.controller import Controller
from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import f32
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.simulation import Limits

from .running import observable

LIMITS = Limits(until_ms=300, max_wall_s=30.0)
REPORT = 'PRINT TIME, " ", a, " ", b, " ", c, " ", i'
HANDLER = '#ONERROR\n  PRINT "error ", ERR, " at ", ERL, " ", TIME\nRETURN\n'

BODY = (
    "a = a + 1",
    "b = b * 2 - a",
    "c = c + i * 3",
    "b = b / a",  # a may be 0: error 2021
    "a = a * 1000",  # overflows binary32 in a few passes: error 3
    "c = c MOD 7 + i",
    "a = -a + 0.5",
    "b = ABS(b) + SQRT(c)",
    "c = LOG(c)",  # 0 or less: error 3 from a function, inside the expression
    "IF a > 5 THEN b = b - 1",
    "IF b < 0 THEN a = a + 1 : c = c - 1",
    "IF c > 40 THEN EXIT",
    "IF a = 3 THEN IF b > 2 THEN EXIT",
    "i = i + 1",
)
STEPS = ("", " STEP 2", " STEP -1", " STEP -3", " STEP 0.5", " STEP 0")


def _loop(kind: str, body: list[str], start: float, end: int, step: str) -> str:
    inner = "".join(f"  {statement}\n" for statement in body)
    if kind == "FOR":
        return f"FOR i = {start} TO {end}{step}\n{inner}NEXT\n"
    if kind == "WHILE":
        return f"WHILE c < {end * 5}\n{inner}ENDW\n"
    if kind == "REPEAT":
        return f"REPEAT\n{inner}UNTIL a > {end}\n"
    return f"LOOP\n{inner}  IF a > {end} THEN EXIT\nENDL\n"


def _programs(body: tuple[str, ...], declarations: str, handler: str) -> st.SearchStrategy[str]:
    loops = st.builds(
        _loop,
        st.sampled_from(("FOR", "WHILE", "REPEAT", "LOOP")),
        st.lists(st.sampled_from(body), min_size=0, max_size=4),
        st.one_of(st.integers(-20, 20), st.sampled_from((0.1, -2.7, 16777210))),  # binary32 rounds each step
        st.integers(-20, 200),
        st.sampled_from(STEPS),
    )
    return st.builds(
        lambda values, parts, handled: (
            declarations
            + "".join(f"{name} = {value}\n" for name, value in zip("abci", values, strict=True))
            + "".join(f"{part}{REPORT}\n" for part in parts)
            + "END\n"
            + (handler if handled else "")
        ),
        st.tuples(*(st.sampled_from((0, 1, 3, -2, 0.25, 7)) for _ in range(4))),
        st.lists(loops, min_size=1, max_size=3),
        st.booleans(),
    )


programs = _programs(BODY, "DIM a\nDIM b\nDIM c\nDIM i\n", HANDLER)
# Mint v3 (24.8 fixed point, its own arithmetic) names no SQRT or LOG and declares a variable by assigning it
v3_programs = _programs(tuple(line for line in BODY if "SQRT" not in line and "LOG" not in line), "", "")


def _interpreted(controller: Controller) -> None:
    """The interpreter alone: no loop compiled whole."""
    controller.vm.compiled_loops[:] = [None] * len(controller.vm.compiled_loops)


def _run(source: str, limits: Limits = LIMITS, *, compiled: bool = True, dialect: str = "v4") -> RunResult:
    return _ran(source, limits, compiled, dialect)[0]


def _seen(source: str, limits: Limits = LIMITS, *, compiled: bool = True, dialect: str = "v4") -> tuple[object, ...]:
    """What the run shows, and every variable's value to the bit (PRINT shows a few decimals)."""
    result, variables = _ran(source, limits, compiled, dialect)
    return (*observable(result), variables)


def _ran(source: str, limits: Limits, compiled: bool, dialect: str) -> tuple[RunResult, tuple[bytes, ...]]:
    built: list[Controller] = []

    def start(controller: Controller) -> None:
        built.append(controller)
        if not compiled:
            _interpreted(controller)

    result = run_source(source, dialect=dialect, limits=limits, on_start=start)
    return result, tuple(struct.pack("<d", value) for controller in built for value in controller.vm.scalars)


@settings(max_examples=50, deadline=None)
@given(programs)
def test_compiled_loops_show_what_the_interpreter_shows(source: str) -> None:
    expected = _seen(source, compiled=False)
    assert _seen(source) == expected
    assert _seen(source, replace(LIMITS, every_tick=True)) == expected


@settings(max_examples=25, deadline=None)
@given(v3_programs)
@example(  # b doubles past 24.8 fixed point's range, which the simulator does not model: the run stops on line 7
    source="a = 0\nb = 0\nc = 0\ni = 0\nREPEAT\n  a = a + 1\n  b = b * 2 - a\n  a = -a + 0.5\nUNTIL a > 0\nEND\n"
)
def test_compiled_loops_run_v3_arithmetic_as_the_interpreter_does(source: str) -> None:
    assert _run(source, dialect="v3").stop.unit in (None, "program")  # the program ran
    expected = _seen(source, compiled=False, dialect="v3")
    assert _seen(source, dialect="v3") == expected
    assert _seen(source, replace(LIMITS, every_tick=True), dialect="v3") == expected


@settings(max_examples=25, deadline=None)
@given(programs, st.sampled_from((1, 3, 7, 20)))
def test_any_slice_size_runs_the_same_statements_in_each_tick(source: str, slice_statements: int) -> None:
    limits = replace(LIMITS, slice_statements=slice_statements)
    assert _seen(source, limits) == _seen(source, limits, compiled=False)


def test_a_for_loop_runs_two_statements_a_pass_twenty_a_tick() -> None:
    # Four DIMs and FOR are the first 5 statements; 100 passes of 2 (the assignment and NEXT, which leaves the
    # variable at 100) end with the 205th, and PRINT is the 206th: tick 10 runs statements 201-220.
    result = _run(f"DIM a\nDIM b\nDIM c\nDIM i\nFOR i = 1 TO 100\n  a = a + i\nNEXT\n{REPORT}\n")
    assert result.terminal == "10 5050 0 0 100\n"


def test_a_failing_statement_names_its_line_at_its_tick() -> None:
    # a doubles each pass from 1, and pass 128 makes it 2**128, past binary32's largest value. DIM, DIM, a = 1
    # and FOR are statements 1-4 and pass k's assignment is statement 2k + 3: the 259th fails, in tick 12
    # (statements 241-260), on line 5.
    result = _run("DIM a\nDIM i\na = 1\nFOR i = 1 TO 1000\n  a = a * 2\nNEXT\n")
    assert (result.err, result.erl, result.stop.time_ms, result.stop.line) == (3.0, 5.0, 12, 5)


BIG = "100000000000000000000000000000000000000"  # 1E38


@pytest.mark.parametrize("sign", ["", "-"])
def test_a_next_past_binary32s_largest_value_is_error_3_on_its_line(sign: str) -> None:
    # 3E38 plus a step of 1E38 (in either direction) is past 3.4E38, binary32's largest value
    source = f"DIM i\nDIM a\nFOR i = {sign}3{BIG[1:]} TO {sign}34{BIG[2:]} STEP {sign}{BIG}\n  a = a + 1\nNEXT\n"
    result = _run(source)
    assert (result.err, result.erl, result.stop.line, result.stop.time_ms) == (3.0, 5.0, 5, 0)
    assert observable(result) == observable(_run(source, compiled=False))


def test_a_for_loop_counting_by_ones_past_2_to_the_24_stays_there_as_binary32_does() -> None:
    # 16777216 + 1 rounds to 16777216 (to even): the loop never passes 16777217, and the timer event sees i stuck
    source = "DIM i\nTIMEREVENT = 10\nFOR i = 16777200 TO 16777300\nNEXT\nEND\n#TIMER\n  PRINT i\nRETURN\n"
    result = _run(source, replace(LIMITS, until_ms=35))
    assert result.terminal == "16777216\n" * 3
    assert observable(result) == observable(_run(source, replace(LIMITS, until_ms=35), compiled=False))


def test_a_for_loop_up_to_2_to_the_24_ends_there() -> None:
    result = _run("DIM i\nFOR i = 16777100 TO 16777215\nNEXT\nPRINT i\n")
    assert result.terminal == "16777215\n"


@pytest.mark.parametrize(
    "body",
    [
        pytest.param("  a = a + i\n", id="arithmetic"),
        pytest.param("  IF a > 3 THEN a = a - 1\n  IF a < 0 THEN EXIT\n", id="IF THEN and EXIT"),
    ],
)
def test_a_loop_of_arithmetic_is_compiled(body: str) -> None:
    compiled: list[int] = []
    run_source(
        f"DIM a\nDIM i\nFOR i = 1 TO 10\n{body}NEXT\n",
        on_start=lambda controller: compiled.extend(
            pc for pc, loop in enumerate(controller.vm.compiled_loops) if loop is not None
        ),
    )
    assert compiled == [3]  # the loop's first statement, after DIM, DIM and FOR


@pytest.mark.parametrize(
    "body",
    [
        pytest.param("  x(i) = i\n", id="array element"),
        pytest.param("  PRINT i\n", id="PRINT"),
        pytest.param("  a = POS.0\n", id="keyword"),
        pytest.param("  FOR j = 1 TO 2\n  NEXT\n", id="nested loop"),
    ],
)
def test_a_loop_doing_more_than_arithmetic_on_variables_is_left_to_the_interpreter(body: str) -> None:
    compiled: list[object] = []
    run_source(
        f"DIM x(10)\nDIM a\nDIM i\nDIM j\nFOR i = 1 TO 3\n{body}NEXT\n",
        on_start=lambda controller: compiled.extend(
            loop for loop in controller.vm.compiled_loops[:6] if loop is not None
        ),
    )
    assert compiled == []


_BINARY32 = memoryview(bytearray(4)).cast("f")


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_a_binary32_store_rounds_as_numbers_f32(value: float) -> None:
    _BINARY32[0] = value
    stored = _BINARY32[0]
    try:
        expected = f32(value)
    except MintError:
        assert stored in (float("inf"), float("-inf"))  # the compiled loop's error 3
    else:
        assert struct.pack("<d", stored) == struct.pack("<d", expected)
