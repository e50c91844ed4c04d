"""The syntax tree: frozen records with exact source spans.

Every node carries the ``Span`` of the source text it was parsed from. Tokens
that came from a macro expansion carry the span of the macro's use, so
diagnostics inside expanded text point at the macro name the user wrote.
Names keep their spelling; ``identity`` gives the controller's view of a name
(upper case, first ten characters significant).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable, Iterator
from functools import lru_cache
from operator import attrgetter
from typing import NamedTuple, TypeVar

from mintlang.diagnostics import Span
from mintlang.records import record

T = TypeVar("T")
SIGNIFICANT_CHARACTERS = 10  # names: only the first ten characters count (v4 guide 3.2.5, 3.9)


def identity(name: str) -> str:
    """The controller's identity of a user name: case-folded, first ten characters."""
    return name[:SIGNIFICANT_CHARACTERS].upper()


@record
class Name:
    """A user name as written: variable, array, macro or label."""

    text: str
    span: Span

    @property
    def identity(self) -> str:
        return identity(self.text)


# ---------------------------------------------------------------- expressions


@record
class Number:
    """A number literal: decimal, binary (a leading 0) or hexadecimal (0x), as ``number_value`` reads it."""

    span: Span
    text: str
    value: float


@lru_cache(maxsize=8192)  # one float per literal text: programs write the same numbers again and again
def number_value(text: str) -> float:
    """The value of a valid Mint number literal: decimal, binary (leading 0) or 0x hex; infinite when
    it is too large for a double (no controller holds it: the lexer reports it, mint-run stops on it)."""
    if text.isdigit() and (text[0] != "0" or len(text) == 1):
        return float(text)  # the common case
    digits = text.replace("_", "")
    if digits[:2] in ("0x", "0X"):
        return _whole(int(digits[2:], 16))
    if len(digits) > 1 and digits[0] == "0" and "." not in digits:
        return _whole(int(digits, 2))
    return float(digits)


def _whole(value: int) -> float:
    try:
        return float(value)
    except OverflowError:
        return math.inf


def character_code(text: str) -> int:
    """The value of a character constant written ``'a'``: the code of its upper case (v4 guide 3.2.3), here 65.

    A character whose upper case is two (``'ß'`` is ``SS``) keeps its own code.
    """
    upper = text[1].upper()
    return ord(upper) if len(upper) == 1 else ord(text[1])


@record
class CharConstant:
    """A character in single quotes (``'a'``): its character code, upper-cased (000:802-809)."""

    span: Span
    text: str
    value: int  # character_code(text): 'a' and 'A' are both 65


@record
class StringLiteral:
    """A string in double quotes, printed (PRINT, LINE) or prompting (INPUT): Mint has no string variables (000:929)."""

    span: Span
    text: str  # with its quotes
    value: str  # without them


@record
class ConstantRef:
    """A Mint constant: ``_`` and its name (``_tmRS232``), the name upper-cased."""

    span: Span
    name: str


@record
class VariableRef:
    """A variable, or an array named without an index, read or written."""

    span: Span
    name: Name


@record
class ElementRef:
    """``name(index)``: an array element."""

    span: Span
    name: Name
    index: Expression


@record
class Selector:
    """Which axes or channel a keyword addresses: ``[0,1]`` or ``.1`` / ``.(a+1)``, in MintMT ``(0,1)``.

    ``items`` holds ``None`` for an empty place (``[0,,2]``, error 2001). A MintMT
    keyword may take indices after its axes, ``CONTOURPARAMETER([0,1],0)``: the
    last ``indices`` items are those, the others the axes (``axes``).
    """

    span: Span
    dot: bool
    items: tuple[Expression | None, ...]
    indices: int = 0

    @property
    def axes(self) -> tuple[Expression | None, ...]:
        return self.items[: len(self.items) - self.indices] if self.indices else self.items


@record
class KeywordRef:
    """A keyword as written: full name, abbreviation or with a glued channel (``IN3``)."""

    span: Span
    keyword: str  # canonical upper-case name
    spelling: str
    spelling_span: Span
    selector: Selector | None
    channel: int | None  # from a glued channel number


@record
class Call:
    """A function keyword: ``POW(x, y)``, ``COMMS(1)`` or bracketless ``SIN 90``."""

    span: Span
    function: str  # canonical upper-case name
    spelling: str
    spelling_span: Span
    arguments: tuple[Expression, ...]
    bracketed: bool


