"""From the token stream to logical lines ready for the grammar.

A logical line is one physical line, or several when a DIM initialiser list
ends a line with a comma. This step also gives ``DEFINE`` its raw body and
expands macros at token level: each expanded token keeps the span of the
macro's use, so the parser and every diagnostic point where the user wrote
the macro's name.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, MutableMapping
from operator import itemgetter
from typing import NamedTuple

from mintlang.diagnostics import Span
from mintlang.records import record
from mintlang.syntax.lexer import LexedLine, LexResult, PhysicalLines
from mintlang.syntax.nodes import identity
from mintlang.syntax.spans import span
from mintlang.syntax.tokens import TokenKind

_K = TokenKind
_DEFINE, _NAME = _K.DEFINE, _K.NAME  # module constants: read per line


@record
class MacroDefinition:
    """A macro's name and body as significant tokens (kind, text), each token's start counted from the body's."""

    name: str
    name_span: Span
    body: tuple[tuple[TokenKind, str], ...]
    body_span: Span | None
    body_starts: tuple[int, ...]

    def shifted(self, offset: int) -> MacroDefinition:
        body_span = self.body_span.shifted(offset) if self.body_span is not None else None
        return MacroDefinition(self.name, self.name_span.shifted(offset), self.body, body_span, self.body_starts)

    def token_span(self, index: int) -> Span:
        """Where the body's ``index``-th token is written (the definition has a body)."""
        assert self.body_span is not None, "only a body has tokens"
        start = self.body_span.start + self.body_starts[index]
        return Span(start, start + len(self.body[index][1]))


@record
class Expansion:
    """Where a macro was used; the LSP shows its value there."""

    span: Span
    macro: str  # identity of the macro

    def shifted(self, offset: int) -> Expansion:
        return Expansion(self.span.shifted(offset), self.macro)


PhysicalLine = tuple[int, LexedLine]  # a lexed line and its offset in the source


class LineGroup(NamedTuple):
    """The physical lines of one logical line: one, or several for a DIM list continued after commas.

    A named tuple: there is one per line of every check.
    """

    number: int  # 1-based physical line where it starts
    origin: int  # offset of the first physical line
    text: str  # everything the line's syntax depends on, its indentation included
    physical: tuple[PhysicalLine, ...]

    def names(self) -> Iterator[str]:
        """The user words written on the line: the ones a macro may stand for."""
        for _, line in self.physical:
            if _NAME in line.kinds:
                yield from (text for kind, text in zip(line.kinds, line.texts, strict=True) if kind is _NAME)

    def tokens(self) -> LogicalLine:
        """The significant tokens, at offsets relative to the start of the first physical line."""
        origin = self.origin
        kinds: list[TokenKind] = []
        texts: list[str] = []
        starts: list[int] = []
        ends: list[int] = []
        end = 0
        for offset, line in self.physical:
            shift = offset - origin
            kinds.extend(line.kinds)
            texts.extend(line.texts)
            if shift:  # a DIM list's continuation line
                starts.extend(start + shift for start in line.starts)
                ends.extend(stop + shift for stop in line.ends)
            else:  # the first line, and almost every line: its offsets are the logical line's
                starts.extend(line.starts)
                ends.extend(line.ends)
            end = shift + line.content_end if line.comment_start >= 0 else ends[-1]  # a REM belongs to the line
        return LogicalLine(self.number, starts[0], end, kinds, texts, starts, ends, [False] * len(kinds))


@record(frozen=False)
class LogicalLine:
    """The significant tokens of one logical line, as parallel arrays the grammar reads.

    Offsets are relative to the start of the line's first physical line.
    """

    number: int  # 1-based physical line where it starts
    start: int  # offset of its first character
    end: int  # offset after its last character (a trailing REM included, the line break not)
    kinds: list[TokenKind]
    texts: list[str]
    starts: list[int]
    ends: list[int]
    expanded: list[bool]  # True for tokens that came from a macro body

    @property
    def span(self) -> Span:
        return span(self.start, self.end)

    def token_span(self, index: int) -> Span:
        return span(self.starts[index], self.ends[index])


_STATEMENT_SEPARATORS = frozenset({_K.COLON, _K.LABEL, _K.THEN})


def _is_statement_start(kinds: list[TokenKind], index: int) -> bool:
    return index == 0 or kinds[index - 1] in _STATEMENT_SEPARATORS


def logical_lines(lexed: LexResult) -> Iterator[LineGroup]:
    """Group the physical lines that hold tokens into logical lines (DIM lists continue after a trailing comma).

    Made one at a time as the parser reads them: a list of them all, each with its tuples and
    integers, was a sixth of a check's peak memory on a file of short lines."""
    return map(itemgetter(0), groups_from(lexed.lines, 0))  # in C: a generator over it cost a frame a line


