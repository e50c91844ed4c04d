"""The addressing rule (``mintlang/analysis/rules/addressing.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import pytest

from tests.analysis.checking import ERROR, covered, found, only


@pytest.mark.parametrize("source", ["SPEED[0,,2]=1000;\n", "SPEED[0,1,]=1000;\n"])
def test_an_empty_place_in_an_axis_list_is_error_2001(source: str) -> None:
    # line 18909: both examples of #2001
    assert found(source) == [("E2001", ERROR, 1)]


def test_more_axes_than_the_controller_has_is_error_2017() -> None:
    # line 19047: SPEED[0,1,3] = 5000; is valid on a 4 axes controller, invalid on a single axis one
    assert found("AXES[0,1,3]\nSPEED[0,1,3] = 5000;\n") == []
    assert found("AXES[0,1,3]\nSPEED[0,1,3] = 5000;\n", controller="mintdrive") == [
        ("E2017", ERROR, 1),
        ("E2017", ERROR, 2),
    ]


def test_more_values_than_listed_axes_is_error_2017() -> None:
    # line 575: MOVEA[0,1] = 100,150,500 is invalid; line 578: MOVEA[0,1,2] = 10,20 is valid
    source = "MOVEA[0,1] = 1,2,3\n"
    diagnostic = only(source, "E2017")
    assert covered(source, diagnostic) == "3"
    assert found("MOVEA[0,1] = 100,150,500\n") == [("E2017", ERROR, 1)]
    assert found("MOVEA[0,1,2] = 10,20\n") == []


def test_a_one_axis_controller_takes_one_value_for_its_default_axes() -> None:
    # 000:572: no more values than axes; on MintDrive and ServoNode the axes can only be [0] (#2017, 19047)
    source = "SPEED = 1,2\nSPEED = ,5\nSPEED = 3\n"
    assert found(source, controller="mintdrive") == [("E2017", ERROR, 1), ("E2017", ERROR, 2)]
    assert found(source) == []  # NextMove PCI: the default axes may be several


def test_an_axis_listed_twice_is_error_2018() -> None:
    # line 19053: AXES[0,1,1,2] and SPEED [2,2,3] = 5000;
    assert found("SPEED[2,2,3] = 5000;\n") == [("E2018", ERROR, 1)]
    assert found("AXES[0,1,1,2]\n") == [("E2018", ERROR, 1)]


def test_an_axis_beyond_the_controller_is_error_2() -> None:
    # line 5613: NextMove BX axes 0 to 7; line 18514: #2 Axis specified out of range
    assert found("SPEED.12 = 1\n", controller="nextmove-bx") == [("E0002", ERROR, 1)]
    assert found("SPEED.8 = 1\n", controller="nextmove-bx") == [("E0002", ERROR, 1)]
    assert found("SPEED.7 = 1\n", controller="nextmove-bx") == []
    assert found("SPEED.8 = 1\n", controller="nextmove-pci") == []


@pytest.mark.parametrize(
    ("source", "controller", "code"),
    [
        # line 5613, the Dot Parameters table; errors 4, 7 and 8 of section 12.2 (line 18522)
        ("DIM v\nv = ADC.8\n", "nextmove-bx", "E0004"),
        ("DIM v\nv = ADC.4\n", "mintdrive", "E0004"),
        ("DIM v\nv = IN16\n", "nextmove-bx", "E0007"),
        ("DIM v\nv = IN.16\n", "nextmove-bx", "E0007"),
        ("DIM v\nv = IN60\n", "nextmove-pci", "E0007"),
        ("OUT8 = 1\n", "nextmove-bx", "E0008"),
        ("OUT.3 = 1\n", "servonode51", "E0008"),
    ],
)
def test_a_channel_beyond_the_controller_is_an_error(source: str, controller: str, code: str) -> None:
    line = source.count("\n")
    assert found(source, controller=controller) == [(code, ERROR, line)]


@pytest.mark.parametrize(
    ("source", "controller"),
    [
        ("DIM v\nv = ADC.7\n", "nextmove-bx"),
        ("DIM v\nv = IN15\n", "nextmove-bx"),
        ("DIM v\nv = IN59\n", "nextmove-pci"),
        ("OUT7 = 1\n", "nextmove-bx"),
        ("OUT.2 = 1\n", "servonode51"),
    ],
)
def test_the_highest_channel_of_the_controller_is_accepted(source: str, controller: str) -> None:
    assert found(source, controller=controller) == []


def test_an_expression_in_an_axis_list_is_a_syntax_error() -> None:
    # line 586: MOVER[a+1] = 100 is invalid; line 583: MOVER[a] = 100 is valid
    source = "DIM a\nMOVER[a+1] = 100\n"
    assert found(source) == [("E2003", ERROR, 2)]
    assert covered(source, only(source, "E2003")) == "a+1"
    assert [code for code, _, _ in found("DIM a\nMOVER[a] = 100\n") if code.startswith("E")] == []


def test_a_channel_keyword_with_brackets_is_a_syntax_error() -> None:
    # line 708: v = ADC[1] is invalid; v = ADC.1 is the channel syntax
    assert found("DIM v\nv = ADC[1]\n") == [("E2003", ERROR, 2)]
    assert found("DIM v\nv = ADC.1\n") == []
