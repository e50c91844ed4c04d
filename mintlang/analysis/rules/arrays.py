"""Arrays: indices known at compile time must lie in 1 .. size (a fraction cut to
its whole part, as mint-run takes it), and only arrays have elements (error 2016,
"Invalid index", 12.4); an array's size and initial
values are numbers written in its DIM, not expressions (DIM, 000:9167-9171),
because the compiler reserves and fills the array (2003 otherwise). INPUT reads
into a variable, never an array element (the FAQ, 000:18430-18435): a syntax
error, 2003, since its format takes a variable (000:12212). COMMS is an array Mint
defines (000:8287-8293): 99 general elements, and 100 to 255 mapped onto the
controller's parameters (000:2566-2584); an element outside 1 to 255, on this node
or another (``COMMS(5,10)``, 000:2556-2559), is an invalid index too. Most of the
mapped locations can only be read (000:2586-2650): a v4 write to one is run-time error
45 (000:18676-18678); the rest are reserved (000:2610, 2621, 2624, 2664-2667), and
reading or writing one is error 46 (000:18679-18680). ``COMMS(i) = a, b`` writes
``b`` to element i + 1, as a host's list fills consecutive elements (002:115), so
every value of the list is judged at the element it lands on.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang import binary32
from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts, LineScope
from mintlang.comms_map import system_element
from mintlang.dialect import Dialect
from mintlang.semantic.constants import constant_integer, constant_value
from mintlang.semantic.symbols import SymbolKind
from mintlang.syntax import nodes as n
from mintlang.syntax.lines import CONTINUED_LIST, continues_a_list

_NUMBERS = (n.Number, n.CharConstant, n.ConstantRef)
_COMMS_ELEMENTS = range(1, 256)
# The map's printed rows: the I/O table stops at offset 34 (000:2667), so 255 is left to the run
_PRINTED_SYSTEM_ELEMENTS = range(100, 255)
# What the v4 map's elements hold that no keyword names, as a message tells it
_UNNAMED = {
    "EXECUTION_STATUS": "the execution status",
    "BUFFER": "the buffer that runs",
    "LINE": "the line number that runs",
}


def _is_number(expression: n.Expression) -> bool:
    """A number as written: a literal, a character, a predefined constant, or one of them negated."""
    if isinstance(expression, n.Unary) and expression.operator in ("-", "+"):
        expression = expression.operand
    return isinstance(expression, _NUMBERS)


def each_line(scope: LineScope) -> Iterator[Finding]:
    """Sizes and values of DIM written as expressions; INPUT into an element; COMMS elements."""
    yield from _comms_elements(scope)
    yield from _comms_read_only(scope)
    yield from _comms_reserved(scope)
    for statement in scope.facts.statements:
        if isinstance(statement, n.Input) and isinstance(statement.target, n.ElementRef):
            name = statement.target.name.text
            detail = f"INPUT reads into a variable, not an element of {name}: INPUT into a variable, then copy it"
            yield Finding(scope.unit, mint_error(2003, statement.target.span, detail))
        if not isinstance(statement, n.Dim) or statement.size is None:
            continue
        if not _is_number(statement.size):
            detail = f"the size of {statement.name.text} must be a number, not an expression"
            yield Finding(scope.unit, mint_error(2003, statement.size.span, detail))
        else:
            yield from _size_problems(scope, statement)
        for value in statement.values:
            if not _is_number(value):
                detail = f"the values of {statement.name.text} must be numbers, not expressions"
                if continues_a_list(scope.syntax.text, value.span.start):
                    detail += f" ({CONTINUED_LIST})"
                yield Finding(scope.unit, mint_error(2003, value.span, detail))


def _comms_elements(scope: LineScope) -> Iterator[Finding]:
    for element in _comms_accesses(scope):
        if element[1] not in _COMMS_ELEMENTS:
            detail = f"COMMS element {element[1]} does not exist: the Comms array's elements are 1 to 255"
            yield Finding(scope.unit, mint_error(2016, element[0].span, detail))


def _comms_read_only(scope: LineScope) -> Iterator[Finding]:
    """``COMMS(element) = value`` where v4 maps the element onto a parameter it only reads; MintMT keeps
    v4's map (MT-1: its note gives only the 99 general elements, 002:19) and its run raises error 45 too."""
    if scope.dialect is Dialect.V3:
        return
    for element in _comms_writes(scope):
        held = _read_only_parameter(element[1])
        if held is not None:
            detail = f"COMMS element {element[1]} is {held}, which can only be read"
            yield Finding(scope.unit, mint_error(45, element[0].span, detail))


