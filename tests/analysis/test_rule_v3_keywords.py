"""The v3 keywords rule (``mintlang/analysis/rules/v3_keywords.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import mintlang
from mintlang.fixes import fix_text
from tests.analysis.checking import ERROR, apply, covered, found, only


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


def test_an_abbreviated_bit_keyword_is_said_to_be_the_bit_v4_still_writes() -> None:
    # O4 and I2 are v3's OUT4 and IN2 (001:10602, 8975); v4 writes OUTx and INx as v3 did (000:14889-14897,
    # 000:11951), so those are the words to write: OUT or IN alone reads or sets every bit at once
    source = "DIM a\nIF I2 THEN O4 = 1\n"
    in2, out4 = [d for d in mintlang.check(source) if d.code == "E3001"]
    assert "abbreviation of IN2; v4: IN2," in in2.message
    assert "abbreviation of OUT4; v4: OUT4," in out4.message


def test_renaming_a_v3_fast_latch_label_renames_the_jumps_that_name_it() -> None:
    # v4's handler is #FASTIN (000:1884-1893); a GOSUB still naming FASTPOS would name no label (3004), and --fix
    # --unsafe-fixes created #FASTPOS again, renamed it again, round after round, writing one #FASTIN a round
    source = "GOSUB FASTPOS\nIF IN1 THEN GOTO fastpos\nEND\n#FASTPOS\nRETURN\n"
    (rename,) = only(source, "W102").fixes
    assert apply(source, rename.edits) == "GOSUB FASTIN\nIF IN1 THEN GOTO FASTIN\nEND\n#FASTIN\nRETURN\n"
    fixed = fix_text("GOSUB FASTPOS\n", mintlang.check, unsafe=True)
    assert (fixed.text, fixed.converged) == ("GOSUB FASTIN\nEND\n\n#FASTIN\nRETURN\n", True)
