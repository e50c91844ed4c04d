"""``mint check --dialect v3`` holds a v3 program to the v3 guide's nesting limits, as ``mint-run --dialect v3`` does.

The v3 guide's table (001:2381-2389, 12946-12955): IF .. DO 30 deep, FOR 8, GOSUB 20, and 30 blocks
in all (001:2409); past them the controller stops with "Too many levels of nesting". The check read
the limits of the v4 machine instead (FOR 50, GOSUB 100: 000:1959-1976), and passed what the run stops on.
"""

from __future__ import annotations

import mintlang
from mintlang.runtime.run import run_source


def _fors(depth: int) -> str:
    return "".join(f"FOR k{i} = 1 TO 1\n" for i in range(depth)) + "PRINT 1\n" + "NEXT\n" * depth


def _ifs(depth: int) -> str:
    return "IF 1 DO\n" * depth + "PRINT 1\n" + "ENDIF\n" * depth


def _chain(levels: int) -> str:
    """A main program whose GOSUB starts ``levels`` nested calls."""
    routines = "".join(f"#s{i}\nGOSUB s{i + 1}\nRETURN\n" for i in range(levels - 1))
    return f"GOSUB s0\nEND\n#s{levels - 1}\nPRINT 1\nRETURN\n{routines}"


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source, dialect="v3")]


def test_for_loops_nest_eight_deep() -> None:
    assert _codes(_fors(8)) == []
    assert _codes(_fors(9)) == ["E2015"]
    assert run_source(_fors(9), dialect="v3").terminal == "ERROR: Program: Too many levels of nesting at line 9\n"


def test_if_blocks_nest_thirty_deep() -> None:
    assert _codes(_ifs(30)) == []
    assert _codes(_ifs(31)) == ["E2015"]


def test_subroutines_nest_twenty_deep() -> None:
    assert _codes(_chain(20)) == []
    (deep,) = mintlang.check(_chain(21), dialect="v3")
    assert deep.code == "W116" and "Mint v3 allows 20" in deep.message
    assert run_source(_chain(21), dialect="v3").terminal.startswith("ERROR: Program: Too many levels of nesting")
