"""Block lines whose text repeats each keep their own place (the parser shares one syntax per line text).

Every case below failed while the runtime keyed statements by the identity of
their syntax: the last of the equal lines won. Expected outputs follow the v4
guide's block rules (section 3.8, lines 1563-1840).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

CASES = [
    pytest.param(
        "DIM a\nFOR a = 1 TO 2\n  PRINT a\nNEXT\nFOR a = 1 TO 2\n  PRINT a\nNEXT\n", "1\n2\n1\n2\n", id="two-for"
    ),
    pytest.param(
        "DIM a\nWHILE a < 2\n  a = a + 1\n  PRINT 1\nENDW\na = 0\nWHILE a < 2\n  a = a + 1\n  PRINT 2\nENDW\n",
        "1\n1\n2\n2\n",
        id="two-while",
    ),
    pytest.param(
        'DIM a\nIF a DO\n  PRINT "x"\nENDIF\nPRINT "between"\nIF a DO\n  PRINT "y"\nENDIF\nPRINT "after"\n',
        "between\nafter\n",
        id="false-if-do-twice",
    ),
    pytest.param(
        'DIM a\nIF a DO\n  PRINT "x"\nELSE\n  PRINT "else 1"\nENDIF\n'
        'IF a DO\n  PRINT "y"\nELSE\n  PRINT "else 2"\nENDIF\n',
        "else 1\nelse 2\n",
        id="two-else",
    ),
    pytest.param(
        "DIM a\nREPEAT\n  a = a + 1\n  PRINT a\nUNTIL a > 2\na = 0\nREPEAT\n  a = a + 1\n  PRINT a\nUNTIL a > 2\n",
        "1\n2\n3\n1\n2\n3\n",
        id="two-repeat",
    ),
    pytest.param(
        "DIM a\nLOOP\n  a = a + 1\n  IF a > 1 THEN EXIT\nENDL\n"
        "LOOP\n  a = a + 1\n  IF a > 3 THEN EXIT\nENDL\nPRINT a\n",
        "4\n",
        id="two-loop",
    ),
    pytest.param(
        "DIM i\nDIM j\nFOR i = 1 TO 2\n  FOR j = 1 TO 2\n    PRINT i * 10 + j\n  NEXT\nNEXT\n",
        "11\n12\n21\n22\n",
        id="nested-next-next",
    ),
]


@pytest.mark.parametrize(("source", "output"), CASES)
def test_each_block_line_runs_at_its_own_place(source: str, output: str) -> None:
    result = simulate(source)
    assert result.stop.reason is StopReason.END, result.stop
    assert result.terminal == output
