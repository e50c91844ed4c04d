"""Commands given as many operands as their formats write (error 2003).

LOCATE writes a column and a row (``LOCATE {#<terminal>} <column>,<row>``, 000:13685) and
PROTECT a password (000:15385): ``LOCATE 10`` or ``LOCATE 1, 2, 3`` does not match the
statement's syntax, which the compiler rejects (#2003, 000:18920). Braces mark what may be left
out (``RUN {<buffer>}``, 000:15723). A format's last ``<expression>`` is a list as PRINT takes it
(LINE prints ``2, "A = ", a``, 000:13640-13656), so it sets no upper bound. Everything comes from
the keyword database's formats, so a command without an operand format is not checked.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from functools import cache

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import KeywordKind
from mintlang.records import record
from mintlang.syntax import nodes as n

_TERMINAL = re.compile(r"\{\s*#<[^>]*>\s*\}")
_OPTIONAL = re.compile(r"\{[^{}]*\}")
_OPERAND = re.compile(r"<[^<>]*>")
_OPEN_ENDED = "<expression>"


@record
class _Operands:
    """How many operands a command's format writes after its name, and the format."""

    least: int
    most: int | None  # None: the last operand is a PRINT list
    format: str

    def holds(self, count: int) -> bool:
        return self.least <= count and (self.most is None or count <= self.most)

    def expected(self) -> str:
        if self.most is None:
            return f"at least {self.least} operands"
        counted = str(self.least) if self.least == self.most else f"{self.least} or {self.most}"
        return f"{counted} operand{'' if self.most == 1 else 's'}"


def each_line(scope: LineScope) -> Iterator[Finding]:
    for statement in scope.facts.statements:
        if type(statement) is not n.KeywordStatement or statement.values is not None:
            continue
        operands = _operands(statement.keyword.keyword, scope.dialect)
        given = len(statement.arguments)
        if operands is not None and not operands.holds(given):
            detail = f"{statement.keyword.spelling} takes {operands.expected()} ({operands.format}), not {given}"
            yield Finding(scope.unit, mint_error(2003, statement.span, detail))
        elif operands is not None and statement.semicolons:
            yield from _semicolons(scope, statement, operands)


def _semicolons(scope: LineScope, statement: n.KeywordStatement, operands: _Operands) -> Iterator[Finding]:
    """A ``;`` is PRINT's separator: it may stand only between what a command prints (its open-ended last
    operand, ``LINE 2, "A = "; a``), not between its other operands (``LOCATE 1; 2``, ``LINE 2; a``)."""
    printed_from = operands.least - 1 if operands.most is None else len(statement.arguments)
    for index in statement.semicolons:
        if index < printed_from:
            at = scope.syntax.text.index(";", statement.arguments[index].span.end)
            detail = f"{statement.keyword.spelling} separates its operands with commas ({operands.format})"
            yield Finding(scope.unit, mint_error(2003, Span(at, at + 1), detail))


@cache
def _operands(name: str, dialect: Dialect) -> _Operands | None:
    """The operands of ``name``'s first format that writes it as a command followed by ``<…>`` operands."""
    keyword = database().keywords_of(dialect).get(name)
    if keyword is None or keyword.kind is KeywordKind.COMMAND_LINE:  # error 2006 in a program already
        return None
    for text in keyword.formats:
        layout = text.strip()
        if not layout.upper().startswith(name):
            continue
        rest = _TERMINAL.sub("", layout[len(name) :]).strip()
        if not rest.startswith(("<", "{")):  # "= <expression>", "[axes]", ".channel": no operands
            continue
        required = _OPERAND.findall(_OPTIONAL.sub("", rest))
        optional = sum(len(_OPERAND.findall(group)) for group in _OPTIONAL.findall(rest))
        open_ended = bool(required) and required[-1] == _OPEN_ENDED
        most = None if open_ended else len(required) + optional
        return _Operands(len(required), most, layout)
    return None
