"""Statements written as C or another BASIC writes them, told how Mint writes them (a syntax error, 2003).

Mint assigns with ``=`` alone and knows only ``+ - * /`` and MOD as arithmetic (000:1274-1282), so
``count += 1`` (and ``count++``) is told ``count = count + 1``, with that as a safe fix: the target and the operator
are both written out, and a right-hand side of more than one token is bracketed, as ``*=`` binds it.
C's ``!=`` and ``==`` are told Mint's ``<>`` and ``=`` (000:1256-1263), ``&&`` and ``||`` its AND and OR, ``//`` REM;
``A NOT = B`` is told ``<>`` (000:14724-14729);
Visual Basic's ``DO .. LOOP UNTIL`` Mint's loops (000:1707, 1747, 1778, 1797) and ``ELSE IF`` a nested IF block;
strings joined with ``+`` or ``&`` PRINT's comma; ``a ^ 2`` POW(a, 2); ``END SUB`` RETURN; ``&H1F`` 0x1F;
``PRINT USING "##.#"; x`` PRINT x USING 2, 1; ``a = "y"`` that Mint's values are numbers (000:929).
"""

from __future__ import annotations

import re
from typing import NamedTuple

from mintlang.analysis.suggestions import NESTED_IF
from mintlang.codes import mint_error
from mintlang.diagnostics import Diagnostic, Edit, Fix
from mintlang.dialect import Dialect
from mintlang.syntax.grammar import ParseFailure
from mintlang.syntax.lines import LogicalLine
from mintlang.syntax.spans import span as shared_span
from mintlang.syntax.tokens import TokenKind

_K = TokenKind
_ARITHMETIC = frozenset({_K.PLUS, _K.MINUS, _K.STAR, _K.SLASH})
_BRACKETS = {_K.LPAR: 1, _K.LSQB: 1, _K.RPAR: -1, _K.RSQB: -1}


def other_languages_habit(
    line: LogicalLine, begin: int, end: int, failure: ParseFailure, dialect: Dialect
) -> Diagnostic | None:
    """The diagnostic for the statement from ``begin`` to ``end`` if it fails where another language's way of
    writing it shows."""
    failed = begin + failure.index
    return (
        _compound_assignment(line, begin, end, failed)
        or _increment(line, begin, end, failed)
        or _c_operator(line, begin, end, failed)
        or _not_equals(line, end, failed)
        or _basic_loop(line, begin, end, failed)
        or _else_if(line, begin, end, failed)
        or _end_sub(line, begin, end, failed)
        or _radix_number(line, end, failed, dialect)
        or _joined_strings(line, begin, end, failed)
        or _string_value(line, begin, end, failed)
        or _power(line, begin, end, failed)
        or _using_picture(line, begin, end, failed)
    )


class _Operator(NamedTuple):
    """How Mint writes one of C's operators, and whether writing it so keeps its meaning."""

    message: str
    replacement: str
    safe: bool


# C's operators (and its comment), by their two signs, each lexed as one of Mint's: '!' is Mint's logical NOT
# (000:1419), and AND/& and OR/| work bit by bit (000:1286-1289, 1306-1307), so 5 & 6 is 4 where 5 && 6 is true.
_C_OPERATORS = {
    "!=": _Operator("Mint writes 'not equal to' as <>", "<>", safe=True),  # 000:1262
    "==": _Operator("Mint compares with one '='", "=", safe=True),  # 000:1258
    "&&": _Operator("Mint has no '&&': write AND, which works bit by bit", "AND", safe=False),
    "||": _Operator("Mint has no '||': write OR, which works bit by bit", "OR", safe=False),
    "//": _Operator("Mint's comments begin with REM", "REM", safe=True),  # 000:15506-15515
}


