"""The keyword usage rule (``mintlang/analysis/rules/keyword_usage.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import mintlang
from tests.analysis.checking import ERROR, covered, found, only


def test_writing_a_read_only_keyword_is_error_2000() -> None:
    # line 18905: e.g. CAMINDEX = 4
    assert found("CAMINDEX = 4\n") == [("E2000", ERROR, 1)]


def test_reading_a_write_only_keyword_is_error_2002() -> None:
    # line 18915: PRINT "Acceleration time is ", ACCELTIME
    assert found("DIM a\na = ACCELTIME\n") == [("E2002", ERROR, 2)]
    assert found('PRINT "Acceleration time is ", ACCELTIME\n') == [("E2002", ERROR, 1)]


def test_a_parameter_alone_as_a_statement_is_error_2005() -> None:
    # line 18930: SPEED : REM ** Axis Slew Speed **
    assert found("SPEED\n") == [("E2005", ERROR, 1)]
    assert found("SPEED : REM ** Axis Slew Speed **\n") == [("E2005", ERROR, 1)]


def test_an_editor_command_in_a_program_is_error_2006() -> None:
    # line 18939: "command line editor command (e.g. NEW, EDIT, etc) cannot be used within a program"
    assert found("NEW\n") == [("E2006", ERROR, 1)]


def test_a_misspelt_keyword_with_a_dot_parameter_is_error_3007() -> None:
    # line 4771 misprints DRIVEENABLE as DRIVENABLE; line 19111: #3007 Keyword not defined
    assert found("DRIVENABLE.0 = 1\n") == [("E3007", ERROR, 1)]


def test_an_unknown_word_as_a_statement_is_error_3007() -> None:
    # line 19111: #3007 Keyword not defined
    assert found("GO\nFOO\n") == [("E3007", ERROR, 2)]


def test_a_misspelt_keyword_with_an_axis_list_is_error_3007() -> None:
    diagnostic = only("DRIVENABLE[0] = 1\n", "E3007")
    assert covered("DRIVENABLE[0] = 1\n", diagnostic) == "DRIVENABLE"
    assert found("DRIVENABLE[0] = 1\n") == [("E3007", ERROR, 1)]


def test_a_misspelt_keyword_with_a_variable_dot_parameter_is_error_3007() -> None:
    assert found("DIM a\nDRIVENABLE.a = 1\n") == [("E3007", ERROR, 2)]


def test_a_keyword_the_controller_lacks_is_error_17() -> None:
    # line 9420: DRIVEENABLESWITCH has attributes for MintDrive only; line 18570: #17
    assert found("DIM a\na = DRIVEENABLESWITCH\n") == [("E0017", ERROR, 2)]
    assert found("DIM a\na = DRIVEENABLESWITCH\n", controller="mintdrive") == []


def test_dac_of_the_one_axis_is_read_on_mintdrive() -> None:
    # 000:8778-8793 reads DAC on MintDrive; footnote 7 (5666): no difference between axis and channel keywords
    assert found("DIM d\nd = DAC.0\nPRINT d\n", controller="mintdrive") == []
    assert [code for code, _, _ in found("DIM d\nd = DAC.1\nPRINT d\n", controller="mintdrive")] == ["E0004"]


def test_a_keyword_the_controller_lacks_is_not_also_a_channel_out_of_range() -> None:
    assert found("DIM d\nd = AUXDAC.0\nPRINT d\n") == [("E0017", ERROR, 2)]


def test_release_is_allowed_in_a_configuration_file_only() -> None:
    # 000:935-939: RELEASE cannot be used in a program; the configuration file is where it belongs
    assert found("PRINT 1\n", config="RELEASE\n") == []
    assert found("RELEASE\n") == [("E2006", ERROR, 1)]


def test_a_keyword_whose_formats_only_read_it_cannot_be_written() -> None:
    # ERR (v = ERR), ERL and INKEY have no attribute table; their formats only read them
    assert [code for code, _, _ in found("ERR = 0\nERL = 0\nINKEY = 5\n")] == ["E2000"] * 3


def test_abbreviations_are_checked_like_the_full_keyword() -> None:
    assert found("sp\n") == [("E2005", ERROR, 1)]
    assert found("sp = 10\n") == []


def test_an_abbreviation_two_keywords_share_means_the_one_recorded_in_conflicts() -> None:
    # SI: STOPINPUT (16408, quick reference 17768), not the advanced STEPPERIO (quick reference SIO, 18181)
    assert found("SI[0,1] = 10,10\n", controller="nextmove-bx") == []
    assert found("SI[0,1] = 10,10\n", controller="mintdrive") == [("E2017", ERROR, 1)]  # one axis only


def test_auto_anywhere_but_first_in_the_configuration_file_is_ignored() -> None:
    # AUTO (v4:6645-6648): first command of the configuration file, REM included; ignored anywhere else
    def codes(config: str, program: str = "PRINT 1\n") -> tuple[list[str], list[str]]:
        analysis = mintlang.check_application(program, config=config, controller="nextmove-bx")
        return [d.code for d in analysis.configuration], [d.code for d in analysis.program]

    assert codes("AUTO\nREM set-up\n") == ([], [])
    assert codes("\ufeff\n  auto : SCALE = 1\n") == ([], [])
    assert codes("REM set-up\nAUTO\n") == (["W114"], [])
    assert codes("REM set-up\n", "AUTO\nPRINT 1\n") == ([], ["W114"])
    # NextMove PCI has no AUTO at all: error 17 says so, without W114
    assert found("AUTO\nPRINT 1\n") == [("E0017", ERROR, 1)]


def test_relay_is_read_and_written_as_its_formats_show() -> None:
    # v4:15460-15461; reading IDLE is fine, writing it is not (v4:11738 "IDLE returns ...")
    assert found("DIM value\nvalue = RELAY.0\nRELAY.0 = 1\nvalue = IDLE.0\n") == []
    assert [code for code, _, _ in found("IDLE.0 = 1\n")] == ["E2000"]


def test_a_value_written_to_a_read_only_keyword_is_not_also_out_of_its_range() -> None:
    # IDLE returns 0 or 1 (000:11742) and cannot be written: the write is error 2000 alone, where "10 is
    # outside the range of IDLE (0 or 1)" said that 1 could be written. A Mint v3 idle window read as v4
    # (IDLE.0 = 10, 001:8772-8778) writes it so.
    assert found("IDLE.0 = 10\n") == [("E2000", ERROR, 1)]


def test_an_abbreviation_two_keywords_share_means_the_one_the_controller_has() -> None:
    # HP is HOMEPOS on a NextMove (v4:11581) and HANDLERPENDING on a MintDrive (v4:11314)
    assert found("DIM a\na = HP.1\n", controller="nextmove-pci") == []
    for controller, keyword in (("nextmove-pci", "HOMEPOS"), ("mintdrive", "HANDLERPENDING")):
        printed = mintlang.parse("PRINT HP\n", controller=controller).lines[0].statements[0].items[0].value
        assert printed.keyword == keyword
