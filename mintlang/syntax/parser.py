"""Parsing a whole source: lexing, logical lines, macros, grammar, recovery.

Each logical line is parsed on its own, so a syntax error never stops the rest
of the file from being parsed. Lines are parsed once per text and macro
context, and every line of the same text shares the one syntax object: never
use a syntax object (its ``id()``, or its value) to name a line or a statement.
A statement is named by its place (file, line number, index among the line's
statements: ``mintlang.semantic.blocks.Place``); what is cached per line is
keyed by ``PlacedLine.content``, the one parse of its text in its context; inside a failing line, the statements between
``:`` separators are retried one by one so that only the broken statement is
lost. Parse errors get the controller's error numbers where the manual gives
one: 2003 syntax error, 2004 brackets, 2006 keyword used as a variable, 2007
THEN or DO expected, 2008 TO expected.
"""

from __future__ import annotations

from array import array
from collections.abc import Hashable, Iterable, Mapping, Sequence
from dataclasses import field, replace
from functools import cached_property

from mintlang.allocation import collector_paused, without_collector
from mintlang.analysis.suggestions import closest, keyword_like, not_a_keyword
from mintlang.caching import LINES_KEPT, RecentCache
from mintlang.codes import mint_error
from mintlang.diagnostics import Diagnostic, Edit, Fix, LineIndex, LinesAndEnd
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, KeywordKind
from mintlang.records import record
from mintlang.syntax import nodes as n
from mintlang.syntax.change import Change
from mintlang.syntax.grammar import ParseFailure, parse_kinds
from mintlang.syntax.grammar import clear_cache as clear_parse_cache
from mintlang.syntax.lexer import PhysicalLines, TokenStream, lex
from mintlang.syntax.lexer import clear_cache as clear_lex_cache
from mintlang.syntax.lines import (
    CONTINUED_LIST,
    Expansion,
    LineGroup,
    LogicalLine,
    MacroDefinition,
    continues_a_list,
    expand_macros,
    logical_lines,
    register,
    take_macro_body,
)
from mintlang.syntax.moved import bisect_right
from mintlang.syntax.nodes import identity
from mintlang.syntax.other_languages import other_languages_habit
from mintlang.syntax.packed import PackedLines, PlacedDiagnostics
from mintlang.syntax.spans import span as shared_span
from mintlang.syntax.tokens import GRAMMAR_KEYWORDS, Token, TokenKind
from mintlang.syntax.vocabulary import Vocabulary, vocabulary

_K = TokenKind
_KEYWORD_KINDS = GRAMMAR_KEYWORDS | {_K.KEYWORD, _K.FUNCTION}
_UNREADABLE = "the line cannot be read"
_OPERATORS = frozenset({_K.AND, _K.OR, _K.XOR, _K.NOT, _K.MOD})


@record(slots=False)  # not slotted: ``lines`` is computed on first use
class Document:
    """A parsed source: the lossless token stream and the syntax of its lines.

    ``placed`` holds each logical line's position-free syntax at its place;
    ``lines`` the same lines with spans that are offsets into the source, made
    when a tool first asks for them (the analyser never does). ``macros`` holds
    every macro visible at the end of the file (those of a configuration passed
    in included); ``expansions`` where macros were used.
    """

    source: str
    dialect: Dialect
    tokens: TokenStream  # lossless: the texts join back to the source
    physical: PhysicalLines  # every physical line, lexed, with its offset
    placed: Sequence[n.PlacedLine]  # ``PackedLines``, or ``MovedLines`` after a re-parse
    lexer_issues: tuple[Diagnostic, ...]  # in order
    parse_issues: Sequence[Diagnostic]  # in order: ``PlacedDiagnostics``, or a tuple after a re-parse
    macros: Mapping[str, MacroDefinition]
    definitions: tuple[MacroDefinition, ...]  # the macros this file defines, in order
    expansions: tuple[Expansion, ...]
    line_index: LineIndex
    context: ParseContext
    change: Change | None = None  # how it differs from the document it was re-parsed from (``reparse``)

    @cached_property
    def diagnostics(self) -> tuple[Diagnostic, ...]:
        """What the lexer and the parser found."""
        return (*self.lexer_issues, *self.parse_issues)

    @cached_property
    def lines(self) -> tuple[n.Line, ...]:
        with collector_paused():  # tens of thousands of acyclic nodes
            return tuple(line.absolute() for line in self.placed)

    def physical_between(self, start: int, end: int) -> range:
        """The indices in ``physical`` of the lines that hold offsets ``start`` to ``end``."""
        offsets = self.physical.offsets
        first = max(0, bisect_right(offsets, start) - 1)
        return range(first, max(first, bisect_right(offsets, end)))

    def tokens_in(self, start: int, end: int) -> list[Token]:
        """The lossless tokens of the physical lines that hold offsets ``start`` to ``end``.

        What a request about a few lines needs, without the whole file's stream (``tokens``):
        that is tens of thousands of objects, made again for every version.
        """
        lines = self.physical
        found: list[Token] = []
        for index in self.physical_between(start, end):
            offset, line = lines[index]
            found.extend(line.tokens(offset))
        return found


