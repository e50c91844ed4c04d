"""SOFTLIMITREVERSE must be less than SOFTLIMITFORWARD (000:16000, 16142): a write that breaks it is error 3.

The guide names no error; the choice (AX-15 in runtime/BEHAVIOUR.md) is the
out-of-range error on the axis written, with the limit left as it was.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

SHOW = 'PRINT SOFTLIMITREVERSE.0, " ", SOFTLIMITFORWARD.0\n'
HANDLER = 'END\n#ONERROR\nPRINT "error ", ERR, " line ", ERL\nRETURN\n'


def test_a_reverse_limit_equal_to_the_forward_one_is_refused_with_error_3() -> None:
    result = simulate("SOFTLIMITFORWARD.0 = 500\nSOFTLIMITREVERSE.0 = 500\n" + SHOW)
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 2)
    assert "SOFTLIMITREVERSE 500 must be below SOFTLIMITFORWARD 500" in result.stop.message


def test_moving_the_window_down_takes_the_reverse_limit_first() -> None:
    # from forward 1000 / reverse 500 to forward 100 / reverse -100: forward first would cross the reverse limit
    start = "SOFTLIMITFORWARD.0 = 1000\nSOFTLIMITREVERSE.0 = 500\n"
    reverse_first = simulate(start + "SOFTLIMITREVERSE.0 = -100\nSOFTLIMITFORWARD.0 = 100\n" + SHOW)
    assert reverse_first.terminal == "-100 100\n"
    forward_first = simulate(start + "SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = -100\n" + SHOW + HANDLER)
    assert forward_first.terminal == "error 3 line 3\n-100 1000\n"


def test_the_limits_compare_in_the_units_scale_gives_them() -> None:
    # SCALE 10: forward 100 is 1000 counts; reverse 99.5 is 995 counts, below it; 100 is not
    result = simulate("SCALE.0 = 10\nSOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 99.5\n" + SHOW)
    assert result.terminal == "99.5 100\n"
    refused = simulate("SCALE.0 = 10\nSOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 100\n")
    assert (refused.err, refused.erl) == (3, 3)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.booleans(), st.integers(-1000, 1000)), min_size=1, max_size=4))
def test_whatever_is_written_the_reverse_limit_stays_below_the_forward_one(writes: list[tuple[bool, int]]) -> None:
    lines = "".join(f"SOFTLIMIT{'FORWARD' if forward else 'REVERSE'}.0 = {value}\n" for forward, value in writes)
    source = lines + 'IF SOFTLIMITREVERSE.0 >= SOFTLIMITFORWARD.0 THEN PRINT "crossed"\nEND\n#ONERROR\nRETURN\n'
    assert simulate(source).terminal == ""
