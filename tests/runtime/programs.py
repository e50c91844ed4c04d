"""Generated Mint programs for the runtime's metamorphic property tests.

A program is a list of **blocks**, each self-contained: it starts by giving
every variable and array element a value of its own, then runs one or more
statements, among them FOR, WHILE, REPEAT, LOOP .. EXIT and IF .. DO .. ELSE
blocks nested up to three deep. Every loop is bounded: a loop's counter is
set just before it and only the loop changes it, and each nesting depth has
its own counter. Lines are written flat or indented by depth, so equal line
texts (``NEXT``, ``PRINT x``, a counter's increment) recur inside and across
blocks: the parser shares one syntax object between them.

``flow_programs`` only compute and print, so they always end normally and a
block does the same wherever it runs. ``timed_programs`` also wait, pause,
move axes, read keys typed ahead and inputs changing on a schedule, raise
timer events and run into errors: they run to ``UNTIL_MS``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cache

from hypothesis import strategies as st

VALUES = ("x", "y", "z")
ARRAY = "t"
ARRAY_SIZE = 4
FOR_COUNTERS = ("i", "j", "k")  # the FOR counter of each nesting depth
LOOP_COUNTERS = ("n", "m", "p")  # the counter of each depth's WHILE, REPEAT or LOOP
MAX_DEPTH = len(FOR_COUNTERS)
TIMER_COUNT = "tn"
KEY = "key"
AXES = (0, 1)
INPUTS = (1, 2, 3, 4)
UNTIL_MS = 800  # how long a timed program runs at most

SUBROUTINE = ("#half", "z = z / 2 + 1", "PRINT z", "RETURN")
TIMER_HANDLER = ("#TIMER", f"{TIMER_COUNT} = {TIMER_COUNT} + 1", f'PRINT "T"; {TIMER_COUNT}', "RETURN")
ERROR_HANDLER = ("#ONERROR", 'PRINT "E"; ERR', "RETURN")


@dataclass(frozen=True)
class Program:
    """A program: the world it meets (``REM @sim`` lines), its blocks, and what stands after ``END``.

    ``prologue`` and ``epilogue`` stand before and after the blocks (a timer set
    going, a ``LOOP`` .. ``ENDL`` around them all).
    """

    world: tuple[str, ...]
    blocks: tuple[tuple[str, ...], ...]
    handlers: tuple[str, ...] = SUBROUTINE
    prologue: tuple[str, ...] = ()
    epilogue: tuple[str, ...] = ()

    @property
    def source(self) -> str:
        declarations = [f"DIM {name}" for name in (*VALUES, *FOR_COUNTERS, *LOOP_COUNTERS, TIMER_COUNT, KEY)]
        lines = [*self.world, *declarations, f"DIM {ARRAY}({ARRAY_SIZE})", *self.prologue]
        lines += [line for block in self.blocks for line in block]
        return "\n".join([*lines, *self.epilogue, "END", *self.handlers, ""])

    def with_block_repeated(self, number: int) -> Program:
        """The program with block ``number`` written twice, one copy right after the other."""
        blocks = self.blocks
        return replace(self, blocks=(*blocks[: number + 1], *blocks[number:]))

    def first_blocks(self, count: int) -> Program:
        """The program cut after its first ``count`` blocks."""
        return replace(self, blocks=self.blocks[:count])


_INDENT = "\0"  # one level of indentation, until the program chooses how it is written
_constant = st.integers(min_value=-3, max_value=3).map(str)
_value = st.sampled_from(VALUES)
_element = st.integers(min_value=1, max_value=ARRAY_SIZE).map(lambda index: f"{ARRAY}({index})")
_operand = st.one_of(_value, _constant, _element)
_comparison = st.builds("{} {} {}".format, _value, st.sampled_from(["<", ">", "=", "<>", "<=", ">="]), _operand)
_condition = st.one_of(
    _comparison,
    st.builds("{} {} {} > {}".format, _comparison, st.sampled_from(["AND", "OR"]), _value, _constant),
)


@cache
def _expression(counters: tuple[str, ...]) -> st.SearchStrategy[str]:
    """A value that grows at most by a constant per assignment, so no run overflows."""
    term = st.one_of(_value, _element, *([st.sampled_from(counters)] if counters else []))
    return st.one_of(
        term,
        st.builds("{} + {}".format, term, _constant),
        st.builds("({} + {}) / 2".format, term, _operand),
        st.builds("-{}".format, term),
        st.builds("{} * 0.5".format, term),
        st.builds("({} + {}) MOD 7".format, term, _constant),
    )


@cache
def _computation(counters: tuple[str, ...]) -> st.SearchStrategy[str]:
    """A statement whose effect depends only on the values the block gave its variables."""
    target, expression = st.one_of(_value, _element), _expression(counters)
    return st.one_of(
        st.builds("{} = {}".format, target, expression),
        st.builds("PRINT {}".format, _operand),
        st.builds("PRINT {}; {}".format, _value, _operand),
        st.sampled_from(['PRINT "a"', 'PRINT "ok"']),
        st.builds("IF {} THEN {} = {}".format, _condition, target, expression),
        st.builds("IF {} THEN PRINT {}".format, _condition, _operand),
        st.just("GOSUB half"),
    )


def _timed() -> st.SearchStrategy[str]:
    """A statement that waits, moves, reads the world or may raise an error."""
    axis, channel, distance = st.sampled_from(AXES), st.sampled_from(INPUTS), st.integers(-3000, 3000)
    moment = st.integers(min_value=0, max_value=400)
    return st.one_of(
        st.builds("WAIT = {}".format, st.integers(min_value=0, max_value=30)),
        st.builds("WHILE TIME < {} : ENDW".format, moment),
        st.builds("REPEAT : UNTIL IN.{} OR TIME > {}".format, channel, moment),
        st.builds("TIME = {}".format, st.integers(min_value=0, max_value=100)),
        st.builds("PAUSE TIME > {}".format, moment),
        st.builds("MOVER.{0} = {1} : GO.{0}".format, axis, distance),
        st.builds("MOVEA.{0} = {1} : GO.{0}".format, axis, distance),
        st.builds("PAUSE IDLE.{}".format, axis),
        st.builds("PAUSE IDLE.{} OR TIME > {}".format, axis, moment),
        st.builds("PAUSE POS.{} > {} OR TIME > 300".format, axis, st.integers(-500, 500)),
        st.builds("JOG.{} = {}".format, axis, st.integers(-20000, 20000)),
        st.builds("STOP.{}".format, axis),
        st.builds("CANCEL.{}".format, axis),
        st.builds("SPEED.{} = {}".format, axis, st.sampled_from([500, 5000, 40000])),
        st.builds("ACCEL.{0} = {1} : DECEL.{0} = {1}".format, axis, st.sampled_from([10000, 300000])),
        st.builds("PRINT POS.{0}; VEL.{0}; IDLE.{0}".format, axis),
        st.just(f"{KEY} = INKEY"),
        st.builds("PAUSE INKEY = '{}' OR TIME > 500".format, st.sampled_from(["Y", "x", "1"])),
        st.just("PAUSE INKEY = 'Y'"),
        st.just("PAUSE INKEY"),
        st.just(f"PRINT INKEY; {KEY}"),
        st.builds("PAUSE IN.{}".format, channel),
        st.builds("PAUSE !IN.{} OR TIME > 200".format, channel),
        st.builds("{} = IN.{} + IN".format, _value, channel),
        st.builds("TIMEREVENT = {}".format, st.sampled_from([0, 10, 25])),
        st.builds("OUT.{} = {}".format, st.integers(min_value=0, max_value=7), st.sampled_from([0, 1, 2])),
        st.just("PRINT TIME"),
        st.builds("{} = {} / {}".format, _value, _value, _value),
        st.builds("{}(ABS({}) + {}) = {}".format, st.just(ARRAY), _value, st.integers(0, 2), _operand),
    )


_timed_statement = _timed()


@cache
def _simple(counters: tuple[str, ...], timed: bool) -> st.SearchStrategy[str]:
    return st.one_of(_computation(counters), *([_timed_statement] if timed else []))


@cache
def _statements(depth: int, counters: tuple[str, ...], looping: bool, timed: bool) -> st.SearchStrategy[list[str]]:
    """One statement on a line, several on a line, or a block of lines (only below ``MAX_DEPTH``)."""
    simple = _simple(counters, timed)
    options = [
        simple.map(lambda line: [line]),
        st.lists(simple, min_size=2, max_size=3).map(lambda parts: [" : ".join(parts)]),
    ]
    if looping:
        options.append(_condition.map(lambda condition: [f"IF {condition} THEN EXIT"]))
    if depth < MAX_DEPTH:
        options.append(_block_statement(depth, counters, looping, timed))
    return st.one_of(options)


@cache
def _body(depth: int, counters: tuple[str, ...], looping: bool, timed: bool) -> st.SearchStrategy[list[str]]:
    statement = _statements(depth, counters, looping, timed)
    return st.lists(statement, max_size=3).map(lambda groups: [_INDENT + line for group in groups for line in group])


@cache
def _block_statement(depth: int, counters: tuple[str, ...], looping: bool, timed: bool) -> st.SearchStrategy[list[str]]:
    """A FOR, WHILE, REPEAT, LOOP .. EXIT or IF .. DO [.. ELSE] block at ``depth`` (0: a block of the program)."""
    index, counter, count = FOR_COUNTERS[depth], LOOP_COUNTERS[depth], st.integers(min_value=0, max_value=3)
    loop_body = _body(depth + 1, (*counters, counter), True, timed)
    branch = _body(depth + 1, counters, looping, timed)
    return st.one_of(
        st.builds(lambda c, body: [f"IF {c} DO", *body, "ENDIF"], _condition, branch),
        st.builds(lambda c, yes, no: [f"IF {c} DO", *yes, "ELSE", *no, "ENDIF"], _condition, branch, branch),
        st.builds(
            lambda start, span, step, body: [f"FOR {index} = {start} TO {start + span}{step}", *body, "NEXT"],
            st.integers(min_value=-2, max_value=2),
            st.integers(min_value=-1, max_value=3),
            st.sampled_from(["", " STEP 2", " STEP -1", " STEP 0.5"]),
            _body(depth + 1, (*counters, index), True, timed),
        ),
        st.builds(
            lambda n, body: [f"{counter} = 0", f"WHILE {counter} < {n}", _counted(counter), *body, "ENDW"],
            count,
            loop_body,
        ),
        st.builds(
            lambda n, body: [f"{counter} = 0", "REPEAT", _counted(counter), *body, f"UNTIL {counter} >= {n}"],
            count,
            loop_body,
        ),
        st.builds(
            lambda n, body: [
                f"{counter} = 0",
                "LOOP",
                _counted(counter),
                f"{_INDENT}IF {counter} > {n} THEN EXIT",
                *body,
                "ENDL",
            ],
            count,
            loop_body,
        ),
        _nest(counters, timed),
    )


_NESTS = {  # opening line, last line of the body, closing line: each copy runs at most once
    "IF": ("IF {} DO", None, "ENDIF"),
    "LOOP": ("LOOP", "EXIT", "ENDL"),
    "WHILE": ("WHILE {}", "EXIT", "ENDW"),
    "REPEAT": ("REPEAT", None, "UNTIL 1"),
}


@cache
def _nest(counters: tuple[str, ...], timed: bool) -> st.SearchStrategy[list[str]]:
    """The same block nested in itself two or three times, so the copies' lines are equal, line for line."""

    def nested(kind: str, condition: str, statements: list[str], copies: int) -> list[str]:
        opening, last, closing = _NESTS[kind]
        block: list[str] = []
        for _ in range(copies):
            body = [*statements, *block, *([last] if last else [])]
            block = [opening.format(condition), *(_INDENT + line for line in body), closing]
        return block

    return st.builds(
        nested,
        st.sampled_from(sorted(_NESTS)),
        _condition,
        st.lists(_simple(counters, timed), max_size=2),
        st.integers(min_value=2, max_value=3),
    )