_MacroBody = tuple[tuple[TokenKind, str], ...]
# A line's key in the parse cache of its dialect and controller: its text, with the bodies of the
# macros it names when any are defined. The text alone in the common case: a tuple per line took
# a twentieth of a check's memory.
_ParseKey = str | tuple[str, tuple[_MacroBody | None, ...]]


class _ParsedLine:
    """What parsing one logical line gives, at offsets relative to its first physical line: its
    syntax, and (``_ParsedLineAndMore``) what parsing found, the macros it defines, and the
    uses of macros it expanded. Most lines have none of those, and their slots took a fortieth
    of a check's memory.

    It is also the line's ``PlacedLine.content``, the key of every per-line cache after the
    parser's: compared by identity, it stands for its text in its context (dialect, controller,
    macros named), for there is one per key in the parse cache. A line parsed again after its
    entry was dropped gets a new one, which the later caches take for a line not seen yet.
    """

    __slots__ = ("syntax",)
    diagnostics: tuple[Diagnostic, ...] = ()
    definitions: tuple[MacroDefinition, ...] = ()
    expansions: tuple[Expansion, ...] = ()

    def __init__(self, syntax: n.LineSyntax) -> None:
        self.syntax = syntax


class _ParsedLineAndMore(_ParsedLine):
    __slots__ = ("definitions", "diagnostics", "expansions")  # in place of the empty tuples of _ParsedLine

    def __init__(
        self,
        syntax: n.LineSyntax,
        diagnostics: tuple[Diagnostic, ...],
        definitions: tuple[MacroDefinition, ...],
        expansions: tuple[Expansion, ...],
    ) -> None:
        super().__init__(syntax)
        self.diagnostics, self.definitions, self.expansions = diagnostics, definitions, expansions


_parsed: dict[tuple[Dialect, Controller | None], RecentCache[_ParseKey, _ParsedLine]] = {}


def _parsed_in(dialect: Dialect, controller: Controller | None) -> RecentCache[_ParseKey, _ParsedLine]:
    """The parsed lines of one dialect and controller, by ``_ParseKey``."""
    cache = _parsed.get((dialect, controller))
    if cache is None:
        cache = _parsed[dialect, controller] = RecentCache(LINES_KEPT, holds_contents=True)
    return cache


def knows(text: str, dialect: Dialect, controller: Controller | None) -> bool:
    """Whether the parse of the logical line ``text`` as ``dialect`` on ``controller`` is cached (``remember``
    would take no other)."""
    return _parsed_in(dialect, controller).get(text) is not None


def remember(line: n.PlacedLine, dialect: Dialect, controller: Controller | None) -> None:
    """Take the syntax of ``line`` for what parsing its text as ``dialect`` on ``controller`` gives,
    unless its own parse found something (diagnostics, macros defined or expanded) or the cache holds
    that text already: for a caller that knows the two read it alike (``mintlang.syntax.alike``)."""
    if type(line.content) is not _ParsedLine:
        return
    cache, text = _parsed_in(dialect, controller), line.syntax.text
    if cache.get(text) is None:
        cache.put(text, _ParsedLine(line.syntax))  # a content of its own: later caches tell the dialects apart


def clear_caches() -> None:
    """Forget lexed and parsed lines (benchmarks measure cold runs with this)."""
    clear_lex_cache()
    clear_parse_cache()
    for cache in _parsed.values():
        cache.clear()