@record
class Unary:
    """An operator before its operand: sign, bitwise ``~`` or logical ``NOT``."""

    span: Span
    operator: str  # "-", "+", "~", "NOT"
    operand: Expression


@record
class Binary:
    """An operator between two operands; the parser has already applied the precedence of the dialect."""

    span: Span
    operator: str  # "+", "-", "*", "/", "MOD", "=", "<>", "<", ">", "<=", ">=", "AND", "OR", "XOR"
    left: Expression
    right: Expression


@record
class Parenthesised:
    """An expression in round brackets, kept so that spans and re-printing show them."""

    span: Span
    expression: Expression


Expression = (
    Number | CharConstant | ConstantRef | VariableRef | ElementRef | KeywordRef | Call | Unary | Binary | Parenthesised
)


# ----------------------------------------------------------------- statements


@record
class Assignment:
    """``name = expr`` or ``name(index) = expr``."""

    span: Span
    target: VariableRef | ElementRef
    value: Expression


@record
class KeywordStatement:
    """A keyword used as a statement.

    ``values`` is set for a write (``SPEED[0,1] = 10,20;``, ``None`` marks a
    skipped place as in ``SPEED = ,10``; ``fill`` is the trailing ``;``);
    ``arguments`` for a command with operands (``LOCATE 1,1``); a terminal
    command that prints (``LINE 2, HEX a;``) keeps how each argument is
    printed in ``formats``, whether a separator ends the line in ``trailing``,
    and which arguments a ``;`` follows rather than a comma in ``semicolons``.
    """

    span: Span
    keyword: KeywordRef
    terminal: Expression | None
    values: tuple[Expression | None, ...] | None
    fill: bool
    arguments: tuple[Expression | StringLiteral, ...]
    using: tuple[Expression, ...] = ()
    formats: tuple[str | None, ...] = ()  # HEX, DEC or BIN per argument; empty when none is written
    trailing: bool = False
    semicolons: tuple[int, ...] = ()  # the indices of the arguments a ";" follows (PRINT's tab, 000:15300-15302)


@record
class FunctionStatement:
    """``COMMS(1) = 5`` or ``CAMTABLE(0, positions, increments)``."""

    span: Span
    call: Call
    values: tuple[Expression | None, ...] | None
    fill: bool


@record
class BareName:
    """A user word standing alone: an unknown keyword (3007) unless a macro explains it."""

    span: Span
    name: Name


@record
class IfThen:
    """``IF condition THEN statements``: the one-line IF, its statements after THEN on the same line."""

    span: Span
    condition: Expression
    body: tuple[Statement, ...]


@record
class IfDo:
    """``IF condition DO``: opens an IF block, closed by ENDIF (ELSE between)."""

    span: Span
    condition: Expression


@record
class For:
    """``FOR variable = start TO end {STEP step}``: opens a loop closed by NEXT, which names no variable."""

    span: Span
    variable: Name
    start: Expression
    end: Expression
    step: Expression | None


@record
class Until:
    """``UNTIL condition``: closes the REPEAT loop opened last."""

    span: Span
    condition: Expression


@record
class While:
    """``WHILE condition``: opens a loop closed by ENDW."""

    span: Span
    condition: Expression


@record
class BlockWord:
    """A statement that is one word: ELSE ENDIF NEXT REPEAT ENDW LOOP ENDL EXIT RETURN END, and MintMT's
    STARTUP, ENDEVENT and ENDSTARTUP (``End Loop`` and ``End If`` are ENDL and ENDIF)."""

    span: Span
    word: str  # canonical upper-case keyword


@record
class EventBlock:
    """MintMT's ``Event NAME``, which opens the handler of that event up to ``End Event``."""

    span: Span
    name: Name


@record
class Jump:
    """``GOSUB label`` or ``GOTO label``."""

    span: Span
    word: str  # "GOSUB" or "GOTO"
    label: Name


@record
class Pause:
    """``PAUSE condition``: waits until the condition holds; None when none is written (error 2005)."""

    span: Span
    condition: Expression | None


@record
class Dim:
    """``DIM name``, ``DIM name = value`` or ``DIM name(size) = v1, v2 ...;``."""

    span: Span
    name: Name
    size: Expression | None
    values: tuple[Expression, ...]
    fill: bool
    modifier: str | None = None  # Mint v3's OFFLINE (a keyword anywhere else is an error)


