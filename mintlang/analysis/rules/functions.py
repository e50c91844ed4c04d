"""Functions given as many values as their formats take, and written where their formats write them.

The guide prints each function's values in brackets: ``POW(x, y)`` takes two,
``SIN(<angle>)`` one (000:15152, 000:15944), ``COMMS( {node, } element)`` one
or two, braces marking what may be left out (10.1, 000:5578-5579). A call with
more or fewer does not match the statement's syntax, which the compiler rejects
(#2003, 000:18920-18925). A function whose formats only read it (``v =
SIN(<angle>)``) is no statement: alone it is a keyword neither read nor given a
value (#2005, 000:18930-18934), given a value it is read only (#2000,
000:18905-18908); ``COMMS(1) = 5`` and ``CAMTABLE(0, a, NULL)`` are statements as
their formats write them. Everything comes from the keyword database's formats,
so a keyword without a bracketed format is not checked, save one word: CAMTABLE's braced
master increment array is written NULL when there is none (000:7957-7958), so its call
always has three values.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from functools import cache
from types import MappingProxyType

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.records import record
from mintlang.syntax import nodes as n

_OPTIONAL = re.compile(r"\{([^}]*)\}")
# Functions whose braced values an entry says must then be written as a stand-in, and the stand-in.
_STAND_INS: Mapping[str, str] = MappingProxyType({"CAMTABLE": "NULL"})  # 000:7957-7958


@record
class _Arity:
    """How many values a function takes, and the format that says so."""

    least: int
    most: int
    format: str
    stand_in: str | None  # written for a braced value left out, which is then still counted

    def holds(self, count: int) -> bool:
        return self.least <= count <= self.most

    def expected(self) -> str:
        counted = str(self.least) if self.least == self.most else f"{self.least} or {self.most}"
        told = f" ({self.format}; {self.stand_in} for one left out)" if self.stand_in else f" ({self.format})"
        return f"{counted} value{'' if self.most == 1 else 's'}{told}"


@record
class _Statements:
    """The statements a function's formats write it as: alone, or given a value."""

    alone: bool  # CAMTABLE ( axis, position array, ... )
    assigned: bool  # COMMS( {node, } element) = <expression>


def each_line(scope: LineScope) -> Iterator[Finding]:
    for call in scope.facts.calls:
        arity = _arity(call.function, scope.dialect)
        if arity is not None and not arity.holds(len(call.arguments)):
            given = len(call.arguments)
            detail = f"{call.function} takes {arity.expected()}, not {given}"
            yield Finding(scope.unit, mint_error(2003, call.span, detail))
    for statement in scope.facts.statements:
        if type(statement) is n.FunctionStatement:
            yield from _as_statement(scope, statement)


def _as_statement(scope: LineScope, statement: n.FunctionStatement) -> Iterator[Finding]:
    call = statement.call
    forms = _statements(call.function, scope.dialect)
    if forms is None:
        return
    if statement.values is not None and not forms.assigned:
        detail = f"{call.function} is read only and cannot be given a value"
        yield Finding(scope.unit, mint_error(2000, call.spelling_span, detail))
    elif statement.values is None and not forms.alone:
        what = "read or given a value here" if forms.assigned else f"read here, as in 'v = {call.function}(…)'"
        yield Finding(scope.unit, mint_error(2005, call.spelling_span, f"{call.function} must be {what}"))


@cache
def bracketed(name: str, dialect: Dialect) -> tuple[str, str] | None:
    """What ``name``'s first bracketed format writes between its brackets, and that format; None without one."""
    keyword = database().keywords_of(dialect).get(name)
    for text in keyword.formats if keyword is not None else ():
        found = re.search(rf"\b{re.escape(name)}\s*\(([^)]*)\)", text)
        if found is not None:
            return found[1], text.strip()
    return None


@cache
def _arity(name: str, dialect: Dialect) -> _Arity | None:
    """The values ``name``'s first bracketed format takes, or None when no format brackets them."""
    found = bracketed(name, dialect)
    if found is None:
        return None
    inside, text = found
    optional = sum(len(_items(group)) for group in _OPTIONAL.findall(inside))
    required = len(_items(_OPTIONAL.sub("", inside)))
    stand_in = _STAND_INS.get(name)
    least = required + optional if stand_in is not None else required
    return _Arity(least, required + optional, text, stand_in)


@cache
def _statements(name: str, dialect: Dialect) -> _Statements | None:
    """How ``name``'s formats write it as a statement; None when no format brackets its values."""
    keyword = database().keywords_of(dialect).get(name)
    formats = [text.strip() for text in keyword.formats] if keyword is not None else []
    if not any(re.search(rf"\b{re.escape(name)}\s*\(", text) for text in formats):
        return None
    leading = [text for text in formats if re.match(rf"{re.escape(name)}\s*\(", text)]
    assigns = [re.search(r"\)\s*=", text) is not None for text in leading]
    return _Statements(alone=not all(assigns), assigned=any(assigns))


def _items(text: str) -> list[str]:
    return [item for item in (part.strip() for part in text.split(",")) if item]
