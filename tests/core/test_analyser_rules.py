"""The analyser's rules, one section per rule module of mintlang/analysis/rules.

Each test states the complete list of diagnostics a small program gets, as
(code, severity, 1-based line). Line numbers in comments refer to the Mint v4
programming guide (/work/shared/seeds/000_f3c82d19754128dd.txt).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Diagnostic

ERROR, WARNING, INFO = "error", "warning", "info"


def found(source: str, *, controller: str = "nextmove-pci", config: str | None = None) -> list[tuple[str, str, int]]:
    """The program's diagnostics as (code, severity, line)."""
    index = mintlang.LineIndex(source)
    return [
        (d.code, d.severity.value, index.position(d.span.start).line)
        for d in mintlang.check(source, controller=controller, config=config)
    ]


def only(source: str, code: str, **options) -> Diagnostic:
    """The single diagnostic of ``code`` in the program."""
    (diagnostic,) = [d for d in mintlang.check(source, **options) if d.code == code]
    return diagnostic


def covered(source: str, diagnostic: Diagnostic) -> str:
    return source[diagnostic.span.start : diagnostic.span.end]


def apply(source: str, edits) -> str:
    for edit in sorted(edits, key=lambda e: e.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source


# ------------------------------------------------------------ declarations


def test_a_variable_that_is_never_declared_is_error_3001_at_each_use() -> None:
    # line 19073: #3001 Variable undefined, use DIM
    assert found("PRINT 1\nspeedVal = 10\nPRINT speedVal\n") == [("E3001", ERROR, 2), ("E3001", ERROR, 3)]


def test_a_use_before_the_dim_is_error_3001_even_if_the_dim_follows() -> None:
    # line 897: variables must be declared before being used
    assert found("PRINT late\nDIM late\nPRINT late\n") == [("E3001", ERROR, 1)]


def test_the_3001_fix_inserts_a_dim_line_before_the_first_use() -> None:
    source = "REM start\n  speedVal = 10\nPRINT speedVal\n"
    first, second = [d for d in mintlang.check(source) if d.code == "E3001"]
    assert second.fixes == first.fixes  # each use offers the one DIM, placed above the first use
    (fix,) = first.fixes
    (edit,) = fix.edits
    line_two = source.index("  speedVal")
    assert (edit.span.start, edit.span.end) == (line_two, line_two)
    assert edit.text == "  DIM speedVal\n"


@pytest.mark.parametrize(
    "source",
    ["PRINT 1 : x = 2\nPRINT x\n", "\tIF 1 THEN x = 2\n", "a = 1\r\nPRINT a\r\n"],
)
def test_applying_the_3001_fix_removes_the_error(source: str) -> None:
    fix = next(d for d in mintlang.check(source) if d.code == "E3001").fixes[0]
    fixed = apply(source, fix.edits)
    assert [code for code, _, _ in found(fixed) if code.startswith("E")] == []


def test_the_3001_fix_keeps_the_files_line_breaks() -> None:
    (edit,) = next(d for d in mintlang.check("a = 1\r\nPRINT a\r\n") if d.code == "E3001").fixes[0].edits
    assert edit.text == "DIM a\r\n"


def test_a_misspelt_variable_gets_the_declared_name_it_resembles() -> None:
    source = "DIM target\ntarget = 1\nPRINT targt\n"
    diagnostic = only(source, "E3001")
    assert diagnostic.message.endswith("did you mean 'target'?")
    replace, declare = diagnostic.fixes
    assert (replace.title, apply(source, replace.edits)) == (
        "Replace with target",
        "DIM target\ntarget = 1\nPRINT target\n",
    )
    assert declare.title == "Declare 'targt' with DIM"


def test_a_misspelling_inside_a_macro_gets_no_replacement_of_the_macro_name() -> None:
    # the error points at the use of the macro; replacing that with 'counter' would drop the "+ 1"
    source = "DIM counter\nDEFINE inc = countr + 1\ncounter = inc\nPRINT counter\n"
    diagnostic = only(source, "E3001")
    assert diagnostic.message.endswith("did you mean 'counter'?")
    assert [fix.title for fix in diagnostic.fixes] == ["Declare 'countr' with DIM"]


def test_the_dim_goes_into_the_file_of_the_first_use_and_declares_it_for_both() -> None:
    # compiled first, the configuration's DIM serves the program too; a fix edits its own diagnostic's file,
    # so the program's squiggle offers no DIM (one there would leave the configuration's use undeclared)
    config = "REM set-up\nfoo = 5\n"
    program = "PRINT 1\nPRINT foo\n"
    analysis = mintlang.check_application(program, config=config)
    (in_program,) = [d for d in analysis.program if d.code == "E3001"]
    (in_configuration,) = [d for d in analysis.configuration if d.code == "E3001"]
    assert in_program.fixes == ()
    fixed_config = apply(config, in_configuration.fixes[0].edits)
    assert fixed_config == "REM set-up\nDIM foo\nfoo = 5\n"
    assert not [d for d in mintlang.check_application(program, config=fixed_config).program if d.code == "E3001"]
    # used in the program alone: the DIM goes into the program
    (alone,) = [d for d in mintlang.check_application(program, config="REM set-up\n").program if d.code == "E3001"]
    assert apply(program, alone.fixes[0].edits) == "DIM foo\nPRINT 1\nPRINT foo\n"


def test_a_character_whose_upper_case_is_two_keeps_its_own_code() -> None:
    assert mintlang.check("DIM a\na = 'ß'\nPRINT a\n") == []


def test_every_line_using_an_undeclared_variable_offers_one_dim_outside_the_loop_that_uses_it() -> None:
    source = "LOOP\n  total = total + 1\n  PRINT total\nENDL\n"
    diagnostics = [d for d in mintlang.check(source) if d.code == "E3001"]
    assert len(diagnostics) == 2
    fixed = {apply(source, d.fixes[0].edits) for d in diagnostics}
    assert fixed == {"DIM total\nLOOP\n  total = total + 1\n  PRINT total\nENDL\n"}


@pytest.mark.parametrize(
    ("source", "fixed"),
    [
        pytest.param(
            "DIM a\nLOOP\n  DIM b\n  c = 1\n", "DIM a\nDIM c\nLOOP\n  DIM b\n  c = 1\n", id="a block never closed"
        ),
        pytest.param(
            "LOOP\nENDL\nDIM a\nWHILE 1\n  DIM b\n  REPEAT\n    DIM d\n    c = 1\n",
            "LOOP\nENDL\nDIM a\nDIM c\nWHILE 1\n  DIM b\n  REPEAT\n    DIM d\n    c = 1\n",
            id="nested blocks never closed after a closed one",
        ),
    ],
)
def test_the_dim_goes_after_the_last_dim_outside_every_block_even_one_left_open(source: str, fixed: str) -> None:
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E3001"]
    assert apply(source, diagnostic.fixes[0].edits) == fixed


@pytest.mark.parametrize(
    ("source", "fixed"),
    [
        pytest.param(
            "REM top\nDIM a\nDIM xs(2) = 1,\n  2\nLOOP\n  DIM b : b = a\n  IF b DO\n    x = 1\n  ENDIF\nENDL\n",
            "REM top\nDIM a\nDIM xs(2) = 1,\n  2\nDIM x\nLOOP\n  DIM b : b = a\n  IF b DO\n    x = 1\n  ENDIF\nENDL\n",
            id="after-the-last-dim-outside-a-block",
        ),
        pytest.param(
            "REM Program title\n\n  LOOP\n    x = 1\n  ENDL\n",
            "REM Program title\n\n  DIM x\n  LOOP\n    x = 1\n  ENDL\n",
            id="above-the-first-statement-below-the-remarks",
        ),
        pytest.param("AUTO\nSPEED = 1\nx = 1\n", "AUTO\nDIM x\nSPEED = 1\nx = 1\n", id="auto-stays-first"),
        pytest.param("x = 1\nDIM a\n", "DIM x\nx = 1\nDIM a\n", id="dims-below-the-use-do-not-count"),
    ],
)
def test_the_dim_goes_with_the_files_other_dims_or_at_the_top(source: str, fixed: str) -> None:
    declare = next(d for d in mintlang.check(source) if d.code == "E3001").fixes[-1]
    assert apply(source, declare.edits) == fixed
    assert not [d for d in mintlang.check(fixed) if d.code == "E3001"]


def test_no_second_dim_is_offered_when_the_dim_comes_later() -> None:
    diagnostic = only("a = 1\nDIM a\n", "E3001")
    assert "comes later" in diagnostic.message and diagnostic.fixes == ()


def test_the_3001_fix_keeps_a_dim_list_continued_over_lines_whole() -> None:
    source = "DIM y(3) = 1,\nb, 2\n"
    (fix,) = only(source, "E3001").fixes
    fixed = apply(source, fix.edits)
    assert fixed == "DIM b\nDIM y(3) = 1,\nb, 2\n"
    assert [code for code, severity, _ in found(fixed) if severity == ERROR] == ["E2003"]  # b: a number is due


def test_gosub_to_an_unknown_label_is_error_3004() -> None:
    # line 19099: #3004 Invalid label
    assert found("GOSUB nowhere\nEND\n") == [("E3004", ERROR, 1)]
    assert found("DIM a\nIF a THEN GOTO nowhere\n") == [("E3004", ERROR, 2)]


def test_a_label_defined_twice_is_error_3004_at_the_second() -> None:
    # line 1844: "If two labels have the same name, an 'Invalid label' error is generated"
    assert found("GOSUB twice\nEND\n#twice\nRETURN\n#TWICE\nRETURN\n") == [("E3004", ERROR, 5)]


def test_a_number_or_keyword_cannot_name_a_macro_and_defines_none_that_could_be_unused() -> None:
    # line 19103: DEFINE 100 = "100" is not valid (3005)
    assert found('DEFINE 100 = "100"\nDEFINE speed = 3\n') == [("E3005", ERROR, 1), ("E3005", ERROR, 2)]


def test_a_macro_redefined_is_error_3005() -> None:
    assert found("DEFINE top = 10\nDEFINE top = 20\nPRINT top\n") == [("E3005", ERROR, 2)]


def test_a_name_redefined_within_its_first_ten_characters_is_the_error_alone() -> None:
    # line 1480: example_No1 and example_No2 are one macro; 3005 says why, W108 would say it again
    macros = "DEFINE example_No1 = 1\nDEFINE example_No2 = 2\nPRINT example_No1\nPRINT example_No2\n"
    assert found(macros) == [("E3005", ERROR, 2)]
    labels = "GOSUB example_No1\nEND\n#example_No1\nRETURN\n#example_No2\nRETURN\n"
    assert found(labels) == [("E3004", ERROR, 5)]
    assert "('example_No1' has the same first ten characters)" in only(labels, "E3004").message


def test_a_macro_whose_text_uses_another_macro_is_a_syntax_error() -> None:
    # line 1549: "A macro cannot contain the reference to another macro"
    source = "DEFINE myMacro = 1\nDEFINE myMove = MOVEA.myMacro = 100 : GO.myMacro\n"
    assert ("E2003", ERROR, 2) in found(source)
    (finding,) = (d for d in mintlang.check(source) if d.code == "E2003")
    assert source[finding.span.start : finding.span.end] == "myMacro"  # the first use, in MOVEA.myMacro
    assert finding.span.start == source.index("MOVEA.") + len("MOVEA.")


# ----------------------------------------------------------- keyword usage


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


def test_an_abbreviation_two_keywords_share_means_the_one_the_controller_has() -> None:
    # HP is HOMEPOS on a NextMove (v4:11581) and HANDLERPENDING on a MintDrive (v4:11314)
    assert found("DIM a\na = HP.1\n", controller="nextmove-pci") == []
    for controller, keyword in (("nextmove-pci", "HOMEPOS"), ("mintdrive", "HANDLERPENDING")):
        printed = mintlang.parse("PRINT HP\n", controller=controller).lines[0].statements[0].items[0].value
        assert printed.keyword == keyword


# -------------------------------------------------------------- addressing


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


# ------------------------------------------------------------------ values


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


# ------------------------------------------------------------------ arrays


def test_an_arrays_size_and_values_are_numbers_not_expressions() -> None:
    # 000:9171: <no_of_elements> and <array values> are Mint numbers and not expressions
    source = "DIM n = 5\nDIM a(n)\nDIM b(2*5)\nDIM c(2) = n, 2\nPRINT n, a(1), b(1), c(1)\n"
    assert found(source) == [("E2003", ERROR, 2), ("E2003", ERROR, 3), ("E2003", ERROR, 4)]
    numbers = "DIM e(4) = -1, 0x10, 'A', _TRUE\nPRINT e(1)\n"
    assert found(numbers) == []


def test_an_array_the_compiler_cannot_make_is_error_2016_at_its_dim() -> None:
    # 000:9171 and 19038: an array has <no_of_elements> elements, indexed 1 to that number, so a size that
    # is no whole number from 1 is no array, and a value beyond the size would have no index; its uses
    # are not reported again
    source = "DIM a(0)\nDIM b(2.5)\nDIM c(3) = 1, 2, 3, 4\nDIM d(3) = 1, 2, 3\nDIM e(3) = 1;\n"
    source += "PRINT a(1), b(1), c(1), d(3), e(3)\n"
    assert found(source) == [("E2016", ERROR, 1), ("E2016", ERROR, 2), ("E2016", ERROR, 3)]
    extra = only("DIM c(3) = 1, 2, 3, 4\nPRINT c(1)\n", "E2016")
    assert (extra.span.start, extra.message.endswith("c has 3 elements: 4 values are too many")) == (20, True)


def test_a_constant_index_outside_the_array_is_error_2016() -> None:
    # line 19038: indices are in the range 1 <= index <= size
    source = "DIM a(10)\na(0) = 1\na(11) = 2\na(10) = 3\na(1) = 4\nPRINT a(12)\n"
    assert found(source) == [("E2016", ERROR, 2), ("E2016", ERROR, 3), ("E2016", ERROR, 6)]


def test_an_element_of_a_plain_variable_is_error_2016() -> None:
    # 3.3: an array is declared with its size, DIM name(n); a plain variable has no elements
    assert found("DIM y\ny(2) = 1\n") == [("E2016", ERROR, 2)]


def test_the_manuals_invalid_index_example() -> None:
    # line 19041
    source = "DIM axis_speeds(100)\naxis_speeds(0) = 1000\naxis_speeds(101) = 2000\n"
    assert found(source) == [("E2016", ERROR, 2), ("E2016", ERROR, 3)]


# ------------------------------------------------------------------ events


def test_fastin_and_fastinx_together_are_error_3006() -> None:
    # line 19108: #3006 #FASTIN conflicts with #FASTINx
    assert found("END\n#FASTIN\nRETURN\n#FASTIN2\nRETURN\n") == [("E3006", ERROR, 4)]


def test_an_input_handler_for_an_input_the_controller_lacks_is_a_warning() -> None:
    # NextMove BX has digital inputs 0 to 15 (line 5613)
    assert found("END\n#IN20\nRETURN\n", controller="nextmove-bx") == [("W109", WARNING, 2)]
    assert found("END\n#IN15\nRETURN\n", controller="nextmove-bx") == []


def test_only_comms_locations_one_to_five_raise_an_event() -> None:
    # line 1898: #COMMS1 .. #COMMS5
    assert found("END\n#COMMS6\nRETURN\n") == [("W109", WARNING, 2)]
    assert found("END\n#COMMS5\nRETURN\n") == []


# ------------------------------------------------------------- v3 keywords


def test_a_mint_v3_keyword_is_an_undeclared_variable_that_says_what_it_became() -> None:
    # v4 has no HMSPEED ("replaced by HOMESPEED", v4 guide's HMSPEED entry): the controller rejects it as 3001
    source = "HMSPEED = 10\n"
    assert found(source) == [("E3001", ERROR, 1)]
    diagnostic = only(source, "E3001")
    assert "a Mint v3 keyword, replaced by HOMESPEED in v4" in diagnostic.message
    (fix,) = diagnostic.fixes  # the rename; no DIM for a whole old keyword
    fixed = apply(source, fix.edits)
    assert fixed == "HOMESPEED = 10\n"
    assert found(fixed) == []


def test_an_old_keyword_with_a_dot_parameter_is_an_unknown_keyword_named_too() -> None:
    (diagnostic,) = mintlang.check("HMSPEED.0 = 10\n")
    assert (diagnostic.code, [fix.title for fix in diagnostic.fixes]) == ("E3007", ["Replace with HOMESPEED"])


def test_a_v3_command_alone_on_a_line_is_an_unknown_keyword_that_says_what_it_became() -> None:
    # DINT "has been replaced by EVENTDISABLE" (000:9228-9229), CONTON by CONTOURMODE (000:8509): v4 takes
    # neither as a command, in a line of its own, after a colon or after THEN. Their replacements take a
    # value (EVENTDISABLE = …, CONTOURMODE = 1), so a rename alone would be wrong: no fix is offered.
    source = "DIM a\nDINT\nPRINT a : CONTON\nIF a THEN DINT\n"
    assert found(source) == [("E3007", ERROR, 2), ("E3007", ERROR, 3), ("E3007", ERROR, 4)]
    dint, conton, _ = mintlang.check(source)
    assert covered(source, dint) == "DINT" and "replaced by EVENTDISABLE in v4" in dint.message
    assert covered(source, conton) == "CONTON" and "replaced by CONTOURMODE in v4" in conton.message
    assert dint.fixes == () and conton.fixes == ()


def test_a_v3_keyword_the_v4_guide_has_no_entry_for_says_what_took_its_place() -> None:
    # GEARN (v3 guide: the gearbox numerator) has no "replaced by" entry in the v4 guide; the v3 keyword
    # table gives FOLLOW for it. It is no misspelling of GEARING, which is gearing compensation.
    (error,) = mintlang.check("GEARN.1 = 2\n")
    assert error.code == "E3007" and "Mint v3 keyword; v4 has FOLLOW instead" in error.message
    assert "GEARING" not in error.message and error.fixes == ()


def test_no_rename_is_offered_to_a_keyword_the_controller_lacks() -> None:
    # CURRLIMIT became CURRENTLIMIT, which the chapter 10 entry lists for MintDrive and ServoNode only
    (on_pci,) = mintlang.check("CURRLIMIT = 2\n")
    assert on_pci.code == "E3001" and on_pci.fixes == () and "NextMove PCI lacks" in on_pci.message
    (on_mintdrive,) = mintlang.check("CURRLIMIT = 2\n", controller="mintdrive")
    assert [fix.title for fix in on_mintdrive.fixes] == ["Replace with CURRENTLIMIT"]


def test_a_v3_keyword_whose_successor_the_controller_lacks_is_not_said_to_be_converted() -> None:
    # GEARD became FOLLOWDENOM (v3 keyword table), which the v4 entry lists for MintDrive and ServoNode 51
    # only; mint-migrate leaves it flagged on a NextMove, so "mint-migrate converts" would be wrong there
    (on_pci,) = mintlang.check("GEARD.1 = 2\n")
    assert "v4 has FOLLOWDENOM instead, which NextMove PCI lacks" in on_pci.message
    assert "mint-migrate converts" not in on_pci.message
    (on_mintdrive,) = mintlang.check("GEARD.1 = 2\n", controller="mintdrive")
    assert "v4 has FOLLOWDENOM instead (mint-migrate converts)" in on_mintdrive.message


def test_an_old_analog_input_is_not_renamed_alone_because_the_units_changed() -> None:
    (analogue,) = mintlang.check("DIM v\nv = ANALOGUE.1\n")
    assert analogue.code == "E3007" and analogue.fixes == () and "percent" in analogue.message


def test_a_mint_v3_constant_says_what_v4_calls_it() -> None:
    (constant,) = mintlang.check("CONFIG = _servo\n")
    assert constant.code == "E3001" and "a Mint v3 constant; v4 uses _cfSERVO" in constant.message
    assert [fix.title for fix in constant.fixes] == ["Replace with _cfSERVO"]


def test_a_whole_v3_keyword_used_as_a_variable_is_not_offered_a_dim() -> None:
    keyword, abbreviation = [d for d in mintlang.check("DIM x\nx = ANALOGUE1 + A2\n") if d.code == "E3001"]
    assert "it is a Mint v3 keyword; v4 has ADC instead" in keyword.message and keyword.fixes == ()
    assert "abbreviation of ANALOGUE2" in abbreviation.message  # a2 may well be a variable
    assert [fix.title for fix in abbreviation.fixes] == ["Declare 'A2' with DIM"]


def test_a_diagnostic_about_a_v3_word_says_so_but_not_one_about_a_name_that_looks_like_one() -> None:
    # the language server offers "migrate this file" for these
    source = "DIM x\nx = ANALOGUE1 + A2 + GAIN\nHMSPEED.0 = 10\nEND\n#FASTPOS\nRETURN\n"
    about_v3 = {covered(source, d): d.from_v3 for d in mintlang.check(source) if d.code != "W104"}
    assert about_v3 == {"ANALOGUE1": True, "A2": False, "GAIN": True, "HMSPEED": True, "#FASTPOS": True}


def test_a_declared_variable_named_like_an_old_keyword_is_not_renamed() -> None:
    assert [code for code, _, _ in found("DIM gain\nPRINT gain\n")] == []


def test_a_character_constant_of_two_characters_is_one_syntax_error() -> None:
    source = "DIM c\nc = 'ab'\nPRINT c\n"
    assert found(source) == [("E2003", ERROR, 2)]
    assert covered(source, only(source, "E2003")) == "'ab'"


def test_next_with_its_index_name_is_a_syntax_error_that_still_closes_the_for() -> None:
    # line 1712: "you must not append the index name after the NEXT statement"
    assert found("DIM a\nFOR a = 1 TO 3\nNEXT a\n") == [("E2003", ERROR, 3)]


def test_v3_keywords_are_not_reported_in_v3_code() -> None:
    assert mintlang.check("HMSPEED = 10\n", dialect="v3") == []


# ------------------------------------------------------------------- calls


def _chain(levels: int) -> str:
    """A main program whose GOSUB starts ``levels`` nested calls."""
    routines = "".join(f"#s{i}\nGOSUB s{i + 1}\nRETURN\n" for i in range(levels - 1))
    return f"GOSUB s0\nEND\n{routines}#s{levels - 1}\nRETURN\n"


def test_a_subroutine_that_calls_itself_nests_deeper_with_every_call() -> None:
    # every GOSUB nests a level until its RETURN; 100 levels at most (3.9, GOSUB notes)
    assert found("GOSUB count\nEND\n#count\nGOSUB count\nRETURN\n") == [("W115", WARNING, 4)]
    source = "GOSUB a\nEND\n#a\nGOSUB b\nRETURN\n#b\nIF 1 THEN GOSUB a\nRETURN\n"
    assert found(source) == [("W115", WARNING, 7)]
    assert covered(source, only(source, "W115")) == "GOSUB a"


def test_calls_nested_deeper_than_the_controller_allows_are_a_warning_at_the_first_gosub() -> None:
    assert found(_chain(100)) == []
    assert found(_chain(101)) == [("W116", WARNING, 1)]
    # NextMove PC allows 50 levels (and 100 labels)
    assert [code for code, _, _ in found(_chain(51), controller="nextmove-pc")] == ["W116"]
    assert found(_chain(50), controller="nextmove-pc") == []


def test_an_event_handler_starts_its_own_chain_and_goto_loops_nest_nothing() -> None:
    handler = "END\n#IN1\nGOSUB s0\nRETURN\n" + _chain(101).removeprefix("GOSUB s0\nEND\n")
    assert ("W116", WARNING, 3) in found(handler)
    assert found("#top\nPRINT 1\nGOTO top\n") == []


# ------------------------------------------------------------------ unused


def test_a_variable_declared_and_never_used_is_a_warning() -> None:
    assert found("DIM spare\nDIM used\nPRINT used\n") == [("W103", WARNING, 1)]


def test_a_subroutine_never_called_is_a_warning() -> None:
    assert found("GOSUB called\nEND\n#called\nRETURN\n#orphan\nRETURN\n") == [("W104", WARNING, 5)]


def test_a_macro_never_used_is_a_warning() -> None:
    assert found("DEFINE slowSpeed = 1000\nDEFINE fastSpeed = 5\nSPEED = fastSpeed\n") == [("W105", WARNING, 1)]


def test_a_routine_of_only_dims_never_called_keeps_variables_non_volatile() -> None:
    # line 958: "non-volatile variables can be set-up by assigning them in a subroutine, but never calling the routine"
    source = (
        "GOSUB init\nEND\n#non_volatile\nDIM my_var1\nREM kept\nDIM my_var2\n\nRETURN\n"
        "#init\nmy_var1 = my_var1 + my_var2\nRETURN\n"
    )
    assert found(source) == []
    assert found(source.replace("REM kept", "PRINT 1")) == [("W104", WARNING, 3)]


@pytest.mark.parametrize("broken", ["FOR a = b 10\nNEXT\n", "IF (a<b) PRINT a\n"])
def test_variables_named_in_a_statement_that_does_not_parse_are_not_called_unused(broken: str) -> None:
    codes = [code for code, _, _ in found("DIM a\nDIM b\n" + broken)]
    assert "W103" not in codes and len(codes) == 1


def test_event_handlers_are_never_unused() -> None:
    assert found("END\n#ONERROR\nRETURN\n#TIMER\nRETURN\n#IN1\nRETURN\n") == []


# -------------------------------------------------------------------- flow


def test_code_after_end_is_unreachable() -> None:
    assert found("PRINT 1\nEND\nPRINT 2\nPRINT 3\n") == [("W106", WARNING, 3)]


def test_a_label_after_end_is_reachable() -> None:
    assert found("GOSUB sub\nEND\n#sub\nPRINT 2\nRETURN\n") == []


def test_main_program_falling_into_a_subroutine_is_2010_as_a_warning_at_the_return() -> None:
    # line 18965: the manual's own example of #2010 RETURN w/o GOSUB
    source = (
        "DIM running\nREM ** Main Program **\nWHILE running\nREM ** Execution code **\nENDW\n"
        'PRINT "Program terminating"\n#ONERROR\nREM ** Error handler code\nRETURN\n'
    )
    assert found(source) == [("E2010", WARNING, 9)]
    assert found(source.replace('terminating"\n', 'terminating"\nEND\n')) == []


def test_a_subroutine_without_return_running_into_the_next_is_a_warning() -> None:
    assert found("GOSUB a\nGOSUB b\nEND\n#a\nPRINT 1\n#b\nPRINT 2\nRETURN\n") == [("W107", WARNING, 6)]


def test_goto_out_of_a_loop_is_a_warning_of_a_stack_overflow_at_run_time() -> None:
    # line 11205: GOTO out of loops or block IFs "will eventually result in a Stack overflow":
    # the controller compiles it, and only repeated jumps overflow, so it is no compile error
    source = "DIM i\nFOR i = 1 TO 10\nGOTO out\nNEXT\n#out\nEND\n"
    assert found(source) == [("W113", WARNING, 3)]


def test_the_goto_warning_names_the_block_it_leaves_once() -> None:
    diagnostic = only("DIM a\nIF a DO\n  GOTO out\nENDIF\n#out\nEND\n", "W113")
    assert diagnostic.message.startswith("GOTO out leaves the IF block of line 2 open")


def test_goto_inside_its_own_loop_is_fine() -> None:
    assert found("DIM i\nFOR i = 1 TO 10\nIF i = 5 THEN GOTO skip\n#skip\nNEXT\n") == []


def test_exit_outside_a_loop_is_error_2003_when_it_runs() -> None:
    # 000:10224-10245: EXIT terminates a FOR, LOOP, REPEAT or WHILE loop; outside one the simulator raises
    # 2003 (NM-8), so the checker reports the same error, as one raised when the line runs
    assert found("PRINT 1\nEXIT\n") == [("E2003", ERROR, 2)]
    assert only("PRINT 1\nEXIT\n", "E2003").at_run_time
    assert found("LOOP\nIF IN7 = 1 THEN EXIT\nENDL\n") == []


def test_exit_inside_if_then_outside_a_loop_is_error_2003() -> None:
    assert found("IF IN1 THEN EXIT\n") == [("E2003", ERROR, 1)]


def test_exit_never_leaves_a_callers_loop() -> None:
    # NM-8: a subroutine's EXIT with no loop of its own is an error even when its caller is in a loop
    source = "LOOP\n  GOSUB check\nENDL\n#check\nIF IN1 THEN EXIT\nRETURN\n"
    assert found(source) == [("E2003", ERROR, 5)]


@pytest.mark.parametrize("loop", [("LOOP", "ENDL"), ("WHILE 1", "ENDW"), ("REPEAT", "UNTIL 0")])
def test_a_main_program_ending_in_an_endless_loop_does_not_fall_into_subroutines(loop) -> None:
    opener, closer = loop
    assert found(f"{opener}\nGOSUB s\n{closer}\n#s\nRETURN\n") == []


def test_code_after_an_endless_loop_is_unreachable_unless_an_exit_leaves_it() -> None:
    assert found("LOOP\nGO\nENDL\nPRINT 1\n") == [("W106", WARNING, 4)]
    assert found("LOOP\nIF IN1 THEN EXIT\nENDL\nPRINT 1\n") == []


@pytest.mark.parametrize("last", ["END", "RETURN"])
def test_a_lone_end_or_return_after_the_endless_main_loop_is_not_dead_code(last: str) -> None:
    # line 293: the manual's program structure ends #main with LOOP .. ENDL then RETURN
    assert found(f"GOSUB main\nEND\n#main\nLOOP\nGO\nENDL\n{last}\n") == []
    assert found(f"LOOP\nGO\nENDL\n{last}\nPRINT 1\n") == [("W106", WARNING, 5)]


def test_an_if_whose_branches_both_return_does_not_run_on() -> None:
    subroutine = "DIM a\nGOSUB one\nGOSUB two\nEND\n#one\nIF a DO\nRETURN\nELSE\na = 2\nRETURN\nENDIF\n"
    assert found(subroutine + "#two\nRETURN\n") == []
    assert found(subroutine + "PRINT 1\n#two\nRETURN\n") == [("W106", WARNING, 12)]
    one_branch = subroutine.replace("ELSE\na = 2\nRETURN\n", "")
    assert found(one_branch + "#two\nRETURN\n") == [("W107", WARNING, 9)]


def test_a_label_only_goto_reaches_is_part_of_the_code_around_it_not_a_subroutine() -> None:
    source = "DIM a\n#start\na = a + 1\nIF a < 3 THEN GOTO start\nGOTO done\nPRINT a\n#done\nEND\n"
    assert found(source) == [("W106", WARNING, 6)]


# ------------------------------------------------------------------ limits


def declarations(count: int) -> str:
    return "".join(f"DIM v{i}\n" for i in range(count)) + "".join(f"PRINT v{i}\n" for i in range(count))


def test_the_256th_variable_is_error_3002_on_nextmove_pci() -> None:
    # line 1909 (3.9): 255 variables; line 19085: #3002 Too many variables
    assert found(declarations(255)) == []
    assert found(declarations(256)) == [("E3002", ERROR, 256)]


def test_the_101st_variable_is_error_3002_on_nextmove_pc() -> None:
    # line 1909 (3.9): NextMove PC 100 variables
    assert found(declarations(100), controller="nextmove-pc") == []
    assert found(declarations(101), controller="nextmove-pc") == [("E3002", ERROR, 101)]


def test_the_256th_macro_is_a_stack_overflow() -> None:
    # line 1453: up to 255 macros; line 19033: #2015 "more macros than can be supported"
    source = "".join(f"DEFINE m{i} = {i}\n" for i in range(256)) + "".join(f"PRINT m{i}\n" for i in range(256))
    assert found(source) == [("E2015", ERROR, 256)]


def test_the_256th_label_is_error_3000() -> None:
    # line 1881: "A maximum of 255 subroutines"; line 19071: #3000 Too many labels
    source = "".join(f"GOSUB l{i}\n" for i in range(256)) + "END\n" + "".join(f"#l{i}\nRETURN\n" for i in range(256))
    first_label_line = 256 + 2  # after the GOSUBs and the END; each label takes two lines
    assert found(source) == [("E3000", ERROR, first_label_line + 2 * 255)]


def test_arrays_beyond_the_user_memory_are_error_3003() -> None:
    # 9.1 (line 5094): MintDrive has 40 KB of Mint user memory, NextMove PCI 1 MB; 4 bytes an element
    source = "DIM big(20000)\nbig(1) = 1\n"
    assert found(source, controller="mintdrive") == [("E3003", ERROR, 1)]
    assert found(source, controller="nextmove-pci") == []


def test_a_configuration_beyond_its_buffer_is_error_3003() -> None:
    # 9.1: the configuration buffer of MintDrive is 4 KB
    configuration = "REM " + "x" * 5000 + "\n"
    analysis = mintlang.check_application("", controller="mintdrive", config=configuration)
    assert [d.code for d in analysis.configuration] == ["E3003", "W111"]


def test_a_line_longer_than_255_characters_is_a_warning() -> None:
    # line 255 and line 18455: "The maximum line length is 255 characters, including comments"
    long_line = "PRINT " + '"' + "x" * 292 + '"'
    assert len(long_line) == 300
    source = "PRINT 1\n" + long_line + "\n"
    assert found(source) == [("W111", WARNING, 2)]
    assert found("REM " + "y" * 251 + "\n") == []


def test_a_form_feed_does_not_end_a_line_for_its_length() -> None:
    # a page break of an old listing is a character of the line, as for the controller and editors
    assert found("REM " + "y" * 150 + "\x0c" + "z" * 150 + "\n") == [("W111", WARNING, 1)]


# ------------------------------------------------------------------- hints


def hints(source: str) -> list[Diagnostic]:
    """The hints of a program, which are reported only when asked for."""
    return list(mintlang.check_application(source, select=("I",)).program)


def test_hints_are_reported_only_when_selected() -> None:
    assert found("DIM b\nb = POS[1]\n") == []
    assert [d.code for d in hints("DIM b\nb = POS[1]\n")] == ["I201"]


def test_one_axis_in_brackets_gets_a_hint_to_use_the_dot() -> None:
    # lines 682-688: b = POS.1 is smaller and faster than b = POS[1]
    source = "DIM b\nb = POS[1]\n"
    (hint,) = hints(source)
    assert (hint.code, hint.severity.value, source[hint.span.start : hint.span.end]) == ("I201", INFO, "[1]")
    (fix,) = hint.fixes
    fixed = apply(source, fix.edits)
    assert fixed == "DIM b\nb = POS.1\n"
    assert hints(fixed) == []


def test_the_dot_hint_keeps_a_macro_with_the_delimiter_it_needs() -> None:
    # lines 1508-1516: MOVER..xAxis, since a dot before a macro is ignored
    source = "DEFINE xAxis = 0\nMOVER[xAxis] = 10\n"
    (hint,) = hints(source)
    (fix,) = hint.fixes
    assert apply(source, fix.edits) == "DEFINE xAxis = 0\nMOVER..xAxis = 10\n"
    assert hints(apply(source, fix.edits)) == []


def test_several_axes_in_brackets_get_no_hint() -> None:
    assert found("PAUSE IDLE[0,1]\n") == []


# -------------------------------------------------------------- collisions


def test_two_spellings_of_one_name_are_a_warning_at_the_second() -> None:
    # line 887: only the first ten characters of a name count
    source = "DIM thisIsAVariable1\nthisIsAVaraible2 = 1\nPRINT thisIsAVariable1\n"
    assert found(source) == [("W108", WARNING, 2)]


def test_two_spellings_of_one_label_are_a_warning() -> None:
    assert found("GOSUB thisIsALabel2\nEND\n#thisIsALabel1\nRETURN\n") == [("W108", WARNING, 1)]