def _comms_reserved(scope: LineScope) -> Iterator[Finding]:
    """``COMMS(element)`` read or written where v4's map reserves the element; MintMT keeps the map (MT-1)."""
    if scope.dialect is Dialect.V3:
        return
    for element in _comms_accesses(scope):
        if element[1] in _PRINTED_SYSTEM_ELEMENTS and system_element(element[1]) is None:
            detail = f"COMMS element {element[1]} is reserved: it holds nothing to read or write"
            yield Finding(scope.unit, mint_error(46, element[0].span, detail))


def _comms_accesses(scope: LineScope) -> Iterator[tuple[n.Expression, int]]:
    """Every known COMMS element the line reads or writes: each call's, then each further value of a list."""
    for call in scope.facts.calls:
        element = _comms_element(call, scope)
        if element is not None:
            yield element
    for statement, element in _comms_assignments(scope):
        yield from _further_writes(statement, element)


def _comms_writes(scope: LineScope) -> Iterator[tuple[n.Expression, int]]:
    """Every known COMMS element the line writes, at its element for the first value and at the value after."""
    for statement, element in _comms_assignments(scope):
        yield element
        yield from _further_writes(statement, element)


def _comms_assignments(scope: LineScope) -> Iterator[tuple[n.FunctionStatement, tuple[n.Expression, int]]]:
    for statement in scope.facts.statements:
        if type(statement) is n.FunctionStatement and statement.values is not None:
            element = _comms_element(statement.call, scope)
            if element is not None:
                yield statement, element


def _further_writes(
    statement: n.FunctionStatement, first: tuple[n.Expression, int]
) -> Iterator[tuple[n.Expression, int]]:
    """The second value of ``COMMS(i) = a, b`` lands on element i + 1, and so on; a skipped place writes nothing."""
    assert statement.values is not None
    for offset, value in enumerate(statement.values[1:], start=1):
        if value is not None:
            yield value, first[1] + offset


def _comms_element(call: n.Call, scope: LineScope) -> tuple[n.Expression, int] | None:
    """The element a COMMS call names (its last value, after a node), where it is a known whole number."""
    if call.function != "COMMS" or not call.arguments:
        return None
    element = call.arguments[-1]
    index = constant_integer(element, scope.dialect)
    return (element, index) if index is not None else None


def _read_only_parameter(element: int) -> str | None:
    """What the read-only COMMS location ``element`` holds; None for one that may be written, or is reserved."""
    held = system_element(element)
    if held is None or held.writable:
        return None
    if held.channel is None:
        return _UNNAMED.get(held.keyword, held.keyword)
    return f"ADC.{held.channel}" if held.keyword == "ADC" else f"{held.keyword} of axis {held.channel}"


def _size_problems(scope: LineScope, statement: n.Dim) -> Iterator[Finding]:
    """A size that is no whole number from 1 (``DIM a(0)``, ``DIM b(2.5)``), and more initial values than
    elements: the compiler cannot make such an array, and a value beyond the size has no index (2016)."""
    assert statement.size is not None
    size = constant_value(statement.size, scope.dialect)
    name = statement.name.text
    if size is not None and (size < 1 or size != int(size)):
        detail = f"the size of {name} must be a whole number from 1, not {size:g}"
        yield Finding(scope.unit, mint_error(2016, statement.size.span, detail))
    elif size is not None and len(statement.values) > size:
        extra = statement.values[int(size)]
        detail = f"{name} has {int(size)} elements: {len(statement.values)} values are too many"
        yield Finding(scope.unit, mint_error(2016, extra.span, detail))


def check(facts: Facts) -> Iterator[Finding]:
    """Elements of what is not an array, or beyond its size."""
    model = facts.model
    dialect = model.program.dialect
    for unit, line, element in facts.elements():
        symbol = model.symbols.variables.get(element.name.identity)
        if symbol is None or not symbol.definitions:
            continue  # undeclared: 3001 says so
        if symbol.kind is not SymbolKind.ARRAY:
            detail = f"'{element.name.text}' is a variable, not an array: declare it with DIM {symbol.name}(size)"
            yield Finding(unit, mint_error(2016, line.span(element.span), detail))
            continue
        if symbol.array_size is None or symbol.array_size < 1:
            continue  # no size, or one its DIM is reported for
        index = constant_value(element.index, dialect)
        if index is None or not binary32.holds(index) or 1 <= int(index) <= symbol.array_size:
            continue
        whole = int(index)  # as mint-run takes a fraction: the guide says nothing of one
        detail = f"{element.name.text}({whole if whole == index else index}) is outside 1 to {symbol.array_size}"
        if whole != index:
            detail += f": a fractional index is cut to its whole part, {whole}"
        yield Finding(unit, mint_error(2016, line.span(element.index.span), detail))