@record
class Define:
    """``DEFINE name = body``: ``body_span`` is the raw text the macro stands for."""

    span: Span
    name: Name
    name_is_word: bool  # False for e.g. DEFINE 100 = "100" (error 3005)
    body_span: Span | None


@record
class Axes:
    """``AXES[list]``: sets the default axes that bracket-less axis keywords address."""

    span: Span
    selector: Selector | None


@record
class PrintItem:
    """One PRINT operand; ``separator`` is the "," or ";" written after it, if any."""

    span: Span
    value: Expression | StringLiteral | None
    format: str | None  # the modifier written before the value: "HEX", "DEC", "BIN" or None
    separator: str | None


@record
class Print:
    """``PRINT {#terminal} items {USING int {,frac}}`` (also ``?``); ``using`` holds USING's digit counts."""

    span: Span
    terminal: Expression | None
    items: tuple[PrintItem, ...]
    using: tuple[Expression, ...]


@record
class Input:
    """``INPUT {#terminal} {prompt,} variable {USING int {,frac}}``: reads a number typed at a terminal."""

    span: Span
    terminal: Expression | None
    prompt: StringLiteral | None
    target: VariableRef | ElementRef
    using: tuple[Expression, ...]


@record
class SyntaxError_:
    """A statement that could not be parsed; its diagnostic is in ``Document.diagnostics``.

    ``opens`` names the block it still opens (``FOR loop = 1 TO 10`` opens a
    FOR even though ``loop`` is a keyword), so its closer matches; ``closes``
    the closing word it still is (``NEXT a``), so its block is not left open.
    """

    span: Span
    opens: str | None = None
    closes: str | None = None


Statement = (
    Assignment
    | KeywordStatement
    | FunctionStatement
    | BareName
    | IfThen
    | IfDo
    | For
    | Until
    | While
    | BlockWord
    | EventBlock
    | Jump
    | Pause
    | Dim
    | Define
    | Axes
    | Print
    | Input
    | SyntaxError_
)


@record
class Line:
    """One logical line: an optional label and its statements.

    ``number`` is the 1-based physical line it starts on; a DIM list continued
    with trailing commas spans several physical lines.
    """

    span: Span
    number: int
    label: Name | None
    statements: tuple[Statement, ...]


@record
class LineSyntax:
    """One logical line as the parser sees it, wherever it stands.

    Its spans are relative to the start of its first physical line, so a line
    whose text did not change parses to the same ``LineSyntax`` after an edit
    above it: the language server re-parses, re-indexes and re-checks only what
    changed.
    """

    text: str  # from the start of its first physical line: what ``span`` and the spans inside index
    span: Span
    label: Name | None
    statements: tuple[Statement, ...]


class PlacedLine(NamedTuple):
    """A ``LineSyntax`` at its place in a file: ``origin`` is the offset of its first physical line.

    Equal lines share one ``syntax`` object, so the syntax names no place: what
    is known of a statement's place is keyed by ``number`` and the statement's
    index, and what is cached per line text by ``content``. A named tuple: a
    document keeps its lines as columns (``PackedLines``) and makes one per read.
    """

    origin: int
    number: int  # 1-based physical line it starts on
    syntax: LineSyntax
    content: Hashable  # the one parse of its text, dialect, controller and macros named (by identity): a cache key

    def span(self, relative: Span) -> Span:
        """Where ``relative``, a span of this line's syntax, is in the file."""
        origin = self.origin
        return _new(Span, (relative.start + origin, relative.end + origin))

    def absolute(self) -> Line:
        """The line with every span an offset into its file."""
        syntax = relocate(self.syntax, self.origin)
        return Line(syntax.span, self.number, syntax.label, syntax.statements)


_new = tuple.__new__  # builds Span without its Python-level constructor
_SPANLESS = frozenset({str, int, float, bool, type(None)})  # field values with no span inside
_FIELDS: dict[type, Callable[[object], tuple[object, ...]] | None] = {}


def _fields_of(kind: type) -> Callable[[object], tuple[object, ...]] | None:
    """Reads every field of a node at once (one call, not one per field); None for what is no node."""
    if not hasattr(kind, "__dataclass_fields__"):
        return None  # a text of a str subclass, an enumeration member
    names = tuple(kind.__dataclass_fields__)
    if len(names) == 1:
        (name,) = names
        return lambda node: (getattr(node, name),)
    return attrgetter(*names)


