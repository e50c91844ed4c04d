"""Metamorphic properties of the runtime: edits whose effect on a run is known without knowing the run.

Nobody has to work out what a generated program prints: it is run twice, once
edited, and the two runs must agree as the edit says. The programs come from
``tests/runtime/programs.py``; each property tries 200 of them in CI, and
``MINT_FUZZ_SCALE=10`` tries ten times as many (``tests/fuzzing.py``).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, note, settings
from hypothesis import strategies as st

from mintlang.runtime.interpreter.vm import StopReason
from tests.conformance.cases import CONFORMANCE, Case, all_cases, read_case
from tests.fuzzing import examples
from tests.runtime.edits import Edited, Seen, gaps, inserted, reindented, seen
from tests.runtime.programs import UNTIL_MS, Program, flow_programs, timed_programs

ENDS_ON_ITS_OWN_MS = 600_000  # a flow program still running after ten simulated minutes is stuck
CONFORMANCE_UNBOUNDED_MS = 600_000

property_test = settings(max_examples=examples(200), deadline=None, suppress_health_check=[HealthCheck.too_slow])

any_program = st.one_of(flow_programs(), timed_programs())
indentation = st.text(alphabet=" \t", max_size=6)
blank_line = indentation
rem_line = st.builds(
    "{}{} {}".format,
    indentation,
    st.sampled_from(["REM", "rem", "Rem"]),
    st.text(alphabet="abcXYZ019 :=.,()+-*/'\"", max_size=16),  # no @: a directive would change the world
).map(str.rstrip)


def _seen(source: str, *, every_tick: bool = False) -> Seen:
    return seen(source, until_ms=UNTIL_MS, every_tick=every_tick)


@property_test
@given(program=any_program, indents=st.lists(indentation, min_size=1, max_size=7))
def test_re_indenting_the_lines_changes_nothing(program: Program, indents: list[str]) -> None:
    """Indentation means nothing to Mint: every line keeps its number, and the runs must be identical.

    Lines equal before may now differ, and lines that differed only in their
    indentation may now be equal (the parser shares one syntax object between them).
    """
    edited = reindented(program.source, indents)
    note(edited.source)
    assert _seen(edited.source) == _seen(program.source)


@property_test
@given(data=st.data(), program=any_program)
def test_blank_lines_and_rem_lines_change_nothing_but_the_line_numbers(data: st.DataObject, program: Program) -> None:
    """Blank and ``REM`` lines inserted anywhere change no output, variable, axis or stop.

    They do move every later line down, and with it ERL, the stop's line and the
    ``line N`` of every error message: those are mapped back to the lines of the
    program as written before comparing, so the comparison stays exact. The
    generated programs never read ERL into a variable or print it, so no other
    number they leave is a line number.
    """
    source = program.source
    where = st.sampled_from(gaps(source))
    insertions = data.draw(st.dictionaries(where, st.lists(st.one_of(blank_line, rem_line), min_size=1, max_size=3)))
    edited = inserted(source, insertions)
    note(edited.source)
    assert _seen(edited.source).renumbered(edited) == _seen(source)


@property_test
@given(data=st.data(), program=flow_programs())
def test_a_block_repeated_verbatim_prints_its_output_again(data: st.DataObject, program: Program) -> None:
    """Every block of a flow program first sets every variable it uses, so running it again repeats what it did.

    A block's output is what the program cut after it prints beyond the program
    cut before it. Written twice, one copy right after the other, the block's
    output comes twice at that place, and every variable ends as it did.
    """
    number = data.draw(st.integers(min_value=0, max_value=len(program.blocks) - 1), label="repeated block")
    note(program.with_block_repeated(number).source)
    before = seen(program.first_blocks(number).source, until_ms=ENDS_ON_ITS_OWN_MS)
    through = seen(program.first_blocks(number + 1).source, until_ms=ENDS_ON_ITS_OWN_MS)
    once = seen(program.source, until_ms=ENDS_ON_ITS_OWN_MS)
    twice = seen(program.with_block_repeated(number).source, until_ms=ENDS_ON_ITS_OWN_MS)
    assert [run.stop.reason for run in (before, through, once, twice)] == [StopReason.END] * 4
    assert through.terminal.startswith(before.terminal) and once.terminal.startswith(through.terminal)
    block_output = through.terminal[len(before.terminal) :]
    assert twice.terminal == through.terminal + block_output + once.terminal[len(through.terminal) :]
    assert twice.variables == once.variables


A_STOP_ENDING_IN_SKIPPED_TICKS = Program(  # found with MINT_FUZZ_SCALE=10: IDLE.0 turns true a tick early
    world=("REM @sim drives enabled",),
    blocks=(("MOVER.0 = 2 : GO.0", "x = 1", "STOP.0", "PAUSE IDLE.0"),),
    prologue=("LOOP",),
    epilogue=("ENDL",),
)


@property_test
@given(program=timed_programs())
@example(program=A_STOP_ENDING_IN_SKIPPED_TICKS)
def test_skipping_idle_ticks_gives_what_stepping_every_tick_gives(program: Program) -> None:
    """Waits, pauses on TIME, IDLE, INKEY and inputs, moves, keys typed ahead, inputs on a schedule, timer events."""
    note(program.source)
    assert _seen(program.source, every_tick=False) == _seen(program.source, every_tick=True)


# 233 mirrors ERL, 237 the line running; TRON prints the number of every line run
_LINE_READER = re.compile(r"\bERL\b|\bCOMMS\s*\(\s*23[37]\s*\)|\bTRON\b", re.IGNORECASE)


def _reads_line_numbers(source: str) -> bool:
    """Whether a line other than a comment reads a line number, which a renumbering cannot find in the output."""
    return any(_LINE_READER.search(line) for line in source.splitlines() if not line.lstrip().upper().startswith("REM"))


def _with_lines(source: str, line: str, *, only_at_the_end: bool) -> Edited:
    if only_at_the_end:
        return inserted(source, {len(source.splitlines()): [line]})
    return inserted(source, {gap: [line] for gap in gaps(source)})


def _run_case(case: Case, source: str, config: str | None) -> Seen:
    return seen(
        source,
        until_ms=case.until_ms or CONFORMANCE_UNBOUNDED_MS,
        config=config,
        controller=case.controller,
        dialect=case.dialect,
        scenario=case.scenario,
    )


@pytest.mark.parametrize("path", all_cases(), ids=lambda path: str(path.relative_to(CONFORMANCE).with_suffix("")))
@pytest.mark.parametrize("line", ["", "REM a line the controller skips : PRINT 1"], ids=["blank", "rem"])
def test_blank_lines_and_rem_lines_change_nothing_in_a_conformance_program(path: Path, line: str) -> None:
    """A blank or ``REM`` line inserted before every line and after the last, of the program and its configuration.

    Both files get the same edit, so a line number maps back the same way
    whichever file it is in (ERL does not say which). A case that reads a line
    number (ERL, or the comms elements mirroring ERL and the line running) or
    traces its lines (TRON) could print it or compute with it, where no renumbering can find it: its files
    get the line only after their last line, which moves nothing.
    """
    case = read_case(path)
    config = case.configuration  # both files get a line in the same places: either edit maps a line number back
    at_the_end = _reads_line_numbers(case.source) or (config is not None and _reads_line_numbers(config))
    program = _with_lines(case.source, line, only_at_the_end=at_the_end)
    edited_config = _with_lines(config, line, only_at_the_end=at_the_end) if config is not None else None
    longer = max([program, edited_config or program], key=lambda edited: len(edited.origin))
    edited_run = _run_case(case, program.source, edited_config.source if edited_config else None)
    assert edited_run.renumbered(longer) == _run_case(case, case.source, config)