@record
class ParseContext:
    """What a document was parsed with beside its text: a re-parse reuses its lines only under the same."""

    dialect: Dialect
    controller: Controller | None
    macros: tuple[tuple[str, _MacroBody], ...]  # those given (by the configuration), by name

    @classmethod
    def of(
        cls, dialect: Dialect | str, controller: Controller | str | None, macros: Mapping[str, MacroDefinition] | None
    ) -> ParseContext:
        given = tuple(sorted((name, macro.body) for name, macro in (macros or {}).items()))
        return cls(Dialect(dialect), Controller(controller) if controller is not None else None, given)


@record(frozen=False)
class PlacedLines:
    """The logical lines parsed so far, and what parsing them found, at offsets into the file."""

    visible: dict[str, MacroDefinition]  # the macros defined so far
    origins: array[int] = field(default_factory=lambda: array("q"))  # the lines' columns (``PackedLines``)
    numbers: array[int] = field(default_factory=lambda: array("q"))
    syntaxes: list[n.LineSyntax] = field(default_factory=list)
    contents: list[Hashable] = field(default_factory=list)
    found: list[Diagnostic] = field(default_factory=list)  # what parsing found, at its line's offsets
    found_at: array[int] = field(default_factory=lambda: array("q"))  # the offset of each one's line
    definitions: list[MacroDefinition] = field(default_factory=list)
    expansions: list[Expansion] = field(default_factory=list)

    def placed(self) -> PackedLines:
        """The lines parsed so far, at their places."""
        return PackedLines(self.origins, self.numbers, tuple(self.syntaxes), tuple(self.contents))

    def issues(self) -> PlacedDiagnostics:
        """What parsing the lines found so far, at their places."""
        return PlacedDiagnostics(tuple(self.found), self.found_at)

    def parse(self, groups: Iterable[LineGroup], context: ParseContext) -> None:
        """Parse ``groups`` in order, each logical line once per text and macro context."""
        dialect, target, visible = context.dialect, context.controller, self.visible
        words, cache = vocabulary(dialect, target), _parsed_in(dialect, target)
        for group in groups:
            key: _ParseKey = group.text
            if visible:
                bodies = tuple(_body(visible.get(identity(name))) for name in group.names())
                if any(body is not None for body in bodies):  # else it parses as if no macro were defined
                    key = (key, bodies)
            parsed = cache.get(key)
            if parsed is None:
                parsed = _parse_group(group, target, visible, words, dialect)
                cache.put(key, parsed)
            origin = group.origin
            if parsed.definitions:
                defined = [definition.shifted(origin) for definition in parsed.definitions]
                register(visible, defined)
                self.definitions.extend(defined)
            if parsed.expansions:
                self.expansions.extend(expansion.shifted(origin) for expansion in parsed.expansions)
            if parsed.diagnostics:
                self.found.extend(parsed.diagnostics)
                self.found_at.extend([origin] * len(parsed.diagnostics))
            self.origins.append(origin)
            self.numbers.append(group.number)
            self.syntaxes.append(parsed.syntax)
            self.contents.append(parsed)


@without_collector
def parse(
    source: str,
    dialect: Dialect | str = Dialect.V4,
    *,
    macros: Mapping[str, MacroDefinition] | None = None,
    controller: Controller | str | None = None,
) -> Document:
    """Parse ``source``; ``macros`` are those already defined (by the configuration file).

    ``controller`` decides the abbreviations two keywords share (HP: HOMEPOS or
    HANDLERPENDING); without one they resolve as conflicts.json says. A logical
    line is parsed once per text and macro context: an edit re-parses only the
    lines it touched.
    """
    context = ParseContext.of(dialect, controller, macros)
    lexed = lex(source, context.dialect)
    lines = PlacedLines(dict(macros or {}))
    lines.parse(logical_lines(lexed), context)
    return Document(
        source,
        context.dialect,
        lexed.tokens,
        lexed.lines,
        lines.placed(),
        lexed.issues,
        lines.issues(),
        lines.visible,
        tuple(lines.definitions),
        tuple(lines.expansions),
        LineIndex(source, LinesAndEnd(lexed.lines.offsets, source)),
        context,
    )


def _body(macro: MacroDefinition | None) -> _MacroBody | None:
    """What a line's parse depends on of a macro it names: where the macro was defined does not count."""
    return macro.body if macro is not None else None


