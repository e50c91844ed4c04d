"""CAMTABLE is always given three values: NULL stands where there is no master increment array.

The format braces the master increment array (``CAMTABLE ( axis, position array, {master increment
array} )``, 000:7907), and the entry says what leaving it out means: the array name is optional, and
where none is given NULL must be written instead (000:7957-7958), as every example does (000:3869,
7693, 7792, 7971). A call with the axis and the position array alone is given fewer values than the
statement takes: error 2003, as for any function given a wrong count (000:18920-18925), in ``mint
check`` and, before the program starts, in ``mint-run``.
"""

from __future__ import annotations

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

WITHOUT_NULL = 'DIM p(3) = 2, 10, 20\nPRINT "before"\nCAMTABLE(0, p)\n'


def test_the_axis_and_position_array_alone_are_error_2003_at_the_call() -> None:
    assert placed_codes(WITHOUT_NULL) == [("E2003", 3, 1)]


def test_the_message_asks_for_null_in_place_of_the_master_array() -> None:
    (diagnostic,) = mintlang.check(WITHOUT_NULL)
    assert "CAMTABLE takes 3 values" in diagnostic.message
    assert "NULL" in diagnostic.message
    assert diagnostic.message.endswith("not 2")


def test_mint_run_refuses_it_before_the_program_starts() -> None:
    result = simulate(WITHOUT_NULL)
    assert result.stop.reason is StopReason.ERROR
    assert result.err == 2003
    assert "before" not in result.terminal
    assert result.terminal.startswith("C2003: PROGRAM Syntax error")


def test_null_or_a_master_array_in_third_place_is_clean() -> None:
    source = "DIM p(3) = 2, 10, 20\nDIM m(2) = 10, 10\nCAMTABLE(0, p, NULL)\nCAMTABLE(1, p, m)\n"
    assert placed_codes(source) == []
    assert simulate(source).stop.reason is not StopReason.ERROR
