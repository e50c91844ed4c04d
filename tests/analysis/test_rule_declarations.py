"""The declarations rule (``mintlang/analysis/rules/declarations.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import ERROR, apply, found, only


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


@pytest.mark.parametrize("newline", ["\r\n", "\r", "\n"], ids=["crlf", "cr", "lf"])
def test_the_3001_fix_keeps_the_files_line_breaks(newline: str) -> None:
    source = f"a = 1{newline}PRINT a{newline}"
    (edit,) = next(d for d in mintlang.check(source) if d.code == "E3001").fixes[0].edits
    assert edit.text == f"DIM a{newline}"


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


@pytest.mark.parametrize(
    ("source", "meant", "fixed"),
    [
        # 000:5563-5567: a keyword is written in any mix of cases; the checker matches names alike, so a
        # misspelling in other letters resembles the declared name all the same
        pytest.param("DIM layer\nPRINT LAYR\n", "layer", "DIM layer\nPRINT layer\n", id="in-capitals"),
        # 000:843-844: every predefined constant begins with "_", whatever its case; HOME's own constants
        # include _hmNEGATIVE_SWITCH (000:11412)
        pytest.param(
            "HOME = _hmNEGATIVE_SWTCH\n", "_hmNEGATIVE_SWITCH", "HOME = _hmNEGATIVE_SWITCH\n", id="a-constant"
        ),
        pytest.param("OUT1 = _of\n", "_OFF", "OUT1 = _OFF\n", id="a-general-constant-in-small-letters"),
        # other BASICs' TRUE is Mint's _true (000:1003, 1017), not the keyword TORQUE it resembles
        pytest.param(
            "DIM a\na = TRUE\n", "_TRUE", "DIM a\na = _TRUE\n", id="a-constant-written-without-its-underscore"
        ),
    ],
)
def test_an_undeclared_name_gets_the_name_or_constant_it_resembles(source: str, meant: str, fixed: str) -> None:
    diagnostic = only(source, "E3001")
    assert diagnostic.message.endswith(f"'{meant}'?")
    replace, _declare = diagnostic.fixes
    assert (replace.title, apply(source, replace.edits)) == (f"Replace with {meant}", fixed)


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # 000:16353: STOP[axes] takes only its axes; the words after it, a comment whose REM is missing
        # (000:15510-15515), are its one syntax error 2003, not undeclared variables as well
        pytest.param("STOP following\n", [("E2003", ERROR, 1)], id="stop"),
        pytest.param("GO.0 : STOP following\n", [("E2003", ERROR, 1)], id="after-a-colon"),
        # 000:16157: SPEED takes its value after "="; the name written without it is meant as that value, and
        # is undeclared all the same
        pytest.param("SPEED later\n", [("E2003", ERROR, 1), ("E3001", ERROR, 1)], id="a-value-without-its-equals"),
    ],
)
def test_words_after_a_command_that_takes_none_are_one_error_2003(source: str, expected: list) -> None:
    assert found(source) == expected


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
