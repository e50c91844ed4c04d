"""The limits rule (``mintlang/analysis/rules/limits.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import mintlang
from tests.analysis.checking import ERROR, WARNING, found


def declarations(count: int) -> str:
    return "".join(f"DIM v{i}\n" for i in range(count)) + "".join(f"PRINT v{i}\n" for i in range(count))


def test_the_254th_variable_is_error_3002_on_nextmove_pci() -> None:
    # lines 866-868 and 1907-1913: the variable stack holds 255 variables; lines 18465-18466: COMMS and
    # GROUPCOMMS are always on it, one place each (line 1058-1059: an array takes one); 255 - 2 = 253
    # for the program; line 19085: #3002 Too many variables
    assert found(declarations(253)) == []
    assert found(declarations(254)) == [("E3002", ERROR, 254)]


def test_the_99th_variable_is_error_3002_on_nextmove_pc() -> None:
    # line 1913 (3.9): NextMove PC 100 variables, two of them COMMS and GROUPCOMMS (18465-18466)
    assert found(declarations(98), controller="nextmove-pc") == []
    assert found(declarations(99), controller="nextmove-pc") == [("E3002", ERROR, 99)]


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


def test_a_mint_v3_line_longer_than_127_characters_is_a_warning() -> None:
    """v3:5144: an off-line editor's lines are held to 127 characters; a longer one stops the v3 compiler
    with "Line too long" (v3:12999-13001). A 128-character comment is one too many, 127 are not."""
    codes = [(d.code, d.span.start) for d in mintlang.check("PRINT 1\nREM " + "y" * 124 + "\n", dialect="v3")]
    assert codes == [("W111", 8 + 127)]
    assert list(mintlang.check("REM " + "y" * 123 + "\n", dialect="v3")) == []


def test_a_form_feed_does_not_end_a_line_for_its_length() -> None:
    # a page break of an old listing is a character of the line, as for the controller and editors
    assert found("REM " + "y" * 150 + "\x0c" + "z" * 150 + "\n") == [("W111", WARNING, 1)]