def groups_from(lines: PhysicalLines, start: int) -> Iterator[tuple[LineGroup, int]]:
    """The logical lines from physical line ``start`` (0-based, where no DIM list is open), each with the
    index of the physical line after its last one: where the grouping could stop and start again."""
    pending: list[PhysicalLine] = []  # the lines of a DIM list so far
    texts: list[str] = []  # and their texts, with those of the blank or comment lines between them
    pending_number = 0
    comma = _K.COMMA
    new = tuple.__new__  # builds the named tuple without its Python-level constructor
    offsets = lines.offsets
    for index in range(start, len(lines)):
        line = lines.lexed(index)
        kinds = line.kinds
        if not kinds:
            if pending:
                texts.append(line.text)
            continue
        physical = (offsets[index], line)
        continued = kinds[-1] is comma and (_ends_in_a_dim(kinds) if not pending else _K.COLON not in kinds)
        if not pending and not continued:  # the common case: one physical line
            yield new(LineGroup, (index + 1, physical[0], line.text, (physical,))), index + 1
            continue
        if not pending:
            pending_number = index + 1
        pending.append(physical)
        texts.append(line.text)
        if not continued:
            yield LineGroup(pending_number, pending[0][0], "".join(texts), tuple(pending)), index + 1
            pending, texts = [], []
    if pending:
        yield LineGroup(pending_number, pending[0][0], "".join(texts), tuple(pending)), len(lines)


def _ends_in_a_dim(kinds: list[TokenKind]) -> bool:
    """Whether the line's last statement is a DIM: only its values go on after a trailing comma (000:1093-1095);
    a PRINT's trailing comma (``DIM a : PRINT a,``) keeps the cursor on the line, and the next line is its own."""
    start = len(kinds) - 1
    while not _is_statement_start(kinds, start):
        start -= 1
    return kinds[start] is _K.DIM


CONTINUED_LIST = "the line before ends DIM's values with a comma, so this line is read as more of them"
"""Why a DIM list's later line is read as its values: a trailing comma continues the list (000:1093-1095)."""


def continues_a_list(text: str, start: int) -> bool:
    """Whether ``start``, in the text of a logical line, is the first word of a physical line after its first:
    the line was taken into a DIM list by the comma ending the line before, left there by mistake if no value
    can be read at its first word."""
    before = max(text.rfind("\n", 0, start), text.rfind("\r", 0, start))
    return before >= 0 and not text[before + 1 : start].strip()


def take_macro_body(line: LogicalLine) -> list[MacroDefinition]:
    """Collapse each ``DEFINE name = ...`` body into one MACRO_BODY token; return the definitions."""
    definitions: list[MacroDefinition] = []
    kinds = line.kinds
    if _DEFINE not in kinds:
        return definitions
    for index, kind in enumerate(kinds):
        if kind is not _K.DEFINE or not _is_statement_start(kinds, index):
            continue
        if index + 1 >= len(kinds):
            break
        name_span = line.token_span(index + 1)
        body_start = index + 3
        has_body = index + 2 < len(kinds) and kinds[index + 2] is _K.EQUAL and body_start < len(kinds)
        body = tuple(zip(kinds[body_start:], line.texts[body_start:], strict=True)) if has_body else ()
        body_span = Span(line.starts[body_start], line.ends[-1]) if has_body else None
        body_starts = tuple(start - line.starts[body_start] for start in line.starts[body_start:]) if has_body else ()
        definitions.append(MacroDefinition(line.texts[index + 1], name_span, body, body_span, body_starts))
        if has_body and body_span is not None:
            text = " ".join(line.texts[body_start:])
            del kinds[body_start:], line.texts[body_start:], line.starts[body_start:], line.ends[body_start:]
            del line.expanded[body_start:]
            kinds.append(_K.MACRO_BODY)
            line.texts.append(text)
            line.starts.append(body_span.start)
            line.ends.append(body_span.end)
            line.expanded.append(False)
        break  # the body runs to the end of the line: no second DEFINE on it
    return definitions


def expand_macros(line: LogicalLine, macros: Mapping[str, MacroDefinition], expansions: list[Expansion]) -> None:
    """Replace uses of known macros by their bodies, in place."""
    kinds = line.kinds
    if not macros or _NAME not in kinds:
        return
    index = 0
    while index < len(kinds):
        if kinds[index] is _K.NAME and not _is_definition(kinds, index):
            macro = macros.get(identity(line.texts[index]))
            if macro is not None and macro.body:
                use = line.token_span(index)
                count = len(macro.body)
                kinds[index : index + 1] = [kind for kind, _ in macro.body]
                line.texts[index : index + 1] = [text for _, text in macro.body]
                line.starts[index : index + 1] = [use.start] * count
                line.ends[index : index + 1] = [use.end] * count
                line.expanded[index : index + 1] = [True] * count
                expansions.append(Expansion(use, identity(macro.name)))
                index += count
                continue
        index += 1


def _is_definition(kinds: list[TokenKind], index: int) -> bool:
    """The name after DEFINE is the macro's own, not a use. After GOSUB or GOTO a macro is replaced as anywhere
    else (000:9110-9111): ``DEFINE job = work`` makes ``GOSUB job`` a jump to ``#work``."""
    return index > 0 and kinds[index - 1] is _K.DEFINE


def register(macros: MutableMapping[str, MacroDefinition], definitions: list[MacroDefinition]) -> None:
    """Make definitions visible to later lines; the first definition of a name wins."""
    for definition in definitions:
        macros.setdefault(identity(definition.name), definition)
