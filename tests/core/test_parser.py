"""The parser: statements, expressions, logical lines, macros and syntax errors.

Line numbers in comments refer to the Mint v4 programming guide
(/work/shared/seeds/000_f3c82d19754128dd.txt).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Severity
from mintlang.syntax import nodes as n
from tests.analysis.placed import placed


def statements(source: str) -> list[n.Statement]:
    """The top-level statements of every line of ``source``."""
    return [statement for line in mintlang.parse(source).lines for statement in line.statements]


def only_statement(source: str) -> n.Statement:
    (statement,) = statements(source)
    return statement


def shape(node: n.Expression | None) -> str:
    """An expression written with every operation bracketed: ``a & b | c`` -> ``(a AND (b OR c))``."""
    match node:
        case None:
            return "_"
        case n.Binary(operator=operator, left=left, right=right):
            return f"({shape(left)} {operator} {shape(right)})"
        case n.Unary(operator=operator, operand=operand):
            return f"({operator} {shape(operand)})"
        case n.Parenthesised(expression=inner):
            return f"[{shape(inner)}]"
        case n.Call(function=function, arguments=arguments, bracketed=bracketed):
            inner = ", ".join(shape(argument) for argument in arguments)
            return f"{function}({inner})" if bracketed else f"{function}<{inner}>"
        case n.Number(text=text):
            return text
        case n.VariableRef(name=name):
            return name.text
        case n.KeywordRef(keyword=keyword):
            return keyword
    raise AssertionError(f"unexpected node {node!r}")


def value_shape(expression_text: str) -> str:
    statement = only_statement(f"x = {expression_text}\n")
    assert isinstance(statement, n.Assignment)
    return shape(statement.value)


def text_of(source: str, node) -> str:
    return source[node.span.start : node.span.end]


# --------------------------------------------------------------- precedence


@pytest.mark.parametrize(
    ("expression", "expected"),
    [
        # line 1412, section 3.4.7: "|" (OR) binds tighter than "&" (AND)
        ("a & b | c", "(a AND (b OR c))"),
        ("a | b & c", "((a OR b) AND c)"),
        ("a AND b OR c", "(a AND (b OR c))"),
        ("a OR b AND c OR d", "((a OR b) AND (c OR d))"),
        # "*,/,MOD" over "+,-"
        ("2 + 3 * 4", "(2 + (3 * 4))"),
        ("a - b / c", "(a - (b / c))"),
        ("a + b MOD c", "(a + (b MOD c))"),
        ("a % b + c", "((a MOD b) + c)"),
        # relational over equality
        ("a < b = c > d", "((a < b) = (c > d))"),
        ("a <> b >= c", "(a <> (b >= c))"),
        # arithmetic over relational, relational over OR
        ("a + 1 > b", "((a + 1) > b)"),
        ("a > 1 | b", "((a > 1) OR b)"),
        # left associativity
        ("a - b - c", "((a - b) - c)"),
        ("a / b * c", "((a / b) * c)"),
        # brackets first
        ("(a + b) * c", "([(a + b)] * c)"),
        # unary operators bind tightest
        ("-a * b", "((- a) * b)"),
        ("!a & b", "((NOT a) AND b)"),
        ("~a | b", "((~ a) OR b)"),
    ],
)
def test_operator_precedence_follows_section_3_4_7(expression: str, expected: str) -> None:
    assert value_shape(expression) == expected


def test_a_function_without_brackets_takes_only_the_next_operand() -> None:
    # line 1395: "SIN 90 + a" is "(SIN(90)) + a"
    assert value_shape("SIN 90 + a") == "(SIN<90> + a)"


@pytest.mark.parametrize(
    ("expression", "expected"),
    [
        # lines 1417-1420: ABS, INT, SIN ... sit at the level of unary minus, whose operand may be a call
        pytest.param("ABS SIN(a)", "ABS<SIN(a)>", id="abs-of-a-call"),
        pytest.param("INT SQRT(a) + 1", "(INT<SQRT(a)> + 1)", id="binds-tighter-than-plus"),
        pytest.param("ABS POW(2, 3) * 2", "(ABS<POW(2, 3)> * 2)", id="two-argument-call"),
        pytest.param("ABS INT SQRT(a)", "ABS<INT<SQRT(a)>>", id="two-bare-functions"),
        pytest.param("-SIN(a)", "(- SIN(a))", id="as-unary-minus-does"),
        pytest.param("ABS (a) + 1", "(ABS(a) + 1)", id="own-bracket-is-still-its-call"),
    ],
)
def test_a_function_without_brackets_takes_a_call_as_its_operand(expression: str, expected: str) -> None:
    assert value_shape(expression) == expected


def test_a_function_with_brackets_takes_the_whole_bracketed_expression() -> None:
    # line 1398: SIN(90 + a)
    assert value_shape("SIN(90 + a)") == "SIN((90 + a))"


def test_a_function_of_two_arguments() -> None:
    assert value_shape("POW(2, 3) + 1") == "(POW(2, 3) + 1)"


# ------------------------------------------------------- multi-axis syntax


def keyword_write(source: str) -> n.KeywordStatement:
    statement = only_statement(source)
    assert isinstance(statement, n.KeywordStatement)
    return statement


def test_bracketed_axes_take_one_value_each() -> None:
    # line 540: SPEED[1,2] = 10,20
    statement = keyword_write("SPEED[0,1] = 10,20\n")
    assert statement.keyword.keyword == "SPEED"
    assert statement.keyword.selector is not None
    assert not statement.keyword.selector.dot
    assert [shape(item) for item in statement.keyword.selector.items] == ["0", "1"]
    assert [shape(value) for value in statement.values or ()] == ["10", "20"]
    assert statement.fill is False


def test_a_leading_comma_skips_the_first_axis() -> None:
    # line 635: SPEED = ,10 sets the speed of axis 1 only
    statement = keyword_write("SPEED = ,10\n")
    assert statement.values is not None
    assert [shape(value) for value in statement.values] == ["_", "10"]
    assert statement.values[0] is None


def test_a_trailing_semicolon_fills_the_remaining_axes() -> None:
    # line 652: KVEL = 10;
    statement = keyword_write("KVEL = 10;\n")
    assert [shape(value) for value in statement.values or ()] == ["10"]
    assert statement.fill is True


def test_dot_selects_one_axis() -> None:
    statement = keyword_write("MOVER.1 = 5\n")
    selector = statement.keyword.selector
    assert selector is not None
    assert selector.dot
    assert [shape(item) for item in selector.items] == ["1"]


def test_dot_with_brackets_selects_an_axis_by_expression() -> None:
    # line 697: b = POS.(a + 1)
    statement = only_statement("b = POS.(a+1)\n")
    assert isinstance(statement, n.Assignment)
    value = statement.value
    assert isinstance(value, n.KeywordRef)
    assert value.selector is not None
    assert value.selector.dot
    assert [shape(item) for item in value.selector.items] == ["[(a + 1)]"]


def test_a_dot_parameter_takes_one_operand_only() -> None:
    # line 691: b = POS.a + 1 is b = POS[a] + 1
    statement = only_statement("b = POS.a + 1\n")
    assert isinstance(statement, n.Assignment)
    assert shape(statement.value) == "(POS + 1)"
    assert isinstance(statement.value, n.Binary)
    position = statement.value.left
    assert isinstance(position, n.KeywordRef)
    assert position.selector is not None
    assert [shape(item) for item in position.selector.items] == ["a"]


@pytest.mark.parametrize("written", ["SPEED servos = 10;", "SPEED^servos = 10;", "SPEED.servos = 10;"])
def test_space_caret_or_dot_may_separate_a_keyword_from_an_axis_list_macro(written: str) -> None:
    # lines 1046-1050 (3.2.6 Delimiters) and line 1489: SF.g1 = 10;
    source = f"DEFINE servos = [0,1,2,3]\n{written}\n"
    write = statements(source)[1]
    assert isinstance(write, n.KeywordStatement)
    assert write.keyword.selector is not None
    assert [shape(item) for item in write.keyword.selector.items] == ["0", "1", "2", "3"]
    assert write.fill is True
    assert mintlang.parse(source).diagnostics == ()


def test_a_double_dot_before_a_macro_is_a_dot_parameter() -> None:
    # lines 1508-1512: DEFINE xAxis = 0 / MOVER..xAxis = 10 ("two dots are required")
    source = "DEFINE xAxis = 0\nMOVER..xAxis = 10\n"
    define, write = statements(source)
    assert isinstance(define, n.Define)
    assert isinstance(write, n.KeywordStatement)
    assert write.keyword.keyword == "MOVER"
    assert write.keyword.selector is not None
    assert write.keyword.selector.dot
    assert [shape(item) for item in write.keyword.selector.items] == ["0"]
    assert [shape(value) for value in write.values or ()] == ["10"]
    assert mintlang.parse(source).diagnostics == ()


def test_a_macro_in_brackets_lists_axes() -> None:
    # lines 1501-1502: DEFINE ALL = 0,1,2,3,4,5,6,7 / SPEED[ALL] = 20;
    source = "DEFINE ALL = 0,1,2,3,4,5,6,7\nSPEED[ALL] = 20;\n"
    write = statements(source)[1]
    assert isinstance(write, n.KeywordStatement)
    assert write.keyword.selector is not None
    assert [shape(item) for item in write.keyword.selector.items] == [str(axis) for axis in range(8)]
    assert write.fill is True


# --------------------------------------------------------------- IF blocks


def test_if_then_takes_every_statement_up_to_the_end_of_the_line() -> None:
    # line 1584: IF IN3 THEN STOP : PAUSE IDLE : OUT0 = _off
    source = "IF a > 1 THEN b = 1 : c = 2\nd = 3\n"
    first, after = statements(source)
    assert isinstance(first, n.IfThen)
    assert shape(first.condition) == "(a > 1)"
    assert [text_of(source, statement) for statement in first.body] == ["b = 1", "c = 2"]
    assert isinstance(after, n.Assignment)


def test_if_do_else_endif_are_separate_statements() -> None:
    # line 1594: the IF block structure
    source = "IF a DO\nb = 1\nELSE\nb = 2\nENDIF\n"
    found = statements(source)
    assert [type(statement).__name__ for statement in found] == [
        "IfDo",
        "Assignment",
        "BlockWord",
        "Assignment",
        "BlockWord",
    ]
    assert [statement.word for statement in found if isinstance(statement, n.BlockWord)] == ["ELSE", "ENDIF"]


def test_for_loop_parts() -> None:
    statement = only_statement("FOR a = 1 TO 20 STEP 2\n")
    assert isinstance(statement, n.For)
    assert (statement.variable.text, shape(statement.start), shape(statement.end), shape(statement.step)) == (
        "a",
        "1",
        "20",
        "2",
    )


# ------------------------------------------------------------ logical lines


def test_a_dim_list_ending_with_a_comma_continues_on_the_next_line() -> None:
    # line 1096: "the last entry on each line should have a comma after it"
    source = "DIM y(10) = 1,2,3,\n4,5\nPRINT y(1)\n"
    document = mintlang.parse(source)
    assert document.diagnostics == ()
    dim_line, print_line = document.lines
    (dim,) = dim_line.statements
    assert isinstance(dim, n.Dim)
    assert [shape(value) for value in dim.values] == ["1", "2", "3", "4", "5"]
    assert text_of(source, dim) == "DIM y(10) = 1,2,3,\n4,5"
    assert (dim_line.number, print_line.number) == (1, 3)


def test_dim_with_a_semicolon_fills_the_array() -> None:
    # line 1100: DIM y_position(10) = 10,0;
    dim = only_statement("DIM y_position(10) = 10,0;\n")
    assert isinstance(dim, n.Dim)
    assert (shape(dim.size), [shape(v) for v in dim.values], dim.fill) == ("10", ["10", "0"], True)


# ------------------------------------------------------------------- macros


def test_print_modifiers_dec_hex_and_bin_each_mark_the_value_after_them() -> None:
    # lines 15352-15359: DEC, HEX and BIN convert the number that follows
    (statement,) = statements("DIM a\nPRINT DEC a, hex a; BIN -a, a\n")[1:]
    assert isinstance(statement, n.Print)
    assert [item.format for item in statement.items] == ["DEC", "HEX", "BIN", None]
    # lines 13651-13653: LINE takes the same modifiers
    assert mintlang.check("DIM a\nLINE 1, DEC a, HEX a, BIN a\n") == []


@pytest.mark.parametrize(
    ("source", "semicolons", "trailing"),
    [
        pytest.param('LINE 1, "a = "; a\n', (1,), False, id="between-items"),
        pytest.param('LINE 1, "a = ", a;\n', (2,), True, id="ending-the-line"),
        pytest.param('LINE 1, "a"; a; "b", a USING 3\n', (1, 2), False, id="before-using"),
        pytest.param('LINE 1, "a", a\n', (), False, id="commas-only"),
    ],
)
def test_line_separates_what_it_prints_as_print_does(source: str, semicolons: tuple[int, ...], trailing: bool) -> None:
    # lines 13658-13660: LINE takes any expression PRINT takes; lines 15300-15302: "," or ";" between them
    statement = statements("DIM a\n" + source)[1]
    assert isinstance(statement, n.KeywordStatement)
    assert (statement.semicolons, statement.trailing) == (semicolons, trailing)
    assert mintlang.parse("DIM a\n" + source).diagnostics == ()


def test_a_macro_use_on_a_later_line_is_replaced_by_its_text() -> None:
    # line 1456: DEFINE mac = ? "OK" - where mac is found, ? "OK" is executed
    source = 'DEFINE mac = ? "OK"\nmac\n'
    define, use = statements(source)
    assert isinstance(define, n.Define)
    assert define.name.text == "mac"
    assert define.body_span is not None
    assert source[define.body_span.start : define.body_span.end] == '? "OK"'
    assert isinstance(use, n.Print)
    (item,) = use.items
    assert isinstance(item.value, n.StringLiteral)
    assert item.value.value == "OK"


def test_an_expanded_statement_has_the_span_of_the_macro_use() -> None:
    source = 'DEFINE mac = ? "OK"\n  mac\n'
    use = statements(source)[1]
    assert text_of(source, use) == "mac"
    assert [(expansion.macro, text_of(source, expansion)) for expansion in mintlang.parse(source).expansions] == [
        ("MAC", "mac")
    ]


def test_a_macro_is_not_expanded_before_its_definition() -> None:
    found = statements("mac\nDEFINE mac = GO\n")
    assert isinstance(found[0], n.BareName)


def test_a_macro_may_hold_several_statements() -> None:
    # line 1560: DEFINE myMove = MOVEA.1 = 100 : GO.1 : PAUSE IDLE.1
    source = "DEFINE myMove = MOVEA.1 = 100 : GO.1 : PAUSE IDLE.1\nmyMove\n"
    expanded = statements(source)[1:]
    assert [type(statement).__name__ for statement in expanded] == ["KeywordStatement", "KeywordStatement", "Pause"]
    assert all(text_of(source, statement) == "myMove" for statement in expanded)


# ------------------------------------------------------------ error recovery


def test_a_syntax_error_loses_only_its_own_colon_separated_statement() -> None:
    source = "a = 1 : b = ) : c = 3\nd = 4\n"
    found = statements(source)
    assert [type(statement).__name__ for statement in found] == [
        "Assignment",
        "SyntaxError_",
        "Assignment",
        "Assignment",
    ]
    assert [text_of(source, statement) for statement in found] == ["a = 1", "b = )", "c = 3", "d = 4"]


def test_lines_after_a_syntax_error_are_parsed() -> None:
    source = "a = (\nPRINT 1\nGO\n"
    document = mintlang.parse(source)
    assert [type(line.statements[0]).__name__ for line in document.lines] == [
        "SyntaxError_",
        "Print",
        "KeywordStatement",
    ]
    assert len(document.diagnostics) == 1


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # 2003 syntax error: unexpected token; the manual's missing ")" (line 18922)
        ("a = = 2\n", [("E2003", "=")]),
        ('IF (( a > b) AND (c > b) THEN PRINT "b is the lowest value"\n', [("E2003", "THEN")]),
        ("x = (1\n", [("E2003", "")]),
        # 2004 parentheses error: one ")" too many (line 18927)
        ("a = (b + 2) *3)\n", [("E2004", ")")]),
        # 2006 reserved keyword used as a variable (line 18940)
        ("FOR loop = 1 TO 10\n", [("E2006", "loop")]),
        ('INPUT "Enter speed", SPEED\n', [("E2006", "SPEED")]),
        # a keyword after DIM is a syntax error whatever its kind (DIM, line 9189)
        ("DIM loop\n", [("E2003", "loop")]),
        ("DIM speed\n", [("E2003", "speed")]),
        # 2007 THEN or DO expected (line 18946)
        ("IF a PRINT 1\n", [("E2007", "PRINT")]),
        ('IF (a < b) PRINT "a is less than b"\n', [("E2007", "PRINT")]),
        # 2008 TO expected (line 18951)
        ("FOR a = 1 10\n", [("E2008", "10")]),
    ],
)
def test_parse_errors_carry_the_controllers_error_numbers(source: str, expected: list[tuple[str, str]]) -> None:
    found = mintlang.parse(source).diagnostics
    assert placed(source, "code", "text", found=found) == expected
    assert all(d.severity is Severity.ERROR for d in found)


@pytest.mark.parametrize(
    ("source", "column", "command"),
    [
        pytest.param('PRINT "X=", a USING 4,1, " Y=", b\n', 24, "PRINT", id="print"),
        pytest.param("? a USING 4 ; b\n", 13, "PRINT", id="question-mark"),
        pytest.param('INPUT "A = ", a USING -5,2, b\n', 27, "INPUT", id="input"),
    ],
)
def test_anything_after_using_is_a_syntax_error_saying_using_ends_the_statement(
    source: str, column: int, command: str
) -> None:
    # 000:15295-15296 and 000:12212: in the formats of PRINT and INPUT, USING and its digit counts come last
    (diagnostic,) = mintlang.parse("DIM a\nDIM b\n" + source).diagnostics
    assert (diagnostic.code, diagnostic.message) == (
        "E2003",
        f"Syntax error: nothing may follow USING and its digit counts: write the rest in another {command}",
    )
    assert diagnostic.span.start == len("DIM a\nDIM b\n") + column - 1


@pytest.mark.parametrize(
    ("source", "column"),
    [
        pytest.param('IF a = 3 THEN PRINT "three" ELSE PRINT "other"\n', 29, id="after-a-print"),
        pytest.param("IF a THEN b = 1 ELSE b = 2\n", 17, id="after-an-assignment"),
    ],
)
def test_else_after_if_then_is_a_syntax_error_naming_the_if_block(source: str, column: int) -> None:
    # 000:1586-1587: the simple IF .. THEN has no ELSE; the IF block (IF .. DO .. ELSE .. ENDIF) has one
    (diagnostic,) = mintlang.parse("DIM a\nDIM b\n" + source).diagnostics
    assert (diagnostic.code, diagnostic.message) == (
        "E2003",
        "Syntax error: IF .. THEN has no ELSE: write an IF .. DO block with ELSE and ENDIF",
    )
    assert diagnostic.span.start == len("DIM a\nDIM b\n") + column - 1


def test_next_with_its_loop_variable_is_an_error_whose_safe_fix_removes_the_name() -> None:
    # v4 guide 3.7.1 and the v3 guide 5.2.1: unlike BASIC, NEXT takes no index name
    source = "DIM i\nFOR i = 1 TO 3\nNEXT i\n"
    (diagnostic,) = mintlang.parse(source).diagnostics
    assert (diagnostic.code, diagnostic.message) == (
        "E2003",
        "Syntax error: NEXT takes no loop variable: write NEXT alone",
    )
    (fix,) = diagnostic.fixes
    (edit,) = fix.edits
    assert (
        fix.safe and source[: edit.span.start] + edit.text + source[edit.span.end :] == "DIM i\nFOR i = 1 TO 3\nNEXT\n"
    )


@pytest.mark.parametrize(
    ("source", "fixed", "command"),
    [
        pytest.param("LOCATE #1, 5, 5\n", "LOCATE #1 5, 5\n", "LOCATE", id="locate"),
        pytest.param('LINE #3, 2, "A"\n', 'LINE #3 2, "A"\n', "LINE", id="line"),
        pytest.param('INPUT #1, "A = ", a\n', 'INPUT #1 "A = ", a\n', "INPUT", id="input"),
        pytest.param("CLS #3,\n", "CLS #3\n", "CLS", id="cls"),
    ],
)
def test_a_comma_after_the_terminal_is_an_error_whose_fix_removes_it(source: str, fixed: str, command: str) -> None:
    # the formats write {#<terminal>} then the operands, and the examples no comma: LOCATE #3 10,10 (000:13693),
    # LINE #3 2, "A = ", a (000:13660), CLS #3 (000:8269)
    (diagnostic,) = mintlang.parse("DIM a\n" + source).diagnostics
    terminal = source.split(",", maxsplit=1)[0].split()[1]
    assert (diagnostic.code, diagnostic.message) == (
        "E2003",
        f"Syntax error: {command} takes no ',' after its terminal {terminal}",
    )
    assert diagnostic.span.start == len("DIM a\n") + source.index(",")
    (fix,) = diagnostic.fixes
    (edit,) = fix.edits
    text = "DIM a\n" + source
    assert fix.safe and text[: edit.span.start] + edit.text + text[edit.span.end :] == "DIM a\n" + fixed


def test_next_with_two_loop_variables_has_no_fix_as_basic_closed_two_loops_with_it() -> None:
    (diagnostic,) = mintlang.parse("DIM i\nDIM j\nFOR i = 1 TO 3\nFOR j = 1 TO 3\nNEXT j, i\n").diagnostics
    assert diagnostic.message.endswith("NEXT takes no loop variable: write NEXT alone") and diagnostic.fixes == ()


@pytest.mark.parametrize(
    ("source", "message", "fixed"),
    [
        # 000:1870 and 000:5754: "the hash is not used in the GOSUB statement"
        pytest.param("GOSUB #init\n", "GOSUB names its label without '#': GOSUB init", "GOSUB init\n", id="gosub"),
        pytest.param("goto # done\n", "GOTO names its label without '#': GOTO done", "goto done\n", id="goto"),
        pytest.param(
            "IF IN1 THEN GOSUB #fault\n",
            "GOSUB names its label without '#': GOSUB fault",
            "IF IN1 THEN GOSUB fault\n",
            id="after-then",
        ),
    ],
)
def test_a_label_written_with_its_hash_after_gosub_or_goto(source: str, message: str, fixed: str) -> None:
    (diagnostic,) = mintlang.parse(source).diagnostics
    assert (diagnostic.code, diagnostic.message) == ("E2003", f"Syntax error: {message}")
    (fix,) = diagnostic.fixes
    (edit,) = fix.edits
    assert fix.safe and source[: edit.span.start] + edit.text + source[edit.span.end :] == fixed


@pytest.mark.parametrize(
    ("source", "written", "closer"),
    [
        # 000:1589-1600: an IF .. DO block ends with ENDIF, one word; END IF as in other BASICs closes it all the
        # same for the block stack, so it is one error with its fix, not also an IF never closed
        pytest.param('DIM a\nIF a = 10 DO\n  PRINT "ten"\nEND IF\nEND\n', "END IF", "ENDIF", id="end-if"),
        pytest.param(
            "DIM a\nWHILE a < 3\n  a = a + 1\nEND WHILE\nEND\n", "END WHILE", "ENDW", id="end-while"
        ),  # 000:1781
    ],
)
def test_a_closer_written_in_two_words_is_one_error_with_the_word_as_fix(
    source: str, written: str, closer: str
) -> None:
    (error,) = mintlang.check(source)
    assert (error.code, source[error.span.start : error.span.end]) == ("E2003", written)
    assert error.message.endswith(f"ends with {closer}, not {written}")
    (fix,) = error.fixes
    (edit,) = fix.edits
    fixed = source[: edit.span.start] + edit.text + source[edit.span.end :]
    assert (fixed, mintlang.check(fixed)) == (source.replace(written, closer), [])


def test_a_keyword_after_gosub_is_refused_as_a_label() -> None:
    (diagnostic,) = mintlang.parse("GOSUB loop\n").diagnostics
    assert diagnostic.code == "E2006" and diagnostic.message.endswith("cannot be used as a label")


def test_a_for_loop_with_a_keyword_variable_still_opens_a_block() -> None:
    # FOR loop = 1 TO 10 : ... : NEXT (line 18940) is one error, not a cascade at NEXT
    codes = [d.code for d in mintlang.check("FOR loop = 1 TO 10\nNEXT\n")]
    assert codes == ["E2006"]


@pytest.mark.parametrize(
    "source",
    [
        "a = 1 +\n",
        "x = (1",
        "PRINT 'AB'\r\n",
        "FOR a = 1 TO\n",
        'PRINT "open',
        "IF a THEN\nELSE",
        "a = b )",
        "DIM y(3) = 1,",
        "SPEED[0,,2] = 1;",
        "05",
        "#",
    ],
)
def test_every_diagnostic_span_lies_inside_the_source(source: str) -> None:
    found = mintlang.check(source)
    assert found
    for diagnostic in found:
        assert 0 <= diagnostic.span.start <= diagnostic.span.end <= len(source)


# -------------------------------------------------------------------- spans


def test_nodes_cover_exactly_the_text_they_were_parsed_from() -> None:
    source = "  SPEED[0,1] = 10, a + 2 * b : REM comment\nIF POS.(a+1) > 5 THEN GO\n"
    write, if_then = statements(source)
    assert isinstance(write, n.KeywordStatement)
    assert text_of(source, write) == "SPEED[0,1] = 10, a + 2 * b"
    assert text_of(source, write.keyword) == "SPEED[0,1]"
    assert write.keyword.selector is not None
    assert text_of(source, write.keyword.selector) == "[0,1]"
    assert source[write.keyword.spelling_span.start : write.keyword.spelling_span.end] == "SPEED"
    second = (write.values or ())[1]
    assert isinstance(second, n.Binary)
    assert text_of(source, second) == "a + 2 * b"
    assert text_of(source, second.right) == "2 * b"
    assert isinstance(if_then, n.IfThen)
    assert text_of(source, if_then) == "IF POS.(a+1) > 5 THEN GO"
    assert text_of(source, if_then.condition) == "POS.(a+1) > 5"
    assert [text_of(source, statement) for statement in if_then.body] == ["GO"]


def test_a_line_span_includes_its_trailing_comment_but_not_its_line_break() -> None:
    source = "#start\nGO : REM go now\r\n"
    label_line, go_line = mintlang.parse(source).lines
    assert label_line.label is not None
    assert (label_line.label.text, text_of(source, label_line.label)) == ("start", "#start")
    assert text_of(source, go_line) == "GO : REM go now"


def test_label_with_statements_on_the_same_line() -> None:
    source = "#loop1 : PRINT 1\n"
    (line,) = mintlang.parse(source).lines
    assert line.label is not None
    assert line.label.text == "loop1"
    assert [type(statement).__name__ for statement in line.statements] == ["Print"]