def _parse_group(
    group: LineGroup,
    controller: Controller | None,
    visible: Mapping[str, MacroDefinition],
    words: Vocabulary,
    dialect: Dialect,
) -> _ParsedLine:
    line = group.tokens()
    defined = take_macro_body(line)
    expansions: list[Expansion] = []
    if visible:
        expand_macros(line, visible, expansions)
    diagnostics: list[Diagnostic] = []
    result = parse_kinds(tuple(line.kinds), dialect)
    if isinstance(result, ParseFailure):
        label, statements = _recover(line, words, dialect, result, diagnostics, controller)
    else:
        label, statements = result(line, words)
    syntax = n.LineSyntax(group.text, line.span, label, statements)
    if diagnostics and len(group.physical) > 1:  # a DIM list over several lines
        diagnostics = [_in_a_continued_list(group.text, diagnostic) for diagnostic in diagnostics]
    if diagnostics or defined or expansions:
        return _ParsedLineAndMore(syntax, tuple(diagnostics), tuple(defined), tuple(expansions))
    return _ParsedLine(syntax)


def _in_a_continued_list(text: str, diagnostic: Diagnostic) -> Diagnostic:
    """A statement that cannot be read at the first word of a DIM list's later line: the comma ending the line
    before took it into the list, which a reader should be told, whatever the word is read as."""
    if not continues_a_list(text, diagnostic.span.start):
        return diagnostic
    return replace(diagnostic, message=f"{diagnostic.message} ({CONTINUED_LIST})")


def _recover(  # noqa: PLR0917 - the line, its reading, and where the findings go
    line: LogicalLine,
    words: Vocabulary,
    dialect: Dialect,
    failure: ParseFailure,
    diagnostics: list[Diagnostic],
    controller: Controller | None,
) -> tuple[n.Name | None, tuple[n.Statement, ...]]:
    """Parse the ``:``-separated statements of a failing line one at a time."""
    kinds = line.kinds
    label: n.Name | None = None
    start = 0
    if kinds and kinds[0] is _K.LABEL:
        label = n.Name(line.texts[0][1:], line.token_span(0))
        start = 1
    statements: list[n.Statement] = []
    if failure.too_complex is not None:  # retrying the parts would not make it simpler
        statements.append(n.SyntaxError_(line.span))
        diagnostics.append(_describe(line, 0, len(kinds), failure, words) or _error(2003, line.span, _UNREADABLE))
        return label, tuple(statements)
    for begin, end in _segments(kinds, start):
        if begin == end:
            continue
        result = parse_kinds(tuple(kinds[begin:end]), dialect)
        if not isinstance(result, ParseFailure):
            statements.extend(result(_slice(line, begin, end), words)[1])
            continue
        span = shared_span(line.starts[begin], line.ends[end - 1])
        broken = kinds[begin:end]
        statements.append(n.SyntaxError_(span, _opened_block(broken), _closing_word(broken)))
        issue = (
            other_languages_habit(line, begin, end, result, dialect)
            or _misspelt_keyword(line, begin, result, words, controller)
            or _describe(line, begin, end, result, words)
        )
        if issue is not None:
            diagnostics.append(issue)
    if not statements and failure.index < len(kinds) and kinds[failure.index] is _K.LABEL:
        issue = _describe(line, 0, len(kinds), failure, words)
        diagnostics.append(issue or _error(2003, line.token_span(0), _UNREADABLE))
    return label, tuple(statements)


def _opened_block(kinds: list[TokenKind]) -> str | None:
    """The block a broken statement still opens, so its closer does not cascade into 2009-2014."""
    first = kinds[0]
    if first in (_K.FOR, _K.WHILE, _K.REPEAT, _K.LOOP):
        return first.value
    if first is _K.IF and _K.DO in kinds:
        return "IF"
    if first is _K.EVENT:
        return "Event"
    return None


_CLOSING_WORDS = frozenset({_K.NEXT, _K.ENDIF, _K.ENDW, _K.ENDL, _K.UNTIL, _K.ENDEVENT, _K.ENDSTARTUP})


def _closing_word(kinds: list[TokenKind]) -> str | None:
    """The closer a broken statement still is (``NEXT a``, ``End While`` for ENDW, ``END IF`` for ENDIF), so its
    block is not reported unclosed as well."""
    two_words = _TWO_WORD_CLOSERS.get(tuple(kinds[:2]))
    if two_words is not None:
        return two_words[0].value
    return kinds[0].value if kinds[0] in _CLOSING_WORDS else None