def relocate(node: T, offset: int) -> T:
    """A copy of the syntax ``node`` with every span ``offset`` characters further on."""
    kind = type(node)
    if kind is Span:
        return _new(Span, (node.start + offset, node.end + offset))  # type: ignore[attr-defined, return-value]
    if kind is tuple:
        return tuple([item if type(item) in _SPANLESS else relocate(item, offset) for item in node])  # type: ignore[attr-defined, return-value]
    if kind not in _FIELDS:
        _FIELDS[kind] = _fields_of(kind)
    fields = _FIELDS[kind]
    if fields is None:
        return node
    return kind(*[value if type(value) in _SPANLESS else relocate(value, offset) for value in fields(node)])


def walk_statements(statements: tuple[Statement, ...]) -> Iterator[Statement]:
    """Statements in source order, descending into IF .. THEN bodies."""
    for statement in statements:
        yield statement
        if type(statement) is IfThen:
            yield from walk_statements(statement.body)


def flatten_statements(statements: tuple[Statement, ...]) -> tuple[Statement, ...]:
    """``walk_statements`` as a tuple; the statements themselves when no IF .. THEN nests any."""
    for statement in statements:
        if type(statement) is IfThen:
            return tuple(walk_statements(statements))
    return statements


_LEAVES = frozenset({Number, CharConstant, ConstantRef, VariableRef, StringLiteral})


def walk_expression(expression: Expression | StringLiteral | None) -> Iterator[Expression]:
    """An expression and all its subexpressions, outermost first.

    Dispatches on the exact type rather than with ``match``: every check walks
    every expression, and this is several times faster.
    """
    stack = [expression]
    pop, push = stack.pop, stack.append
    while stack:
        node = pop()
        kind = type(node)
        if node is None or kind is StringLiteral:
            continue
        yield node  # type: ignore[misc]
        if kind in _LEAVES:
            continue
        if kind is Binary:
            push(node.right)  # type: ignore[union-attr]
            push(node.left)  # type: ignore[union-attr]
        elif kind is Unary:
            push(node.operand)  # type: ignore[union-attr]
        elif kind is Parenthesised:
            push(node.expression)  # type: ignore[union-attr]
        elif kind is ElementRef:
            push(node.index)  # type: ignore[union-attr]
        elif kind is Call:
            stack.extend(reversed(node.arguments))  # type: ignore[union-attr]
        elif kind is KeywordRef and node.selector is not None:  # type: ignore[union-attr]
            stack.extend(reversed(node.selector.items))  # type: ignore[union-attr]


Evaluated = tuple[Expression | StringLiteral | None, ...]


def _element_index(target: VariableRef | ElementRef) -> Evaluated:
    return (target.index,) if type(target) is ElementRef else ()


def _keyword_statement(statement: KeywordStatement) -> Evaluated:
    selector = statement.keyword.selector
    return (
        *(selector.items if selector is not None else ()),
        statement.terminal,
        *(statement.values or ()),
        *statement.arguments,
        *statement.using,
    )


def _condition(statement: IfThen | IfDo | Until | While | Pause) -> Evaluated:
    return (statement.condition,)


# The expressions of each kind of statement, looked up by exact type: every check asks this
# for every statement, and a dictionary beats a chain of class patterns.
_EVALUATED: dict[type, Callable[..., Evaluated]] = {
    Assignment: lambda s: (*_element_index(s.target), s.value),
    KeywordStatement: _keyword_statement,
    FunctionStatement: lambda s: (*s.call.arguments, *(s.values or ())),
    IfThen: _condition,
    IfDo: _condition,
    Until: _condition,
    While: _condition,
    Pause: _condition,
    For: lambda s: (s.start, s.end, s.step),
    Dim: lambda s: (s.size, *s.values),
    Axes: lambda s: s.selector.items if s.selector is not None else (),
    Print: lambda s: (s.terminal, *(item.value for item in s.items), *s.using),
    Input: lambda s: (s.terminal, *_element_index(s.target), *s.using),
}


def expressions_of(statement: Statement) -> Evaluated:
    """The expressions a statement evaluates, in source order (``None`` for absent parts)."""
    evaluated = _EVALUATED.get(type(statement))
    return evaluated(statement) if evaluated is not None else ()