def _counted(counter: str) -> str:
    return f"{_INDENT}{counter} = {counter} + 1"


@st.composite
def _block(draw: st.DrawFn, timed: bool) -> list[str]:
    """Values for every variable and element, then statements that use only them."""
    values = " : ".join(f"{name} = {draw(_constant)}" for name in VALUES)
    elements = " : ".join(f"{ARRAY}({index}) = {draw(_constant)}" for index in range(1, ARRAY_SIZE + 1))
    first, rest = draw(_block_statement(0, (), False, timed)), draw(_body(0, (), False, timed))
    return [values, elements, *first, *(line.removeprefix(_INDENT) for line in rest)]


@st.composite
def _written(draw: st.DrawFn, blocks: list[list[str]]) -> tuple[tuple[str, ...], ...]:
    """The blocks' lines written flat (more equal lines) or indented two spaces a level."""
    indent = draw(st.sampled_from(["", "  "]))
    return tuple(tuple(line.replace(_INDENT, indent) for line in block) for block in blocks)


@st.composite
def flow_programs(draw: st.DrawFn) -> Program:
    """Programs that compute and print, and always end normally."""
    blocks = draw(st.lists(_block(timed=False), min_size=1, max_size=4))
    return Program((), draw(_written(blocks)))


def _what_it_sets_when(line: str) -> str:
    """A world line without an input's level: one input takes one level a millisecond (a second is refused)."""
    words = line.split()
    return " ".join(words[:4] + words[5:]) if words[2] == "input" else line


