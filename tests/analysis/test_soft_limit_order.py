"""SOFTLIMITREVERSE must be less than SOFTLIMITFORWARD (000:16000): W119 when constants break it.

The guide gives no error number, so it is a warning, and only a certain case is reported:
each limit written once on the axis, with a constant, on a constant axis.

A write without axes is made on the AXES default, every axis at power-up, its values taken in order and a
trailing ';' giving the last to the axes left (000:605-608, 617-639, 656-660): ``SOFTLIMITFORWARD = 100`` sets axis 0.
That default is certain while the program and its configuration write no AXES.
"""

from __future__ import annotations

import pytest

import mintlang


def _codes(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source)]


@pytest.mark.parametrize(
    "source",
    [
        "SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 99\n",  # just below
        "SOFTLIMITFORWARD[0,1] = 100, 5\nSOFTLIMITREVERSE[0,1] = -100, 4\n",
        "SOFTLIMITREVERSE.1 = 500\nSOFTLIMITFORWARD.0 = 100\n",  # different axes
        "SOFTLIMITREVERSE.0 = 500\n",  # the forward limit keeps its default, 8388607.0 (000:15996)
    ],
)
def test_a_reverse_limit_below_the_forward_one_is_accepted(source: str) -> None:
    assert _codes(source) == []


@pytest.mark.parametrize(
    "source",
    [
        "SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 100\n",  # equal is not less
        "SOFTLIMITREVERSE[2] = 101\nSOFTLIMITFORWARD[2] = 100\n",
        "SOFTLIMITFORWARD[0,1] = 100, 5\nSOFTLIMITREVERSE[0,1] = -100, 6\n",
        "slf.0 = 5\nslr.0 = 10\n",  # the abbreviations, in lower case (000:15957, 16098)
        "DEFINE reverse_limit = SOFTLIMITREVERSE.0\nSLF.0 = 5\nreverse_limit = 10\n",  # through a macro
    ],
)
def test_a_reverse_limit_at_or_above_the_forward_one_is_w119(source: str) -> None:
    assert _codes(source) == ["W119"]


def test_the_warning_points_at_the_reverse_value_and_names_the_forward_line() -> None:
    source = "SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 200\n"
    (diagnostic,) = mintlang.check(source)
    assert source[diagnostic.span.start : diagnostic.span.end] == "200"
    assert "line 1" in diagnostic.message


@pytest.mark.parametrize(
    "source",
    [
        "a = 0\nSOFTLIMITFORWARD.a = 100\nSOFTLIMITREVERSE.0 = 200\n",  # the axis is known at run time only
        "SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 200\nSOFTLIMITFORWARD.0 = 300\n",  # set twice: order matters
        "SCALE.0 = 1\nSOFTLIMITFORWARD.0 = 100\nSCALE.0 = 10\nSOFTLIMITREVERSE.0 = 20\n",
        "DIM r = 200\nSOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = r\n",
    ],
)
def test_what_is_not_certain_is_not_reported(source: str) -> None:
    assert "W119" not in _codes(source)


@pytest.mark.parametrize(
    ("source", "axis"),
    [
        ("SOFTLIMITFORWARD = -10\nSOFTLIMITREVERSE = 0\n", 0),
        ("SOFTLIMITFORWARD = 100;\nSOFTLIMITREVERSE = ,,200\n", 2),
        ("SOFTLIMITFORWARD.1 = 50\nSOFTLIMITREVERSE = -5, 60\n", 1),
    ],
)
def test_a_write_without_axes_is_on_the_default_axes(source: str, axis: int) -> None:
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.code == "W119"
    assert f"reverse software limit of axis {axis} " in diagnostic.message


@pytest.mark.parametrize(
    "source",
    [
        "SOFTLIMITFORWARD = -10\nSOFTLIMITREVERSE.1 = 0\n",  # the forward limit is axis 0's
        "AXES[1]\nSOFTLIMITFORWARD = -10\nSOFTLIMITREVERSE.0 = 0\n",  # AXES changed the default
    ],
)
def test_a_write_without_axes_is_not_taken_for_another_axis(source: str) -> None:
    assert _codes(source) == []
