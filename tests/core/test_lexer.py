"""The lexer: how Mint source text is cut into tokens.

Line numbers in comments refer to the Mint v4 programming guide
(/work/shared/seeds/000_f3c82d19754128dd.txt).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Severity
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import TRIVIA, TokenKind
from mintlang.syntax.vocabulary import vocabulary
from tests.analysis.placed import placed

K = TokenKind


def significant(source: str) -> list[tuple[TokenKind, str]]:
    """The (kind, text) of every token that is not white space, a line break or a comment."""
    return [(token.kind, token.text) for token in mintlang.parse(source).tokens if token.kind not in TRIVIA]


def assigned_value(source: str) -> n.Expression:
    """The expression on the right of the single assignment or keyword write in ``source``."""
    statement = mintlang.parse(source).lines[0].statements[0]
    if isinstance(statement, n.Assignment):
        return statement.value
    assert isinstance(statement, n.KeywordStatement)
    assert statement.values is not None
    value = statement.values[0]
    assert value is not None
    return value


def apply(source: str, edits) -> str:
    for edit in sorted(edits, key=lambda e: e.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source


# ------------------------------------------------------------------ numbers


@pytest.mark.parametrize(
    ("source", "value"),
    [
        ("a = 10", 10),
        ("a = 20.5", 20.5),  # line 790: SPEED = 20.5
        ("a = 0.5", 0.5),  # line 761: a leading zero before the point is still decimal
        ("a = .5", 0.5),  # line 654: KINT = .1;
        ("a = 11", 11),  # line 753: "not a valid binary number and will assign the value of 11"
    ],
)
def test_decimal_numbers_have_their_decimal_value(source: str, value: float) -> None:
    number = assigned_value(source)
    assert isinstance(number, n.Number)
    assert number.value == value


@pytest.mark.parametrize(
    ("source", "value"),
    [
        ("a = 011011", 27),  # line 746: PRINT 011011 prints 27
        ("OUT = 011111000", 0b11111000),  # line 750: output bits 3 to 7 on
        ("a = 0xF2FA", 62202),  # line 770
        ("a = 0XFF", 255),
        ("OUT = 01111_0000_1111", 0b0111100001111),  # line 781: underscores separate digits
        ("OUT = 0xFF_00", 0xFF00),  # line 782
    ],
)
def test_leading_zero_is_binary_and_0x_is_hexadecimal(source: str, value: int) -> None:
    number = assigned_value(source)
    assert isinstance(number, n.Number)
    assert number.value == value


def test_a_leading_zero_number_with_other_digits_than_0_and_1_is_a_syntax_error() -> None:
    # line 756: "a = 05 ... is an invalid binary number and will generate a syntax error"
    source = "a = 05\n"
    assert (K.INVALID, "05") in significant(source)
    assert placed(source, "code", "severity", "text", found=mintlang.parse(source).diagnostics) == [
        ("E2003", Severity.ERROR, "05")
    ]


def test_print_of_an_invalid_binary_number_is_a_syntax_error() -> None:
    # line 758: PRINT 05
    source = "PRINT 05\n"
    assert placed(source, "code", "severity", "text", found=mintlang.parse(source).diagnostics) == [
        ("E2003", Severity.ERROR, "05")
    ]


@pytest.mark.parametrize("source", ["a = 0x\n", "a = 0xFG\n", "a = 1_000\n"])
def test_malformed_numbers_are_syntax_errors(source: str) -> None:
    # "_" separates digits only in binary and hexadecimal numbers (line 778)
    assert [d.code for d in mintlang.parse(source).diagnostics] == ["E2003"]


# ------------------------------------------------------- character constants


@pytest.mark.parametrize("source", ["a = 'A'", "a = 'a'"])
def test_character_constants_have_the_upper_case_ascii_code(source: str) -> None:
    # lines 804-811: 'A' and 'a' both have the value of 65
    constant = assigned_value(source)
    assert isinstance(constant, n.CharConstant)
    assert constant.value == 65
    assert significant(source)[-1] == (K.CHAR, source[-3:])


def test_a_character_constant_of_two_characters_is_a_syntax_error() -> None:
    assert {d.code for d in mintlang.parse("a = 'AB'\n").diagnostics} == {"E2003"}


# ---------------------------------------------------------------- labels and #


@pytest.mark.parametrize("source", ["#main\n", "   #main\n", "\t#main\n"])
def test_hash_name_as_first_non_blank_of_a_line_is_a_label(source: str) -> None:
    # line 1872: "The # must be placed as the first non white space character on the line"
    assert significant(source) == [(K.LABEL, "#main")]


def test_hash_after_a_keyword_is_the_terminal_selector() -> None:
    assert significant("PRINT #1, 5\n") == [
        (K.PRINT, "PRINT"),
        (K.HASH, "#"),
        (K.NUMBER, "1"),
        (K.COMMA, ","),
        (K.NUMBER, "5"),
    ]


def test_a_label_after_a_statement_is_not_a_label_and_is_a_syntax_error() -> None:
    # line 1876: "a = 10 : #label1" is an invalid use of a label
    source = "a = 10 : #label1\n"
    assert (K.LABEL, "#label1") not in significant(source)
    assert significant(source)[-2:] == [(K.HASH, "#"), (K.NAME, "label1")]
    assert [d.code for d in mintlang.parse(source).diagnostics] == ["E2003"]


# ---------------------------------------------------------- dots and numbers


def test_dot_right_after_a_keyword_is_the_dot_parameter() -> None:
    # line 682: b = POS.1
    assert significant("SPEED.1 = 10\n") == [
        (K.KEYWORD, "SPEED"),
        (K.DOT, "."),
        (K.NUMBER, "1"),
        (K.EQUAL, "="),
        (K.NUMBER, "10"),
    ]


def test_dot_after_an_equals_sign_starts_a_number() -> None:
    assert significant("a = .5\n") == [(K.NAME, "a"), (K.EQUAL, "="), (K.NUMBER, ".5")]


def test_two_dot_parameters_follow_each_other() -> None:
    # CAN keywords take bus and node: REMOTEIN.1.2
    assert significant("a = REMOTEIN.1.2\n")[2:] == [
        (K.KEYWORD, "REMOTEIN"),
        (K.DOT, "."),
        (K.NUMBER, "1"),
        (K.DOT, "."),
        (K.NUMBER, "2"),
    ]


# ------------------------------------------------------------------- comments


def test_rem_comments_out_the_rest_of_the_line() -> None:
    # line 15510: "All characters after the REM until the end of line are ignored"
    source = "PRINT REM This also prints a blank line\nSPEED = 1\n"
    tokens = [(t.kind, t.text) for t in mintlang.parse(source).tokens]
    assert (K.COMMENT, "REM This also prints a blank line") in tokens
    assert significant(source) == [(K.PRINT, "PRINT"), (K.KEYWORD, "SPEED"), (K.EQUAL, "="), (K.NUMBER, "1")]
    assert placed(source, "code", "severity", "text", found=mintlang.parse(source).diagnostics) == []


@pytest.mark.parametrize("word", ["REMOTEIN", "REMOTEOUT"])
def test_a_keyword_that_starts_with_rem_is_a_word_not_a_comment(word: str) -> None:
    source = f"a = {word}.1.2\n"
    assert all(token.kind is not K.COMMENT for token in mintlang.parse(source).tokens)
    assert (K.KEYWORD, word) in significant(source)


def test_rem_in_lower_case_is_a_comment() -> None:
    assert significant("rem SPEED = 10\n") == []


# ------------------------------------------------------------------- keywords


@pytest.mark.parametrize("spelling", ["SPEED", "speed", "Speed", "sp", "Sp", "SP"])
def test_keywords_are_read_in_any_case_and_by_abbreviation(spelling: str) -> None:
    # line 5563: keywords "can be entered in any combination of upper and lower case";
    # line 194: "SPEED is abbreviated to SP"
    statement = mintlang.parse(f"{spelling} = 10\n").lines[0].statements[0]
    assert isinstance(statement, n.KeywordStatement)
    assert statement.keyword.keyword == "SPEED"
    assert statement.keyword.spelling == spelling
    assert significant(f"{spelling} = 10\n")[0] == (K.KEYWORD, spelling)


@pytest.mark.parametrize(("spelling", "kind"), [("print", K.PRINT), ("?", K.PRINT), ("If", K.IF), ("next", K.NEXT)])
def test_grammar_keywords_are_read_in_any_case(spelling: str, kind: TokenKind) -> None:
    assert significant(spelling)[0] == (kind, spelling)


@pytest.mark.parametrize(("spelling", "keyword", "channel"), [("IN3", "IN", 3), ("in12", "IN", 12), ("OUT1", "OUT", 1)])
def test_a_channel_number_glued_to_in_or_out_is_the_channel(spelling: str, keyword: str, channel: int) -> None:
    # line 1584: IF IN3 THEN STOP : PAUSE IDLE : OUT0 = _off
    assert significant(f"x = {spelling}\n")[-1] == (K.KEYWORD, spelling)
    value = assigned_value(f"x = {spelling}\n")
    assert isinstance(value, n.KeywordRef)
    assert (value.keyword, value.channel, value.spelling) == (keyword, channel, spelling)


def test_a_word_that_is_no_keyword_is_a_name() -> None:
    assert significant("motorSpeed = 1\n")[0] == (K.NAME, "motorSpeed")


# ----------------------------------------------------------------- quotes


def test_typographic_double_quotes_are_accepted_with_a_warning_and_a_fix() -> None:
    # the manual itself prints DEFINE mac = ? “OK” (line 1456)
    source = "PRINT \u201cOK\u201d\n"
    document = mintlang.parse(source)
    assert [(d.code, d.severity) for d in document.diagnostics] == [("W101", Severity.WARNING)]
    (warning,) = document.diagnostics
    assert source[warning.span.start : warning.span.end] == "\u201cOK\u201d"
    (fix,) = warning.fixes
    fixed = apply(source, fix.edits)
    assert fixed == 'PRINT "OK"\n'
    assert mintlang.parse(fixed).diagnostics == ()


def test_typographic_single_quotes_are_accepted_with_a_warning_and_a_fix() -> None:
    source = "a = \u2018Y\u2019\n"
    (warning,) = mintlang.parse(source).diagnostics
    assert (warning.code, warning.severity) == ("W101", Severity.WARNING)
    constant = assigned_value(source)
    assert isinstance(constant, n.CharConstant)
    assert constant.value == ord("Y")
    fixed = apply(source, warning.fixes[0].edits)
    assert fixed == "a = 'Y'\n"
    assert mintlang.parse(fixed).diagnostics == ()


def test_an_unterminated_string_is_a_syntax_error_up_to_the_end_of_the_line() -> None:
    source = 'PRINT "abc\nPRINT "ok"\n'
    assert placed(source, "code", "severity", "text", found=mintlang.parse(source).diagnostics) == [
        ("E2003", Severity.ERROR, '"abc')
    ]
    assert significant(source)[-1] == (K.STRING, '"ok"')


@pytest.mark.parametrize(
    ("source", "message"),
    [
        pytest.param("PRINT 7 \\ 2\n", "Syntax error: unexpected character '\\'", id="backslash-as-typed"),
        pytest.param("PRINT 1 $ 2\n", "Syntax error: unexpected character '$'", id="dollar"),
        pytest.param("PRINT 1 \x01 2\n", "Syntax error: unexpected character '\\x01'", id="control-escaped"),
    ],
)
def test_an_unexpected_character_is_named_as_typed_and_an_invisible_one_escaped(source: str, message: str) -> None:
    """The message quotes the character the user typed, not Python's escaped spelling of it; only a
    character that would not show is written as an escape."""
    assert [d.message for d in mintlang.parse(source).diagnostics] == [message]


# ------------------------------------------------------------- losslessness


@pytest.mark.parametrize(
    "source",
    [
        "DIM a\r\nPRINT a\r\n",
        "DIM a\rPRINT a\r",
        "DIM a\n\r\n\rPRINT a",
        "\tIF a > 1 THEN\tb = 2\t\n",
        "SPEED = 10   \n   \n",
        "REM caf\u00e9 \u00fcber \u20ac \u65e5\u672c\n",
        'PRINT "\u00e9t\u00e9"\n',
        "\ufeffSPEED = 1\n",
        "a = 05 : b = 'xy' : \u00a7\n",
        "",
        "\n",
        "PRINT \u201cunterminated\n",
    ],
)
def test_tokens_join_back_to_the_source_exactly(source: str) -> None:
    tokens = mintlang.parse(source).tokens
    assert "".join(token.text for token in tokens) == source
    offset = 0
    for token in tokens:
        assert token.start == offset
        offset = token.end
    assert offset == len(source)


@pytest.mark.parametrize("newline", ["\r\n", "\r", "\n"], ids=["CRLF", "CR", "LF"])
def test_every_line_break_convention_ends_a_line(newline: str) -> None:
    source = newline.join(["PRINT 1", "PRINT 2", "GO", ""])
    document = mintlang.parse(source)
    assert [line.number for line in document.lines] == [1, 2, 3]
    assert document.diagnostics == ()
    assert [token.text for token in document.tokens if token.kind is K.NEWLINE] == [newline] * 3


def test_no_controller_changes_the_kind_of_a_word() -> None:
    # the lexer caches lines per dialect alone: only the keyword a shared abbreviation names may differ
    for dialect in Dialect:
        assert all(vocabulary(dialect, controller).words == vocabulary(dialect).words for controller in Controller)