# Other BASICs' closers in two words, which Mint writes as one (MintMT's End While too: MT-23), with the block
_TWO_WORD_CLOSERS = {
    (_K.END, _K.WHILE): (_K.ENDW, "a WHILE loop"),  # 000:1781
    (_K.END, _K.IF): (_K.ENDIF, "an IF .. DO block"),  # 000:1589-1600
}
_LABEL_AFTER_CODE = [_K.HASH, _K.NAME]  # a label written after a statement on its line
_JUMPS = (_K.GOSUB, _K.GOTO)
# What a value PRINT prints may begin with, a modifier included (PRINT HEX 255, 000:15354-15363)
_VALUE_STARTS = frozenset({
    _K.NAME, _K.KEYWORD, _K.FUNCTION, _K.CONSTANT, _K.NUMBER, _K.CHAR, _K.STRING,
    _K.NOT, _K.TILDE, _K.HEX, _K.DEC, _K.BIN,
})  # fmt: skip
_PRINT_SEPARATORS = (
    "PRINT's values are separated by ',' (the next printed directly after) or ';' (at the next tab stop)"
)


def _segments(kinds: list[TokenKind], start: int) -> list[tuple[int, int]]:
    """Index ranges between top-level ``:`` separators."""
    segments: list[tuple[int, int]] = []
    depth = 0
    begin = start
    for index in range(start, len(kinds)):
        kind = kinds[index]
        if kind in (_K.LPAR, _K.LSQB):
            depth += 1
        elif kind in (_K.RPAR, _K.RSQB):
            depth = max(0, depth - 1)
        elif kind is _K.COLON and depth == 0:
            segments.append((begin, index))
            begin = index + 1
    segments.append((begin, len(kinds)))
    return segments


def _slice(line: LogicalLine, begin: int, end: int) -> LogicalLine:
    return LogicalLine(
        line.number,
        line.starts[begin],
        line.ends[end - 1],
        line.kinds[begin:end],
        line.texts[begin:end],
        line.starts[begin:end],
        line.ends[begin:end],
        line.expanded[begin:end],
    )


_error = mint_error


def _misspelt_keyword(
    line: LogicalLine, begin: int, failure: ParseFailure, words: Vocabulary, controller: Controller | None
) -> Diagnostic | None:
    """A statement that starts with a name the grammar cannot go on from is a misspelt command (``PRNT "a"``,
    ``PAUS IDLE.0``): error 3007 at the name, as the name alone is, with the keyword it resembles. So is, in
    MintMT, a name close to a keyword with a keyword's brackets (``VECTRR(0,1) = 10, 10``, as ``VECTRR[0,1]``
    is in v4), rather than an array with two indices; and a name close to a keyword given a list of values
    (``VECTRR = 100, 200``, ``MFOLEERR = 10, 10`` in v3): a variable takes one value, a keyword one per axis."""
    kinds = line.kinds
    if kinds[begin] is not _K.NAME:
        return None
    command = failure.index == 1 and begin + 1 < len(kinds)
    bracketed = words.dialect is Dialect.MINTMT and kinds[begin + 1 : begin + 2] == [_K.LPAR]
    if not (command or bracketed or _given_a_list(kinds, begin, begin + failure.index)):
        return None
    written = line.texts[begin]
    if begin > 0 and kinds[begin - 1] is _K.LABEL and line.texts[begin - 1][1:].upper() == "REM":
        # #REM Main loop (000:1027): a label named REM, the comment's words read as a statement
        label = line.texts[begin - 1]
        detail = f"{label} is a label named REM, and a statement follows it: a comment is written REM, without '#'"
        return _error(3007, line.token_span(begin), f"'{written}' is not a keyword ({detail})")
    if words.dialect.modern:
        meant = keyword_like(written.upper(), controller, dialect=words.dialect)
    else:  # Mint v3 has keywords of its own
        meant = closest(written.upper(), set(words.canonical.values()))
    span = line.token_span(begin)
    if meant is None and not command:
        return None
    fixes = (Fix.replace(span, meant),) if meant is not None else ()
    return _error(3007, span, not_a_keyword(written, meant), fixes=fixes)


def _given_a_list(kinds: list[TokenKind], begin: int, failed: int) -> bool:
    """Whether the statement from ``begin`` failed at a comma after ``=``, outside brackets: a list of values."""
    if failed >= len(kinds) or kinds[failed] is not _K.COMMA:
        return False
    assigned = kinds[begin:failed]
    balanced = assigned.count(_K.LPAR) == assigned.count(_K.RPAR) and assigned.count(_K.LSQB) == assigned.count(_K.RSQB)
    return _K.EQUAL in assigned and balanced


