"""Advanced-guide keywords set per axis take the AXES list, as every axis keyword does.

The guide defers SRAMP, IDLEPOS, IDLEVEL, KACCEL, KINTMODE, FOLERRORMODE, ERRORINPUTMODE, MOVEBUFFERSIZE,
MOVEBUFFERFREE and HOMEPOS to the Advanced guide and prints no format for them, yet each belongs to an axis:
``FOLERRORMODE[2] = 0`` (000:7280), ``PRINT MOVEBUFFERFREE.5`` (000:2982), each axis its own move buffer
(000:2870-2871), IDLEPOS and IDLEVEL among the axis variables DEFAULT[axes] resets (000:8983, 9036-9037),
KACCEL and KINTMODE terms of an axis's servo loop beside KPROP (000:430-442), ERRORINPUTMODE the action of
an axis's error input (000:4667-4671), HOMEPOS the axis position before homing cleared it (000:3436-3438).
Written without a selector, an axis keyword writes every axis AXES names (000:599-608, 000:6915-6920), ``;``
giving the last value to the rest (000:654-658), and more values than axes is error 2017 (000:572-580,
000:19047); an axis the controller lacks is error 2 (000:18514-18517). ``mint check`` and ``mint-run`` agree.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("write", "read", "printed"),
    [
        pytest.param("SRAMP = 50;", "SRAMP", "0 50 50", id="SRAMP filled"),
        pytest.param("IDLEPOS = 7,8", "IDLEPOS", "1000 7 8", id="IDLEPOS"),
        pytest.param("IDLEVEL = 3;", "IDLEVEL", "0 3 3", id="IDLEVEL"),
        pytest.param("KACCEL = 2,4", "KACCEL", "0 2 4", id="KACCEL"),
        pytest.param("KINTMODE = 0;", "KINTMODE", "1 0 0", id="KINTMODE"),
        pytest.param("FOLERRORMODE = 2;", "FOLERRORMODE", "1 2 2", id="FOLERRORMODE"),
        pytest.param("ERRORINPUTMODE = 3,0", "ERRORINPUTMODE", "1 3 0", id="ERRORINPUTMODE"),
        pytest.param("MOVEBUFFERSIZE = 5,6", "MOVEBUFFERSIZE", "2 5 6", id="MOVEBUFFERSIZE"),
    ],
)
def test_a_write_without_axes_goes_to_the_axes_list(write: str, read: str, printed: str) -> None:
    """Defaults from the DEFAULT table (000:9036-9037) and the runtime's power-up values (BEHAVIOUR.md)."""
    program = f'AXES[1,2]\n{write}\nPRINT {read}.0, " ", {read}.1, " ", {read}.2\n'
    assert placed(program, "code") == []
    result = run_source(program, controller="nextmove-pci")
    assert result.terminal == printed + "\n"


def test_a_read_without_axes_is_the_first_of_the_list() -> None:
    """``PRINT MOVEBUFFERSIZE`` after AXES[1,2] reads axis 1, as PAUSE IDLE reads the first AXES axis
    (000:663-666)."""
    result = run_source("AXES[1,2]\nMOVEBUFFERSIZE = 5,6\nPRINT MOVEBUFFERSIZE\n", controller="nextmove-pci")
    assert result.terminal == "5\n"


@pytest.mark.parametrize(
    ("line", "code", "at"),
    [
        pytest.param("AXES[0,1]\nSRAMP = 1,2,3\n", "E2017", "3", id="more values than the AXES list"),
        pytest.param("IDLEPOS[0,1] = 1,2,3\n", "E2017", "3", id="more values than the bracket list"),
        pytest.param("SRAMP.13 = 1\n", "E0002", "13", id="an axis the controller lacks"),
        pytest.param("DIM a\na = MOVEBUFFERFREE.13\n", "E0002", "13", id="a read of an axis it lacks"),
    ],
)
def test_the_axis_rules_hold_in_both_tools(line: str, code: str, at: str) -> None:
    assert placed(line, "code", "text", codes=code) == [(code, at)]
    result = run_source(line, controller="nextmove-pci")
    assert result.err == int(code[1:])
