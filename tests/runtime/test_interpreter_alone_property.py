"""Running the program alone on quiet ticks never changes what a run shows.

Programs are drawn from statements that work on variables only (which the
simulator may run without the rest of their ticks) and statements that read or
change the machine (``PRINT TIME``, outputs, moves, ``WAIT``, ``PAUSE``), with a
timer event; each runs with ticks run alone, with every tick the program runs in
processed whole, and stepping every tick, and all three must show the same.
"""

from __future__ import annotations

from dataclasses import replace

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

from .running import observable

PURE = (
    "a = a + 1",
    "b = b * 2 - a",
    "IF a > 3 THEN b = 0",
    "FOR i = 1 TO 30\n  c = c + i\nNEXT",
    "WHILE c < 400\n  c = c + 7\nENDW",
    "c = c MOD 97",
    "IF b > 1000 DO\n  b = b / 3\nELSE\n  b = b + 5\nENDIF",
)
MACHINE = (
    'PRINT TIME, " ", a, " ", c',
    "OUT.1 = a MOD 2",
    "MOVER.0 = 500\nGO.0",
    "WAIT = 3",
    "PAUSE IDLE.0",
    "d = POS.0",
)
HEADER = "DIM a\nDIM b\nDIM c\nDIM d\nDIM i\nDIM t\nTIMEREVENT = 20\nLOOP\n"
FOOTER = "ENDL\nEND\n#TIMER\n  t = t + 1\nRETURN\n"


@settings(max_examples=40, deadline=None)
@given(st.lists(st.sampled_from(PURE + MACHINE), min_size=1, max_size=8))
def test_ticks_run_alone_show_what_every_tick_processed_whole_shows(body: list[str]) -> None:
    source = HEADER + "".join(f"{statement}\n" for statement in body) + FOOTER
    limits = Limits(until_ms=400, max_wall_s=30.0)
    alone = run_source(source, config="RESETALL\n", limits=limits)
    whole = run_source(source, config="RESETALL\n", limits=replace(limits, program_alone=False))
    stepped = run_source(source, config="RESETALL\n", limits=replace(limits, every_tick=True))
    assert observable(alone) == observable(whole) == observable(stepped)