def _describe(line: LogicalLine, begin: int, end: int, failure: ParseFailure, words: Vocabulary) -> Diagnostic | None:
    """The diagnostic for a statement the grammar rejected, numbered as the controller would."""
    if failure.too_complex is not None:
        span = shared_span(line.starts[begin], line.ends[end - 1])
        return _error(2015, span, f"too complex to analyse: {failure.too_complex}")
    kinds = line.kinds
    index = begin + failure.index
    at_end = index >= end
    span = shared_span(line.ends[end - 1], line.ends[end - 1]) if at_end else line.token_span(index)
    if not at_end and kinds[index] is _K.INVALID:
        return None  # the lexer already reported it
    segment = kinds[begin:end]
    opened = segment.count(_K.LPAR) + segment.count(_K.ADDRESS) - segment.count(_K.RPAR)  # MintMT's POS(0) opens too
    expected = failure.expected
    found = "the end of the statement" if at_end else f"'{line.texts[index]}'"
    if not at_end and kinds[index] is _K.RPAR and index > begin and kinds[index - 1] is _K.LPAR:
        return _empty_brackets(line, begin, index)
    if (at_end or kinds[index] is _K.RPAR) and _innermost_open(kinds, begin, index) is _K.LSQB:
        return _error(2003, span, "a ']' is missing")  # SPEED[0,1 = 4, SPEED[0,1) = 4: not a ')' too many
    # The manual's examples: a missing ")" is a syntax error (2003), one ")" too many is 2004.
    if opened < 0 or (not at_end and kinds[index] is _K.RPAR and opened <= 0):
        return _error(2004, span, "there is a ')' too many")
    if opened > 0:
        return _error(2003, span, "a ')' is missing")
    if index == begin and segment[:2] == _LABEL_AFTER_CODE:  # a = 10 : #label1 (000:1872-1876)
        written = shared_span(line.starts[index], line.ends[index + 1])
        return _error(2003, written, f"#{line.texts[index + 1]} follows code: a label must begin its line")
    if at_end and not words.dialect.modern and segment[0] is _K.NAME and segment[-1] is _K.EQUAL:
        # v3 names this one: "There is an assignment but no expression", avar = (001:12957-12964); a statement
        # that cannot be parsed is refused by the compiler, as a syntax error is
        return _error(2005, span, f"nothing after '=': give {line.texts[begin]} a value", at_run_time=False)
    if segment[0] is _K.IF and not at_end and kinds[index] is _K.ELSE and _K.THEN in kinds[begin:index]:
        return _error(2003, span, "IF .. THEN has no ELSE: write an IF .. DO block with ELSE and ENDIF")  # 000:1586
    split = _split_by_a_macro(line, begin, end)
    if segment[0] is _K.IF and {"THEN", "DO"} <= expected and (at_end or kinds[index] not in _OPERATORS):
        return _error(2007, span, f"found {found}{split}")
    if segment[0] is _K.FOR and "TO" in expected:
        return _error(2008, span, f"found {found}")
    if (two_words := _TWO_WORD_CLOSERS.get(tuple(segment[:2]))) is not None:
        closer, block = two_words[0].value, two_words[1]
        words = shared_span(line.starts[begin], line.ends[begin + 1])
        written = f"{line.texts[begin]} {line.texts[begin + 1]}"
        return _error(2003, words, f"{block} ends with {closer}, not {written}", fixes=(Fix.replace(words, closer),))
    if not at_end and index > begin and kinds[index - 1] in _JUMPS and kinds[index] is _K.HASH and end == index + 2:
        # GOSUB #init: "the hash is not used in the GOSUB statement" (000:1870, 000:5754)
        removal = Fix("Remove the '#'", (Edit(shared_span(line.starts[index], line.starts[index + 1]), ""),), safe=True)
        jump, label = line.texts[index - 1].upper(), line.texts[index + 1]
        return _error(2003, span, f"{jump} names its label without '#': {jump} {label}", fixes=(removal,))
    if not at_end and kinds[index] is _K.COMMA and index - 2 > begin and kinds[index - 2] is _K.HASH:
        # LOCATE #1, 5, 5 as other BASICs write it: Mint puts no ',' after the terminal (LOCATE #3 10,10, 000:13693)
        removal = Fix("Remove the ','", (Edit(shared_span(line.ends[index - 1], line.ends[index]), ""),), safe=True)
        terminal, command = f"#{line.texts[index - 1]}", line.texts[begin].upper()
        return _error(2003, span, f"{command} takes no ',' after its terminal {terminal}", fixes=(removal,))
    if segment[0] is _K.NEXT and index == begin + 1 and kinds[index] is _K.NAME:
        # "NEXT i" as in BASIC: Mint's NEXT takes no loop variable (000:1708-1710; 001:2238)
        removal = Fix(
            "Remove the loop variable", (Edit(shared_span(line.ends[begin], line.ends[index]), ""),), safe=True
        )
        fixes = (removal,) if end == index + 1 else ()  # NEXT i, j closed two loops in BASIC: no single meaning
        return _error(2003, span, "NEXT takes no loop variable: write NEXT alone", fixes=fixes)
    if segment[0] is _K.DIM:  # DIM of a keyword is a syntax error (DIM, 000:9189-9192), whichever kind it lexes as
        named = index if index == begin + 1 and not at_end else index - 1
        if named > begin and kinds[named] in _KEYWORD_KINDS:
            word = words.quoted(line.texts[named])
            return _error(2003, line.token_span(named), f"{word} is a keyword and cannot be declared as a variable")
        if index == begin + 2 and not at_end and kinds[index] is _K.COMMA:  # DIM a, b: one name per DIM
            listed = _dim_list(line, begin, end)
            if listed is not None:
                return listed
        if index == begin + 2 and not at_end and line.texts[index].upper() == "AS":  # every number is one type
            return _error(2003, span, "DIM takes no type: every Mint variable holds a floating point number")
        if index == begin + 2 and not at_end and kinds[index] is _K.LSQB:  # DIM a[10]: DIM a(10) (000:9167)
            return _square_dimension(line, begin, index, end)
    if not at_end and _K.USING in kinds[begin:index]:  # PRINT a USING 4,1, b: USING ends its statement
        command = "PRINT" if line.texts[begin] == "?" else line.texts[begin].upper()
        return _error(2003, span, f"nothing may follow USING and its digit counts: write the rest in another {command}")
    separator_due = "SEMICOLON" in expected and words.dialect.modern
    if segment[0] is _K.PRINT and separator_due and _a_value_begins(line, index, end):
        # PRINT a b: a value begins where a separator or the end was due (000:15299-15302)
        return _error(2003, span, _PRINT_SEPARATORS)
    if segment[0] is _K.IF and not at_end and kinds[index] is _K.DO and kinds[index - 1] is _K.THEN:
        # IF a THEN DO: IF .. THEN runs its line, IF .. DO opens a block (000:1573-1578, 1594-1600)
        detail = "THEN and DO both follow the condition: IF .. DO opens a block closed by ENDIF, "
        return _error(2006, span, detail + "IF .. THEN runs the rest of its line")
    if not at_end and kinds[index] in _KEYWORD_KINDS and "NAME" in expected:
        word = line.texts[index]
        role = "a label" if index > begin and kinds[index - 1] in (_K.GOSUB, _K.GOTO) else "a variable"
        read = index > begin and kinds[index - 1] not in (_K.GOSUB, _K.GOTO, _K.FOR)
        if read and _only_a_command(word):
            return _error(2003, span, f"{word.upper()} is a command and gives no value")  # PRINT AXES, as PRINT GO
        return _error(2006, span, f"{words.quoted(word)} is a reserved keyword and cannot be used as {role}")
    if line.expanded[index if not at_end else end - 1]:
        return _error(2003, span, f"unexpected {_unexpected(found)} in the text of a macro{split}")
    return _error(2003, span, f"unexpected {_unexpected(found)}{split}")


