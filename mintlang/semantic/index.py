"""One walk over the syntax of an application, in compile order.

The symbol table, the analyser's rules and the tools all need the same lists:
every statement, every keyword and how it is used, every array element and
every user name with what happens to it. Walking the trees once and keeping
the lists is what keeps a check fast enough for every keystroke.

The analyser reads them per line (``line_facts``), at the line's relative
offsets, so a line the parser gave back unchanged after an edit is not walked
again; the tools read them for the whole application with offsets into the
files (``index_syntax``).
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Iterator, Sequence
from enum import StrEnum
from functools import partial
from itertools import chain, compress, count, repeat
from operator import attrgetter, not_
from typing import NamedTuple, overload

from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.keyworddb.model import Use
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.change import Change
from mintlang.syntax.moved import Spliced
from mintlang.syntax.parser import Document


class KeywordUse(NamedTuple):
    """A keyword and how a statement uses it (a named tuple: there is one per keyword written)."""

    unit: Unit
    statement: n.Statement
    keyword: n.KeywordRef
    use: Use


class NameUse(StrEnum):
    """What a statement does with a user name."""

    READ = "read"
    WRITE = "write"  # assigned, a FOR variable, an INPUT target
    DECLARE = "declare"  # DIM
    BARE = "bare"  # a word alone as a statement: an unknown keyword, not a variable


class NameEvent(NamedTuple):
    """What a statement does with a user name (a named tuple: there is one per name written)."""

    unit: Unit
    name: n.Name
    use: NameUse
    element: bool  # written with an index: name(i)
    size: n.Expression | None = None  # the array size of a DIM


@record
class SyntaxIndex:
    statements: tuple[tuple[Unit, n.Line, n.Statement], ...]  # IF .. THEN bodies included
    keyword_uses: tuple[KeywordUse, ...]
    elements: tuple[tuple[Unit, n.ElementRef], ...]  # array elements read or written
    names: tuple[NameEvent, ...]  # in compile order: a DIM after its values, a write after its value


_new = tuple.__new__  # builds a named tuple without its Python-level constructor
_READ, _READ_KEYWORD = NameUse.READ, Use.READ  # module constants: read per name and keyword written
_CONSTANTS = frozenset({n.Number, n.CharConstant, n.ConstantRef, n.StringLiteral, type(None)})
_ARITHMETIC = frozenset({"+", "-", "*", "/", "MOD"})  # the parser reads % as MOD
# Commands whose operand is a word of their own, neither a variable nor a keyword: PROTECT <password>
# (000:5288) and VIEW <type>, VIEW VAR or VIEW CANBUSSTATE.2 (000:17184-17305).
_WORD_OPERANDS = frozenset({"PROTECT", "VIEW"})


class LineFacts(NamedTuple):
    """The index of one line: its statements (IF .. THEN bodies included), keywords, elements and names.

    A named tuple made by ``tuple.__new__``: there is one per distinct line of every check, and a
    record's constructor, setting each slot in Python, was a tenth of the time it takes to index one.
    """

    statements: tuple[n.Statement, ...]
    keyword_uses: tuple[KeywordUse, ...]
    elements: tuple[n.ElementRef, ...]
    names: tuple[NameEvent, ...]
    kinds: frozenset[type]  # the types of its statements: passes that look for a few skip the other lines
    calls: tuple[n.Call, ...]  # as statements (``CAMTABLE(0, a, NULL)``) and in expressions, in source order
    arithmetic: tuple[n.Binary, ...]  # every ``+ - * /`` and ``MOD`` it works out, each statement's outermost first


class _Walker:
    def __init__(self) -> None:
        self.uses: list[KeywordUse] = []
        self.elements: list[tuple[Unit, n.ElementRef]] = []
        self.names: list[NameEvent] = []
        self.calls: list[n.Call] = []
        self.arithmetic: list[n.Binary] = []

    def statement(self, unit: Unit, statement: n.Statement) -> None:
        kind = type(statement)  # exact-type dispatch: this runs for every statement of every check
        if kind is n.KeywordStatement:
            keyword = statement.keyword  # type: ignore[union-attr]
            use = Use.WRITE if statement.values is not None else Use.COMMAND  # type: ignore[union-attr]
            self.uses.append(KeywordUse(unit, statement, keyword, use))
            if keyword.keyword not in _WORD_OPERANDS or use is Use.WRITE:
                self.expressions(unit, statement)
            else:  # though its calls and operations are still indexed
                self._calls_and_operations(statement)
        elif kind is n.Dim:
            self.expressions(unit, statement)
            size = statement.size  # type: ignore[union-attr]
            self.names.append(NameEvent(unit, statement.name, NameUse.DECLARE, size is not None, size))  # type: ignore[union-attr]
        elif kind is n.Assignment or kind is n.Input:
            self.expressions(unit, statement)
            target = statement.target  # type: ignore[union-attr]
            element = type(target) is n.ElementRef
            if element:
                self.elements.append((unit, target))
            self.names.append(NameEvent(unit, target.name, NameUse.WRITE, element))
        elif kind is n.For:
            self.names.append(NameEvent(unit, statement.variable, NameUse.WRITE, False))  # type: ignore[union-attr]
            self.expressions(unit, statement)
        elif kind is n.BareName:
            self.names.append(NameEvent(unit, statement.name, NameUse.BARE, False))  # type: ignore[union-attr]
        elif kind is not n.BlockWord:
            if kind is n.FunctionStatement:
                self.calls.append(statement.call)  # type: ignore[union-attr]
            self.expressions(unit, statement)

    def _calls_and_operations(self, statement: n.Statement) -> None:
        for expression in n.expressions_of(statement):
            for node in n.walk_expression(expression):
                kind = type(node)
                if kind is n.Call:
                    self.calls.append(node)  # type: ignore[arg-type]
                elif kind is n.Binary and node.operator in _ARITHMETIC:  # type: ignore[union-attr]
                    self.arithmetic.append(node)  # type: ignore[arg-type]

    def expressions(self, unit: Unit, statement: n.Statement) -> None:
        names, uses, elements, calls, arithmetic = self.names, self.uses, self.elements, self.calls, self.arithmetic
        for expression in n.expressions_of(statement):
            if type(expression) in _CONSTANTS:
                continue  # most values are plain numbers: no walk needed
            for node in n.walk_expression(expression):
                kind = type(node)
                if kind is n.VariableRef:
                    names.append(_new(NameEvent, (unit, node.name, _READ, False, None)))  # type: ignore[union-attr]
                elif kind is n.KeywordRef:
                    uses.append(_new(KeywordUse, (unit, statement, node, _READ_KEYWORD)))
                elif kind is n.ElementRef:
                    elements.append((unit, node))  # type: ignore[arg-type]
                    names.append(_new(NameEvent, (unit, node.name, _READ, True, None)))  # type: ignore[union-attr]
                elif kind is n.Call:
                    calls.append(node)  # type: ignore[arg-type]
                elif kind is n.Binary and node.operator in _ARITHMETIC:  # type: ignore[union-attr]
                    arithmetic.append(node)  # type: ignore[arg-type]


def index_syntax(documents: Iterable[tuple[Unit, Document]]) -> SyntaxIndex:
    """Walk the documents (configuration first) once."""
    walker = _Walker()
    statements: list[tuple[Unit, n.Line, n.Statement]] = []
    for unit, document in documents:
        for line in document.lines:
            for statement in n.flatten_statements(line.statements):
                statements.append((unit, line, statement))
                walker.statement(unit, statement)
    return SyntaxIndex(tuple(statements), tuple(walker.uses), tuple(walker.elements), tuple(walker.names))


# Per unit, by what the line was parsed from: the facts hold no place, so equal lines share them.
_facts: dict[Unit, RecentCache[Hashable, LineFacts]] = {unit: RecentCache(LINES_KEPT) for unit in Unit}


# One frozenset per combination of statement types (a few dozen occur), not one per line: 200 bytes a line.
_kind_sets: dict[frozenset[type], frozenset[type]] = {}


def clear_cache() -> None:
    for facts in _facts.values():
        facts.clear()


IndexedLine = tuple[Unit, n.PlacedLine, LineFacts]
_KINDS = attrgetter("kinds")


class IndexedLines(Sequence[IndexedLine]):
    """Every logical line of the files of an application with its index, in compile order.

    Kept as each file's lines beside a tuple of their facts, and paired when read: a
    tuple of three per line was a twentieth of a check's memory.
    """

    __slots__ = ("_files", "_length")

    def __init__(self, files: Iterable[tuple[Unit, Sequence[n.PlacedLine]]]) -> None:
        self._files = tuple((unit, lines, tuple(line_facts(unit, line) for line in lines)) for unit, lines in files)
        self._length = sum(len(lines) for _, lines, _ in self._files)

    def edited(self, files: Iterable[tuple[Unit, Sequence[n.PlacedLine]]], change: Change) -> IndexedLines:
        """The index of ``files``, the same files after an edit to the program (``change``): a
        keystroke looks up the index of the lines it re-read, not of every line of the file."""
        first = change.first_line
        old_end, new_end = first + change.old_lines, first + change.new_lines
        edited_files = []
        for (unit, lines), (_, _, facts) in zip(files, self._files, strict=True):
            if unit is not Unit.PROGRAM:
                edited_files.append((unit, lines, facts))
                continue
            window = [line_facts(unit, line) for line in lines[first:new_end]]
            edited_files.append((unit, lines, Spliced.spliced(facts, (first, old_end), window, 0, 0)))
        edited = object.__new__(IndexedLines)
        edited._files = tuple(edited_files)
        edited._length = sum(len(facts) for _, _, facts in edited._files)
        return edited

    def __len__(self) -> int:
        return self._length

    def __iter__(self) -> Iterator[IndexedLine]:
        return chain.from_iterable(zip(repeat(unit), lines, facts) for unit, lines, facts in self._files)

    def facts(self) -> Iterator[LineFacts]:
        """Each line's index alone, in compile order: a pass that reads no line needs none made."""
        return chain.from_iterable(facts for _, _, facts in self._files)

    def where(self, wanted: Callable[[LineFacts], object]) -> Iterator[IndexedLine]:
        """The lines whose index ``wanted`` holds true of, in compile order, each line made only for them.

        A file's lines are made as they are read (``PackedLines``); most passes look for what few
        lines have, so they test the indexes first. ``wanted`` is best a C callable (an
        ``attrgetter``): it is called for every line.
        """
        return self._selected(lambda facts: map(wanted, facts))

    def with_kinds(self, kinds: frozenset[type]) -> Iterator[IndexedLine]:
        """The lines with a statement of one of ``kinds`` (IF .. THEN bodies included)."""
        return self._selected(partial(_having, kinds))

    def _selected(self, selectors: Callable[[Sequence[LineFacts]], Iterable[object]]) -> Iterator[IndexedLine]:
        """The lines whose selector, one per index of a file's lines, is true."""
        for unit, lines, facts in self._files:
            for index in compress(count(), selectors(facts)):
                yield unit, lines[index], facts[index]

    def places_with_kinds(self, unit: Unit, kinds: frozenset[type]) -> Iterator[int]:
        """Where in ``unit``'s lines those with a statement of one of ``kinds`` are, as indices."""
        facts = next((facts for file, _, facts in self._files if file is unit), ())
        return compress(count(), _having(kinds, facts))

    def of(self, unit: Unit) -> Iterator[tuple[n.PlacedLine, LineFacts]]:
        """The lines of one file with their indexes."""
        files = self._files
        return chain.from_iterable(zip(lines, facts, strict=True) for file, lines, facts in files if file is unit)

    @overload
    def __getitem__(self, index: int) -> IndexedLine: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[IndexedLine]: ...
    def __getitem__(self, index: int | slice) -> IndexedLine | Sequence[IndexedLine]:
        return tuple(self)[index]  # whole-file passes iterate; a place is read rarely


def _having(kinds: frozenset[type], facts: Iterable[LineFacts]) -> Iterator[bool]:
    """For each line's index, whether the line has a statement of one of ``kinds``: in C, for every line."""
    return map(not_, map(kinds.isdisjoint, map(_KINDS, facts)))


def line_facts(unit: Unit, line: n.PlacedLine) -> LineFacts:
    """The index of one line of ``unit``, walked once per line text (the parser shares unchanged ones)."""
    cache = _facts[unit]
    cached = cache.get(line.content)
    if cached is not None:
        return cached
    walker = _Walker()
    statements = n.flatten_statements(line.syntax.statements)
    for statement in statements:
        walker.statement(unit, statement)
    elements = tuple(element for _, element in walker.elements)
    kinds = frozenset(map(type, statements))
    kinds = _kind_sets.setdefault(kinds, kinds)
    uses, names, calls = tuple(walker.uses), tuple(walker.names), tuple(walker.calls)
    facts = _new(LineFacts, (statements, uses, elements, names, kinds, calls, tuple(walker.arithmetic)))
    cache.put(line.content, facts)
    return facts
