"""The values rule (``mintlang/analysis/rules/values.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

from tests.analysis.checking import ERROR, found, only


def test_a_constant_outside_the_keywords_range_is_error_3() -> None:
    # line 534: SCALE = -1 gives "Out of range" (#3, line 18518)
    assert found("SCALE = -1\n") == [("E0003", ERROR, 1)]
    assert found("SCALE = 10\n") == []


def test_a_bound_printed_with_less_than_is_left_out() -> None:
    # 000:14910-14913: OUT is 0 ≤ x < 4096 on NextMove PCI and 0 ≤ x < 256 on NextMove BX
    assert found("OUT = 4096\nOUT = 4095\n") == [("E0003", ERROR, 1)]
    assert found("OUT = 256\nOUT = 255\n", controller="nextmove-bx") == [("E0003", ERROR, 1)]


def test_a_scaled_keyword_is_checked_only_for_the_sign_the_scale_cannot_change() -> None:
    # the range of a scaled keyword applies to the value times the scale factor (line 5649), and the scale
    # factor is positive (000:534-537): SPEED is 1.0 ≤ x, ACCEL 0.0 < x, FOLERRORFATAL 0 ≤ x (§10.3)
    assert found("SPEED = 0.5\nSPEED = 2000\nFOLERRORFATAL = 0\nACCEL = 0.01\n") == []
    source = "SPEED = -5\nSPEED = 0\nACCEL = 0\nFOLERRORFATAL = -1\n"
    assert found(source) == [("E0003", ERROR, 1), ("E0003", ERROR, 2), ("E0003", ERROR, 3), ("E0003", ERROR, 4)]
    assert only("ACCEL = 0\n", "E0003").message.endswith("(0.0 < x ≤ 8388607.0) whatever the scale factor")


def test_a_mode_keyword_takes_only_the_values_its_table_lists() -> None:
    # HOME is "0 .. 4, 6" and LIMITMODE "0 ≤ x ≤ 3, 5" in their attributes tables (§10.3)
    source = "HOME.0 = 5\nHOME.0 = 6\nHOME.0 = 4\nLIMITMODE.0 = 5\nLIMITMODE.0 = 4\nLIMITMODE.0 = 9\n"
    assert found(source) == [("E0003", ERROR, 1), ("E0003", ERROR, 5), ("E0003", ERROR, 6)]