def _split_by_a_macro(line: LogicalLine, begin: int, end: int) -> str:
    """What to add when a ':' that came from a macro's text ends or begins the statement: ``DEFINE fast = 5000 :
    REM mm/s`` keeps the ':' in the macro (a macro may hold several statements, 000:1560; only what follows REM is
    left out, 000:15510-15511), so ``SPEED[0,1] = fast, slow`` is cut after ``5000``."""
    kinds, expanded = line.kinds, line.expanded
    before = begin > 0 and kinds[begin - 1] is _K.COLON and expanded[begin - 1]
    after = end < len(kinds) and kinds[end] is _K.COLON and expanded[end]
    if not (before or after):
        return ""
    return (
        "; a ':' from a macro's text ends the statement before it: a REM after a DEFINE's value goes without"
        " the ':', which stays in the macro"
    )


def _dim_list(line: LogicalLine, begin: int, end: int) -> Diagnostic | None:
    """``DIM a, b, c`` as other BASICs write it: each name has its DIM (000:911-913), and the fix writes them as
    statements of their own on the line, separated by ':' (000:5687), so no line moves."""
    kinds = line.kinds
    names = range(begin + 1, end, 2)
    commas = range(begin + 2, end, 2)
    if (end - begin) % 2 or any(kinds[at] is not _K.NAME for at in names) or any(line.expanded[begin:end]):
        return None
    if any(kinds[at] is not _K.COMMA for at in commas):
        return None
    written = " : ".join(f"DIM {line.texts[at]}" for at in names)
    edits = tuple(Edit(shared_span(line.ends[at - 1], line.starts[at + 1]), " : DIM ") for at in commas)
    fix = Fix("Give each name its own DIM", edits, safe=True)
    return _error(2003, line.token_span(begin + 2), f"one variable per DIM: {written}", fixes=(fix,))