def _compound_assignment(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``count += 1``: an operator joined to the ``=`` of an assignment, the grammar failing at one of the two."""
    kinds = line.kinds
    operator = _first_at_the_top(kinds, begin, end, _K.EQUAL) - 1
    if (
        operator <= begin
        or operator + 2 >= end  # no '=' (first_at_the_top gave the end), or nothing after it
        or failed not in (operator, operator + 1)
        or kinds[operator] not in _ARITHMETIC
        or not _assignable(kinds, begin, operator)
        or line.ends[operator] != line.starts[operator + 1]
        or any(line.expanded[begin:end])  # a macro's text: its tokens are not where the fix would write
    ):
        return None
    target = _written(line, begin, operator)
    written = line.texts[operator]
    value = _written(line, operator + 2, end)
    value = value if end - operator - 2 == 1 else f"({value})"
    joined = shared_span(line.starts[operator], line.ends[operator + 1])
    rewrite = Edit(shared_span(line.starts[operator], line.ends[end - 1]), f"= {target} {written} {value}")
    fix = Fix(f"Write {target} = {target} {written} {value}", (rewrite,), safe=True)
    message = f"Mint has no '{written}=': write {target} = {target} {written} {value}"
    return mint_error(2003, joined, message, fixes=(fix,))


def _increment(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``count++``: a statement ending in two joined signs, ``+`` or ``-``, after what it changes."""
    kinds = line.kinds
    last = end - 1
    signs = kinds[last - 1 : end]
    if (
        last - 1 <= begin
        or signs not in ([_K.PLUS, _K.PLUS], [_K.MINUS, _K.MINUS])
        or line.ends[last - 1] != line.starts[last]
        or failed < last - 1
        or not _assignable(kinds, begin, last - 1)
        or any(line.expanded[begin:end])
    ):
        return None
    target, sign = _written(line, begin, last - 1), line.texts[last]
    joined = shared_span(line.starts[last - 1], line.ends[last])
    written = f"{target} = {target} {sign} 1"
    fix = Fix(
        f"Write {written}",
        (Edit(shared_span(line.ends[last - 2], line.ends[last]), written[len(target) :]),),
        safe=True,
    )
    return mint_error(2003, joined, f"Mint has no '{sign}{sign}': write {written}", fixes=(fix,))


def _c_operator(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``a != 2``, ``a == 2``, ``a && b``: two signs written together, the grammar failing at one of them."""
    for first in (failed - 1, failed):
        if not (begin <= first and first + 1 < end) or line.ends[first] != line.starts[first + 1]:
            continue
        operator = _C_OPERATORS.get(line.texts[first] + line.texts[first + 1])
        if operator is not None and not line.expanded[first]:
            joined = shared_span(line.starts[first], line.ends[first + 1])
            # every one in the statement: the parse stops at the first, so the others would each be met only once
            # the one before is mended; what follows a // is its comment
            places = [first] if operator.replacement == "REM" else _joined_again(line, first, end)
            edits = tuple(
                Edit(shared_span(line.starts[at], line.ends[at + 1]), _apart(line, at, at + 2, operator.replacement))
                for at in places
            )
            fix = Fix(f"Write {operator.replacement}", edits, safe=operator.safe)
            return mint_error(2003, joined, operator.message, fixes=(fix,))
    return None


def _not_equals(line: LogicalLine, end: int, failed: int) -> Diagnostic | None:
    """``IF A NOT = B``: NOT (or ``!`` apart from the ``=``; joined, it is C's ``!=``, told above) before the ``=``
    of a comparison, the grammar failing at the NOT (000:14724-14729)."""
    kinds = line.kinds
    if not (failed + 1 < end and kinds[failed] is _K.NOT and kinds[failed + 1] is _K.EQUAL):
        return None
    if line.expanded[failed] or line.expanded[failed + 1]:
        return None  # a macro's text is not where the fix would write
    words = shared_span(line.starts[failed], line.ends[failed + 1])
    fix = Fix("Write <>", (Edit(words, "<>"),), safe=True)
    return mint_error(2003, words, "Mint writes 'not equal to' as <>, with no NOT before the '='", fixes=(fix,))


def _joined_again(line: LogicalLine, first: int, end: int) -> list[int]:
    """Where the two signs joined at ``first`` are written joined again, from ``first`` up to ``end``."""
    signs = line.texts[first] + line.texts[first + 1]
    found: list[int] = []
    at = first
    while at + 1 < end:
        if (
            line.texts[at] + line.texts[at + 1] == signs
            and line.ends[at] == line.starts[at + 1]
            and not line.expanded[at]
        ):
            found.append(at)
            at += 2
        else:
            at += 1
    return found


def _basic_loop(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """Visual Basic's ``DO`` and ``LOOP UNTIL``: DO only follows an IF's condition (000:1594-1600), and LOOP
    .. ENDL takes no condition (000:1797-1799)."""
    kinds = line.kinds
    if kinds[begin] is _K.DO and failed == begin:
        loops = "write REPEAT .. UNTIL, WHILE .. ENDW or LOOP .. ENDL"  # 000:1707-1797
        return mint_error(2003, line.token_span(begin), f"Mint has no DO loop: {loops}")
    if kinds[begin] is _K.LOOP and failed == begin + 1 < end and kinds[failed] in (_K.UNTIL, _K.WHILE):
        detail = "LOOP .. ENDL loops for ever and takes no condition: a loop tested at its end is REPEAT .. UNTIL"
        return mint_error(2003, line.token_span(failed), detail)
    return None


def _else_if(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``ELSE IF``: an IF after the ELSE on its line, the grammar failing at the IF."""
    if not (line.kinds[begin] is _K.ELSE and failed == begin + 1 < end and line.kinds[failed] is _K.IF):
        return None
    return mint_error(2003, shared_span(line.starts[begin], line.ends[failed]), f"Mint has no ELSE IF: {NESTED_IF}")


def _end_sub(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``END SUB``: a subroutine is a label and what follows it up to its RETURN (000:1841-1850)."""
    if not (line.kinds[begin] is _K.END and failed == begin + 1 == end - 1 and line.texts[failed].upper() == "SUB"):
        return None
    words = shared_span(line.starts[begin], line.ends[failed])
    fix = Fix("Write RETURN", (Edit(words, "RETURN"),), safe=True)
    return mint_error(2003, words, "a subroutine ends with RETURN, not END SUB", fixes=(fix,))


class _Radix(NamedTuple):
    """How Mint writes the numbers of one of other BASICs' radix prefixes."""

    base: int
    name: str
    prefix: str | None  # what Mint writes before the digits; None: Mint has no such numbers
    told: str = ""  # the prefix as the message names it


# Other BASICs' radix prefixes, each lexed as '&' (Mint's AND) and a word: Mint v4 writes hexadecimal with 0x
# (000:769-770), binary with a leading zero (000:743-745, 001:1185), and has no octal.
_RADICES = {
    "H": _Radix(16, "hexadecimal", "0x", "0x"),
    "B": _Radix(2, "binary", "0", "a leading 0"),
    "O": _Radix(8, "octal", None),
}


def _radix_number(line: LogicalLine, end: int, failed: int, dialect: Dialect) -> Diagnostic | None:
    """``&H1F``, ``&B101``, ``&O17``: an '&' the grammar fails at, joined to a prefix letter and its digits. The
    number is written as Mint writes it, or in decimal where Mint has no such numbers (v3 has no hexadecimal)."""
    if not (failed + 1 < end and line.texts[failed] == "&" and line.ends[failed] == line.starts[failed + 1]):
        return None
    word = line.texts[failed + 1]
    radix, digits = _RADICES.get(word[:1].upper()), word[1:]
    if radix is None or not digits.replace("_", "").isalnum() or any(line.expanded[failed : failed + 2]):
        return None
    try:
        value = int(digits, radix.base)
    except ValueError:
        return None
    if radix.prefix is None or (radix.base == 16 and dialect is Dialect.V3):
        written = str(value)
        message = f"Mint{' v3' if radix.prefix else ''} has no {radix.name} numbers: write {written}"
    else:
        written = radix.prefix + digits
        message = f"Mint writes a {radix.name} number with {radix.told}: {written}"
    span = shared_span(line.starts[failed], line.ends[failed + 1])
    return mint_error(2003, span, message, fixes=(Fix(f"Write {written}", (Edit(span, written),), safe=True),))


# What other BASICs join strings with, and what Mint makes of it where it is no PRINT item separator.
_JOINS = {"+": "", "&": ", its bitwise AND"}  # 000:1286-1289


def _joined_strings(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``PRINT "a" + b``, ``PRINT "a" & b``: PRINT's items follow one another after a comma (000:15299-15302), and
    a string is no value to add or AND. Between two strings the comma is plainly meant; after one, ``+`` may have
    summed what follows, and of ``"a" & b & c`` the second '&' would be left as an AND. One fix makes every join
    beside a string a comma, and is safe only when each stands between two strings."""
    kinds, texts = line.kinds, line.texts
    if kinds[begin] is not _K.PRINT and texts[begin].upper() != "LINE":  # LINE takes PRINT's items: 000:15353
        return None
    join = failed if failed < end and texts[failed] in _JOINS else failed - 1
    if not (begin < join < end - 1 and texts[join] in _JOINS and _K.STRING in (kinds[join - 1], kinds[join + 1])):
        return None
    joins = _joins_beside_strings(line, join, end)
    safe = all(kinds[at - 1] is kinds[at + 1] is _K.STRING for at in joins)
    edits = tuple(Edit(shared_span(line.ends[at - 1], line.ends[at]), ",") for at in joins)
    span = line.token_span(join)
    fix = Fix("Separate the items with ','", edits, safe=safe)
    detail = f"Mint does not join strings with '{texts[join]}'{_JOINS[texts[join]]}: separate the items with ',', "
    return mint_error(2003, span, detail + "which prints each directly after the one before", fixes=(fix,))


_COMPARED = frozenset({_K.EQUAL, _K.NOTEQUAL, _K.LESSTHAN, _K.MORETHAN, _K.LESSEQUAL, _K.MOREEQUAL})


def _string_value(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``a = "y"``, ``IF key = "Y"``: a string assigned or compared, where Mint's values are numbers (000:929). One
    character is told its character constant, a number (000:801-806); the fix is unsafe, the quotes saying the
    author thought of text."""
    kinds = line.kinds
    if not (begin < failed < end and kinds[failed] is _K.STRING and kinds[failed - 1] in _COMPARED):
        return None
    if line.expanded[failed]:
        return None  # a macro's text: not where the fix would write
    message = "Mint's values are numbers: a string can only be printed, or be INPUT's prompt"
    character = line.texts[failed][1:-1]
    if len(character) != 1 or character == "'":
        return mint_error(2003, line.token_span(failed), message)
    constant = f"'{character}'"
    fix = Fix(f"Write {constant}", (Edit(line.token_span(failed), constant),), safe=False)
    detail = f"{message}; a character in single quotes, {constant}, is its ASCII code"
    return mint_error(2003, line.token_span(failed), detail, fixes=(fix,))


def _joins_beside_strings(line: LogicalLine, join: int, end: int) -> list[int]:
    """The joins from ``join`` on, at its depth of brackets, that stand beside a string."""
    found: list[int] = []
    depth = 0
    for at in range(join, end - 1):
        depth += _BRACKETS.get(line.kinds[at], 0)
        if depth < 0:  # the bracket around ``join`` closes
            break
        if depth == 0 and line.texts[at] in _JOINS and _K.STRING in (line.kinds[at - 1], line.kinds[at + 1]):
            found.append(at)
    return found


_OPERANDS = frozenset({_K.NAME, _K.NUMBER, _K.KEYWORD})


def _power(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``a ^ 2``: the power is the function POW(x, y) (000:1410); a function is evaluated before any operator
    around it (000:1418-1420), so one token on each side of the caret goes into its brackets as written."""
    kinds = line.kinds
    caret = failed if failed < end and kinds[failed] is _K.CIRCUMFLEX else failed - 1
    if not (begin < caret < end and kinds[caret] is _K.CIRCUMFLEX):
        return None
    span = line.token_span(caret)
    base, exponent = caret - 1, caret + 1
    single = exponent < end and kinds[base] in _OPERANDS and kinds[exponent] in _OPERANDS
    single = single and (base == begin or kinds[base - 1] is not _K.DOT) and not line.expanded[base]
    if not single or (exponent + 1 < end and kinds[exponent + 1] in (_K.DOT, _K.LPAR, _K.LSQB)):
        return mint_error(2003, span, "Mint has no '^': write POW(x, y) for x to the power y")
    written = f"POW({line.texts[base]}, {line.texts[exponent]})"
    fix = Fix(f"Write {written}", (Edit(shared_span(line.starts[base], line.ends[exponent]), written),), safe=True)
    return mint_error(2003, span, f"Mint has no '^': write {written}", fixes=(fix,))


_PICTURE = re.compile(r'"(#+)(?:\.(#*))?"')  # other BASICs' number picture: digits before and after the point


def _using_picture(line: LogicalLine, begin: int, end: int, failed: int) -> Diagnostic | None:
    """``PRINT USING "###.##"; x``: Mint writes the items first, then USING with the number of integer and
    fractional digits (000:15295-15296, 15313-15315). The integer part is padded with zeroes (000:15330-15332)
    where a picture pads it with spaces, so the rewrite, offered for one item and a picture of '#'s, is unsafe."""
    kinds = line.kinds
    picture = begin + 2
    if not (kinds[begin] is _K.PRINT and kinds[begin + 1] is _K.USING and failed == picture < end):
        return None
    if kinds[picture] is not _K.STRING:
        return None
    command = line.texts[begin] if line.texts[begin] == "?" else line.texts[begin].upper()
    counts = _PICTURE.fullmatch(line.texts[picture])
    item = picture + 2
    separated = item < end and kinds[picture + 1] in (_K.SEMICOLON, _K.COMMA)
    one_item = separated and all(_first_at_the_top(kinds, item, end, sign) == end for sign in (_K.COMMA, _K.SEMICOLON))
    if counts is None or not one_item or any(line.expanded[begin:end]):
        written, fixes = f"{command} <items> USING <integer digits>, <fraction digits>", ()
    else:
        digits = str(len(counts[1])) + (f", {len(counts[2])}" if counts[2] else "")
        written = f"{command} {_written(line, item, end)} USING {digits}"
        rewrite = Edit(shared_span(line.starts[begin + 1], line.ends[end - 1]), written[len(command) + 1 :])
        fixes = (Fix(f"Write {written}", (rewrite,), safe=False),)
    message = f"Mint's USING follows the items it formats and counts the digits, it takes no picture: {written}"
    return mint_error(2003, line.token_span(picture), message, fixes=fixes)


def _apart(line: LogicalLine, first: int, end: int, word: str) -> str:
    """``word`` in place of the tokens from ``first`` to ``end``, a space on each side that touches a token
    when it is a word (``a=1&&b=2`` becomes ``a=1 AND b=2``, not ``a=1ANDb=2``)."""
    if not word.isalpha():
        return word
    before = " " if first > 0 and line.ends[first - 1] == line.starts[first] else ""
    after = " " if end < len(line.kinds) and line.ends[end - 1] == line.starts[end] else ""
    return f"{before}{word}{after}"


def _assignable(kinds: list[TokenKind], begin: int, end: int) -> bool:
    """Whether the tokens from ``begin`` to ``end`` can be what an assignment sets: a variable, an array's element
    or a keyword with its axes (``count``, ``a(2)``, ``SPEED.0``), not a command and its operands (``PRINT a``)."""
    if kinds[begin] not in (_K.NAME, _K.KEYWORD):
        return False
    return end == begin + 1 or kinds[begin + 1] in (_K.LPAR, _K.LSQB, _K.DOT)


def _written(line: LogicalLine, first: int, end: int) -> str:
    """The tokens from ``first`` to ``end`` as written, a space where they were apart."""
    texts = [line.texts[first]]
    for index in range(first + 1, end):
        texts.append(f" {line.texts[index]}" if line.starts[index] > line.ends[index - 1] else line.texts[index])
    return "".join(texts)


def _first_at_the_top(kinds: list[TokenKind], begin: int, end: int, wanted: TokenKind) -> int:
    """The index of the first ``wanted`` outside brackets from ``begin`` (``end`` if none)."""
    depth = 0
    for index in range(begin, end):
        kind = kinds[index]
        if kind is wanted and depth == 0:
            return index
        depth = max(0, depth + _BRACKETS.get(kind, 0))
    return end