_world_line = st.one_of(
    st.builds(
        lambda text, at: f'REM @sim key "{text}" at {at}',
        st.sampled_from(["xy", "Y", "1\\r", "xyz", "q"]),
        st.integers(min_value=0, max_value=300),
    ),
    st.builds(
        lambda channel, level, at: f"REM @sim input {channel} {level} at {at}",
        st.sampled_from(INPUTS),
        st.sampled_from([0, 1]),
        st.integers(min_value=0, max_value=400),
    ),
)


@st.composite
def timed_programs(draw: st.DrawFn) -> Program:
    """Programs that also meet a world over time: they may wait or loop for ever, so they run to ``UNTIL_MS``.

    Most have their drives enabled (a move on a disabled drive is an error);
    some set a timer going, some handle errors or an input, some repeat all
    their blocks for ever, and one in ten has a stray block end that stops it
    compiling.
    """
    drives = [] if draw(st.integers(min_value=0, max_value=3)) == 3 else ["REM @sim drives enabled"]
    world = (*drives, *draw(st.lists(_world_line, max_size=5, unique_by=_what_it_sets_when)))
    blocks = draw(st.lists(_block(timed=True), min_size=1, max_size=3))
    if draw(st.integers(min_value=0, max_value=9)) == 9:
        # a block end with no block to end: the controller will not compile the program
        stray = draw(st.sampled_from(["NEXT", "ENDW", "UNTIL x > 0", "ENDL", "ELSE", "ENDIF"]))
        blocks.insert(draw(st.integers(min_value=0, max_value=len(blocks))), [stray])
    handlers, prologue, epilogue = [*SUBROUTINE], [], []
    timer = draw(st.sampled_from([None, 10, 25, 60]))
    if timer is not None:
        prologue.append(f"TIMEREVENT = {timer}")
        handlers += TIMER_HANDLER
    if draw(st.booleans()):
        handlers += ERROR_HANDLER
    if draw(st.integers(min_value=0, max_value=3)) == 3:  # called every tick while the input is high
        handlers += (f"#IN{draw(st.sampled_from(INPUTS))}", 'PRINT "in"; TIME', "RETURN")
    if draw(st.booleans()):
        prologue.append("LOOP")
        epilogue.append("ENDL")
    return Program(world, draw(_written(blocks)), tuple(handlers), tuple(prologue), tuple(epilogue))