def _square_dimension(line: LogicalLine, begin: int, opening: int, end: int) -> Diagnostic:
    """``DIM a[10]``: an array's elements are given in round brackets, and square ones address axes; the fix
    writes ``DIM a(10)`` when a ``]`` closes the ``[``."""
    name, span = line.texts[begin + 1], line.token_span(opening)
    message = f"an array's size is given in round brackets: DIM {name}(...)"
    closing = next((i for i in range(opening + 1, end) if line.kinds[i] is _K.RSQB), None)
    if closing is None:
        return _error(2003, span, message)
    rounded = (Edit(line.token_span(opening), "("), Edit(line.token_span(closing), ")"))
    return _error(2003, span, message, fixes=(Fix("Use round brackets", rounded, safe=True),))


def _innermost_open(kinds: list[TokenKind], begin: int, end: int) -> TokenKind | None:
    """The innermost bracket still open before ``end`` in the statement from ``begin``: ``(`` or ``[``."""
    open_: list[TokenKind] = []
    for kind in kinds[begin:end]:
        if kind is _K.LPAR or kind is _K.LSQB or kind is _K.ADDRESS:
            open_.append(_K.LPAR if kind is _K.ADDRESS else kind)
        elif (kind is _K.RPAR or kind is _K.RSQB) and open_:
            open_.pop()
    return open_[-1] if open_ else None


def _empty_brackets(line: LogicalLine, begin: int, closing: int) -> Diagnostic:
    """``ABS()``: as many ``)`` as ``(`` (so not 2004, 000:18925-18928), but a value missing between them."""
    span = shared_span(line.starts[closing - 1], line.ends[closing])
    called = closing - 2 >= begin and line.kinds[closing - 2] in (_K.FUNCTION, _K.NAME)  # ABS(), an array's t()
    named = f" of {line.texts[closing - 2]}" if called else ""
    return _error(2003, span, f"nothing between the brackets{named}")


def _a_value_begins(line: LogicalLine, index: int, end: int) -> bool:
    """Whether the token at ``index`` begins a value PRINT could print: not a command such as BEEP, which a
    ':' would have made a statement of its own."""
    if index >= end or line.kinds[index] not in _VALUE_STARTS:
        return False
    if line.kinds[index - 1] is _K.NUMBER and line.ends[index - 1] == line.starts[index]:
        return False  # 2.5e2, 2.5mm: one word the lexer read as a number and a name, no second value
    keyword = database().lookup(line.texts[index]) if line.kinds[index] is _K.KEYWORD else None
    return keyword is None or keyword.kind is not KeywordKind.COMMAND


def _only_a_command(word: str) -> bool:
    """Whether ``word`` is a keyword no controller reads, only commands (AXES, 000:6883-6910)."""
    keyword = database().keywords.get(word.upper())
    rows = keyword.attributes if keyword is not None else ()
    return bool(rows) and all(row.command and not row.read for row in rows)


def _unexpected(found: str) -> str:
    """``found`` after "unexpected": "unexpected end of the statement", not "unexpected the end …"."""
    return found.removeprefix("the ")
