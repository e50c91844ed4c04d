"""A DECEL write is kept as it is, with no manual item: v3 obeyed it too, until the next ACCEL write.

The v3 guide's DECEL entry: with AXISCON bit 0 off "DECEL can be used, but any write to ACCEL will overwrite
the DECEL value with ACCEL" (001:7203); AXISCON's bit 0 "will allow the ACCEL value to over-write the DECEL
value" (001:6027). So ``ACCEL = 20000; : DECEL = 5000;`` decelerates at 5000 in v3 as in v4 (000:8900), and
what v4 lacks is only the overwrite, which S-ACCEL writes beside every ACCEL. The manual item saying "v3
ignored DECEL unless AXISCON bit 0 was set" told the engineer the opposite of the v3 guide.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def test_a_decel_alone_is_left_unflagged() -> None:
    result = migrate("DECEL = 5000;\n", only=["S-ACCEL"])
    assert (result.text, result.manual) == ("DECEL = 5000;\n", ())


def test_a_decel_after_an_accel_keeps_its_own_value() -> None:
    # v3: ACCEL = 20000 also set DECEL 20000, then DECEL = 5000 set it to 5000; v4 the same in writing order
    result = migrate("ACCEL = 20000;\nSPEED = 5 : DECEL = 5000;\n", only=["S-ACCEL"])
    assert result.text == "ACCEL = 20000; : DECEL = 20000;\nSPEED = 5 : DECEL = 5000;\n"
    assert result.manual == ()


def test_a_decel_before_an_accel_is_overwritten_in_both() -> None:
    # v3: the later ACCEL write overwrote DECEL (001:7203); v4: the DECEL written beside it does
    result = migrate("DECEL.1 = 5000\nACCEL.1 = 20000\n", only=["S-ACCEL"])
    assert result.text == "DECEL.1 = 5000\nACCEL.1 = 20000 : DECEL.1 = 20000\n"
    assert result.manual == ()
