"""A v3 run judges a keyword's use by the v3 guide's attribute ticks, as ``mint check --dialect v3`` does, not by
the v4 entry of the same name.

Writing ``VEL`` sets the idle velocity (001:12480), where v4's ``VEL`` is read only; ``OFFSET`` is written in
its own example (001:10409); ``ACCELTIME``'s table ticks a read (001:5703). None is a programming error, so the
run goes on or says it does not simulate the line. A use the ticks leave out is "Read only or Command", a write
or the read of a command (001:13083-13094), or "Write only" (001:13073-13080): an editor command, which
cannot be in a program (001:5160, the error unnamed), given a value too. ``AXES`` on its own, which only
the command line takes, is a run time error in a program (001:1027, unnamed): "No expression" in both.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("VEL = 0", id="001:12480 writing VEL sets the idle velocity"),
        pytest.param("OFFSET = 10", id="001:10409 OFFSET's own example"),
        pytest.param("a = ACCELTIME", id="001:5703 ACCELTIME's table ticks Read"),
    ],
)
def test_a_use_the_v3_table_ticks_is_no_programming_error(line: str) -> None:
    stop = run_source(f"{line}\n", dialect="v3").stop
    assert stop.reason is StopReason.END or "not simulated" in stop.message
    assert mintlang.check(f"{line}\n", dialect="v3") == []


@pytest.mark.parametrize(
    ("line", "code", "message"),
    [
        pytest.param("CON = 1", "E2000", "Read only or Command", id="001:5160 an editor command given a value"),
        pytest.param("a = LIST", "E2000", "Read only or Command", id="001:13083-13094 an editor command read"),
        pytest.param("a = FLY", "E2002", "Write only", id="001:13073-13080 a write only keyword read"),
        pytest.param("AXES", "E2005", "No expression", id="001:1027 AXES on its own in a program"),
    ],
)
def test_a_use_the_v3_table_leaves_out_is_the_same_error_in_both(line: str, code: str, message: str) -> None:
    assert [d.code for d in mintlang.check(f"{line}\n", dialect="v3")] == [code]
    assert run_source(f"{line}\n", dialect="v3").terminal == f"ERROR: Program: {message} at line 1\n"
