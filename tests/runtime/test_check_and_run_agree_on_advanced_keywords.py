"""mint check and mint-run judge alike a line using a keyword the guide prints no attributes table for.

Such keywords have no attributes table in the v4 guide (HOMEPOS, EVENTACTIVE, FOLERRORMODE: "This is an
advanced Mint feature", 000:11581-11583, 10112-10114, 10692-10694). What the guide says of them elsewhere is
the same for both tools: HOMEPOS "can be read" (000:3438, 11401-11402), EVENTACTIVE and MOVEBUFFERFREE are
read in the quick reference (000:18061, 17689), so a write is error 2000 ("Read only or Command",
000:18905-18908). FOLERRORMODE takes the modes of LIMITMODE's table, 0 to 3 and 5 (000:13479-13493; the
runtime specification's AX-10): 4, smart mode, anticipates a software limit only (000:16057). A bit pattern
takes a fraction inside its printed range (INPUTMODE 0 to 1048575, 000:12336) by its whole part, as the
checker, which checks the printed range, lets it through. DACMODE, GEARING, GEARINGMODE and KEYPADNODE are
settings: the guide's examples only assign them (000:4188, 3746-3747, 2077), so one named alone is neither
read nor assigned, error 2005 (000:18930-18933), and given an operand without '=' a syntax error.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


def _checked(line: str) -> list[str]:
    return [d.code for d in mintlang.check(line + "\n", controller="nextmove-pci") if d.code.startswith("E")]


@pytest.mark.parametrize(
    ("line", "code"),
    [
        pytest.param("HOMEPOS.0 = 5", 2000, id="HOMEPOS"),
        pytest.param("EVENTACTIVE = 1", 2000, id="EVENTACTIVE"),
        pytest.param("MOVEBUFFERFREE.0 = 3", 2000, id="MOVEBUFFERFREE"),
        pytest.param("FOLERRORMODE.0 = 4", 3, id="FOLERRORMODE-4"),
        pytest.param("ERRORINPUTMODE.0 = 6", 3, id="ERRORINPUTMODE-6"),
        pytest.param("SRAMP.0 = 101", 3, id="SRAMP-101"),
    ],
)
def test_both_tools_give_the_same_error(line: str, code: int) -> None:
    assert _checked(line) == [f"E{code:04d}"]
    result = simulate(f'{line}\nPRINT "after"\n' + HANDLER, controller="nextmove-pci")
    assert result.terminal.startswith(f"ERR {code} ERL 1\n")


@pytest.mark.parametrize(
    ("line", "code"),
    [
        pytest.param("DACMODE.1", 2005, id="DACMODE"),
        pytest.param("GEARING.0", 2005, id="GEARING"),
        pytest.param("GEARINGMODE", 2005, id="GEARINGMODE"),
        pytest.param("KEYPADNODE._tmLCD1", 2005, id="KEYPADNODE"),
        pytest.param("GEARINGMODE.0 1", 2003, id="GEARINGMODE-given-an-operand"),
    ],
)
def test_a_setting_named_alone_is_the_same_error_in_both_tools(line: str, code: int) -> None:
    assert _checked(line) == [f"E{code:04d}"]
    assert simulate(f"{line}\n", controller="nextmove-pci").err == code


@pytest.mark.parametrize("line", ["FOLERRORMODE.0 = 5", "FOLERRORMODE.0 = 0", "INPUTMODE = 0.5", "PRINT HOMEPOS.0"])
def test_both_tools_pass_the_line(line: str) -> None:
    assert _checked(line) == []
    result = simulate(f'{line}\nPRINT "after"\n', controller="nextmove-pci")
    assert result.stop.reason is StopReason.END and result.terminal.endswith("after\n")


def test_a_fraction_in_a_bit_pattern_is_taken_by_its_whole_part() -> None:
    # 3.7 -> 3: inputs 0 and 1 edge triggered; 0.5 -> 0: none
    source = "INPUTMODE = 3.7\nPRINT INPUTMODE\nINPUTMODE = 0.5\nPRINT INPUTMODE\n"
    assert simulate(source, controller="nextmove-pci").terminal == "3\n0\n"


def test_reading_a_command_stops_both_before_the_run() -> None:
    # TRON's only format is the bare command (000:16922): like PRINT GO, a syntax error the compiler finds
    assert _checked("DIM a = TRON") == ["E2003"]
    result = simulate('PRINT "before"\nDIM a = TRON\n', controller="nextmove-pci")
    assert (result.stop.reason, result.err, result.terminal) == (
        StopReason.ERROR,
        2003,
        "C2003: PROGRAM Syntax error [line 2]\n",
    )


def test_lasterr_reads_success_when_no_program_has_ended_on_an_error() -> None:
    # "to return the last known error condition which resulted in program termination" (000:13270-13282): a run
    # starts at power-up, so none has; -1 is the error list's "Success" (000:18508-18510)
    assert _checked("PRINT LASTERR") == []
    assert simulate("PRINT LASTERR\n", controller="nextmove-pci").terminal == "-1\n"


def test_lasterr_as_a_statement_has_no_message_to_display_and_the_program_goes_on() -> None:
    # LASTERR alone is its format (000:13279-13280); it displays the error that ended a program, and none has
    # before a run that starts at power-up: nothing is printed, and the next line runs
    assert _checked("LASTERR") == []
    result = simulate('LASTERR\nPRINT "on"\n', controller="nextmove-pci")
    assert (result.stop.reason, result.terminal) == (StopReason.END, "on\n")
