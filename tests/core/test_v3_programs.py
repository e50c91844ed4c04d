"""Mint v3 programs parse in the v3 dialect, so that the migrator can read them.

Every complete program and configuration file of the v3 guide parses without
a syntax error, apart from the guide's own misprints that the file headers
name (the analyser's v4 rules do not apply to v3 code).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.corpus_files import CorpusCase, cases

SYNTAX_ERRORS = frozenset({"E2003", "E2004", "E2006", "E2007", "E2008", "E3007"})  # 3007: a misspelt command


@pytest.mark.parametrize("case", cases("v3/programs", "*.*"), ids=lambda case: case.name)
def test_v3_program_parses(case: CorpusCase) -> None:
    document = mintlang.parse(case.source, "v3")
    lines = {(d.code, document.line_index.position(d.span.start).line) for d in document.diagnostics}
    assert {item for item in lines if item[0] in SYNTAX_ERRORS} == set(case.expected)


def test_v3_reads_variables_without_dim() -> None:
    # v3 guide line 1352: any assignment declares a variable
    assert [d.code for d in mintlang.check("a = 10\nPRINT a\n", dialect="v3") if d.code == "E3001"] == []
    assert [d.code for d in mintlang.check("a = 10\nPRINT a\n") if d.code == "E3001"] == ["E3001", "E3001"]


def test_v3_keeps_its_own_keywords_and_offline_arrays() -> None:
    document = mintlang.parse("HMSPEED = 10\nDIM OFFLINE table(100)\n", "v3")
    assert document.diagnostics == ()
    first, second = (line.statements[0] for line in document.lines)
    assert first.keyword.keyword == "HMSPEED"
    assert (second.name.text, second.modifier) == ("table", "OFFLINE")


@pytest.mark.parametrize("bit", range(8))
def test_v3_reads_x0_to_x7_as_the_expanded_io_bits(bit: int) -> None:
    # v3 guide 12753: "X2 is the abbreviated keyword for XIO2"; X2.0 is bit 2 of bank 0 (v3:12750)
    document = mintlang.parse(f"X{bit}.0 = 0\n", "v3")
    (statement,) = document.lines[0].statements
    assert (document.diagnostics, statement.keyword.keyword) == ((), f"XIO{bit}")


@pytest.mark.parametrize("source", ["a = PEEK(10)\n", "a = pk(3 + 1)\n"])
def test_v3_reads_peek_as_a_function(source: str) -> None:
    # v3 guide 10723-10750: PEEK/PK, "v = PEEK(<expression>)"
    document = mintlang.parse(source, "v3")
    (statement,) = document.lines[0].statements
    call = statement.value
    assert (document.diagnostics, call.function, len(call.arguments)) == ((), "PEEK", 1)


def test_v3_prints_peek_of_an_address() -> None:
    # v3 guide 10750: the entry's example
    assert mintlang.parse("PRINT PEEK(10)\n", "v3").diagnostics == ()


@pytest.mark.parametrize(
    ("source", "operator"),
    [
        ("PAUSE DEMAND > = 50\n", ">="),  # v3 guide 3096, run as "until the demand exceeds 50%"
        ("PAUSE a >  = 50\n", ">="),
        ("PAUSE a < = 50\n", "<="),
        ("PAUSE a < > 50\n", "<>"),
        ("PAUSE a >= 50\n", ">="),
    ],
)
def test_v3_reads_a_two_character_relation_with_blanks_inside(source: str, operator: str) -> None:
    document = mintlang.parse(source, "v3")
    (statement,) = document.lines[0].statements
    assert (document.diagnostics, statement.condition.operator) == ((), operator)
    assert "".join(token.text for token in document.tokens) == source


def test_v4_keeps_a_relation_in_one_piece() -> None:
    assert [d.code for d in mintlang.parse("PAUSE a > = 50\n", "v4").diagnostics] == ["E2003"]


def test_v3_binds_and_tighter_than_or_unlike_v4() -> None:
    # v3 guide 4.2 (lines 1986-1995): AND above OR; v4 guide 3.4.7 (line 1412): | above &
    def top(dialect: str) -> tuple[str, str]:
        (statement,) = mintlang.parse("PAUSE a AND b OR c\n", dialect).lines[0].statements
        condition = statement.condition
        return condition.operator, type(condition.left).__name__

    assert top("v3") == ("OR", "Binary")  # (a AND b) OR c
    assert top("v4") == ("AND", "VariableRef")  # a AND (b OR c)


def test_v3_keywords_are_used_as_the_v3_guide_ticks_them() -> None:
    # v3 guide 001:7956: FASTPOS has only Read ticked, so a write was an error on the v3 controller too
    diagnostics = mintlang.check("FASTPOS.0 = 5\nSPEED.0 = 10\n", dialect="v3")
    assert [(d.code, d.span.start) for d in diagnostics] == [("E2000", 0)]
    assert "FASTPOS is read only in Mint v3" in diagnostics[0].message


@pytest.mark.parametrize("source", ["a = STOP\n", "a = CLS\n", "PRINT LASTERR\n"])
def test_v3_reading_a_command_is_read_only_or_command(source: str) -> None:
    # 001:13083-13094: "Read only or Command" is the error of a read of a command; its example is a = STOP
    (diagnostic,) = mintlang.check(source, dialect="v3")
    assert diagnostic.code == "E2000" and "is a command in Mint v3 and gives no value" in diagnostic.message


def test_v3_reading_a_write_only_keyword_is_write_only() -> None:
    # 001:13073-13080: "Write only" is the error of a read of a write only keyword; its example is a = FLY
    (diagnostic,) = mintlang.check("a = FLY\n", dialect="v3")
    assert diagnostic.code == "E2002" and "FLY can only be written in Mint v3, not read" in diagnostic.message


def test_v3_an_assignment_with_no_expression_is_no_expression() -> None:
    # 001:12957-12964: "No expression" is an assignment with nothing after '='; its example is avar =
    (diagnostic,) = mintlang.check("avar =\n", dialect="v3")
    assert diagnostic.code == "E2005" and not diagnostic.at_run_time


@pytest.mark.parametrize(
    ("source", "column"),
    [
        pytest.param("a = 0\nSF[a+1] = 1000\n", 9, id="001:13184 an expression as an axis number"),
        pytest.param("DIM t(2)\nSF[t(1)] = 1000\n", 12, id="001:13175 an array element"),
        pytest.param("VR[0] = 100\n", 2, id="001:13183 a vector move on one axis"),
        pytest.param("VR[0,1] = 100\n", 10, id="001:13175 one position: the other axis is left out"),
        pytest.param("VA = 100\n", 5, id="001:13175 the default axes given one position"),
    ],
)
def test_v3_invalid_axis_examples_are_found_as_the_run_raises_them(source: str, column: int) -> None:
    # 001:13173-13184: "Invalid axis", ERR 4 (001:4925), the run's error 2 (E0002)
    (diagnostic,) = mintlang.check(source, dialect="v3")
    assert diagnostic.code == "E0002" and "Invalid axis in Mint v3" in diagnostic.message
    assert diagnostic.span.start == column


def test_v3_numbers_and_variables_are_axes() -> None:
    # 001:1005-1007: MOVER[a] = 100 is valid; a vector move on two axes too
    assert mintlang.check("a = 1\nMOVER[a] = 100\nVR[0,1] = 10,10\n", dialect="v3") == []


@pytest.mark.parametrize(
    ("line", "password"),
    [
        pytest.param("PROTECT abc", "abc", id="one word"),
        pytest.param("PROTECT my pass, 1!", "my pass, 1!", id="spaces and punctuation"),
        pytest.param("PROTECT pw : REM x  ", "pw : REM x", id="a REM is part of it, trailing blanks are not"),
    ],
)
def test_v3_reads_the_rest_of_a_protect_line_as_its_password(line: str, password: str) -> None:
    # letters, numbers, spaces and punctuation; a REM on the line becomes part of the password (v3:11089-11092)
    source = f"{line}\nPRINT 1\n"
    document = mintlang.parse(source, "v3")
    assert document.diagnostics == ()
    (statement,) = document.placed[0].syntax.statements
    assert statement.arguments[0].name.text == password
    assert mintlang.check(source, dialect="v3") == []


@pytest.mark.parametrize("source", ["JOG 5\n", "JOG\n", "SPEED\n", "MA 5\n"])
def test_v3_a_parameter_written_as_a_command_is_found_as_the_run_stops_on_it(source: str) -> None:
    # v3's formats give a parameter its value with '=' (JOG[.axis] = <expr>, 001:9326); a line that names it
    # as a command stops mint-run --dialect v3 with "No expression", and the checker says so where it is written
    (diagnostic,) = mintlang.check(source, dialect="v3")
    assert (diagnostic.code, diagnostic.span.start) == ("E2005", 0)
    assert "is no command in Mint v3" in diagnostic.message


@pytest.mark.parametrize(
    "source",
    [
        "GO\n",
        "STOP\n",
        "CANCEL.0\n",
        "HOME.0 = 0\n",
        "? POS; : BOL\n",  # 001:3553
        "LOOP : ? POS[0]; : BOL : ENDL\n",  # BOL's own entry, 001:6256
    ],
)
def test_v3_commands_and_assignments_stand_as_statements(source: str) -> None:
    assert mintlang.check(source, dialect="v3") == []


def test_v3_bol_moves_the_cursor_and_gives_no_value() -> None:
    # "Return the cursor to the Beginning Of Line" (001:6249-6251) is a command, not a value to read
    (diagnostic,) = mintlang.check("DIM a\na = BOL\n", dialect="v3")
    assert (diagnostic.code, "is a command in Mint v3" in diagnostic.message) == ("E2000", True)
