"""Suppression comments: ``REM mint: ignore[W103]`` on a line, ``REM mint: ignore-file[W103]`` in a file.

MintMT's ``'`` opens a comment as ``REM`` does, and carries a directive too (``' mint: ignore[W103]``).

A comment silences the codes it names on its own line (after a statement,
``DIM x : REM mint: ignore[W103]``) or, with ``ignore-file``, anywhere in its
file. It names complete codes, comma-separated, in either spelling of an error
(``E17`` or ``E0017``): a prefix would silence more than its author looked at.
A named code that silenced nothing, or that is no code, is reported as
``UNUSED_SUPPRESSION`` (as ruff's RUF100), with a fix that removes it: safe,
unless the code is one this run does not check. So is a comment that names no code
(``ignore[]``) or whose list no ``]`` closes (``ignore[W103``): it silences nothing, which
its author would not otherwise learn.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from mintlang.codes import code_named, own
from mintlang.diagnostics import Diagnostic, Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.syntax.moved import bisect_left, bisect_right
from mintlang.syntax.tokens import TokenKind

if TYPE_CHECKING:
    from mintlang.syntax.parser import Document

UNUSED_SUPPRESSION = "W117"
# A line's last token whose statement goes on after it: a list's comma, a block's DO (MintMT's block
# ``If .. Then`` is read as DO only while Then ends its line)
_GOES_ON = (TokenKind.COMMA, TokenKind.DO)

# From the REM (MintMT: or the ') that starts the comment: the directive must be the comment's first words.
_DIRECTIVE = re.compile(
    r"(?P<opener>REM\s+|')\s*mint:\s*ignore(?P<file>-file)?\[(?P<codes>[^\]]*)(?P<closed>\])?", re.IGNORECASE
)
_ENTRY = re.compile(r"[^,\s]+")
_MENTION = "mint:"


@record
class Entry:
    """One code as written in a directive: ``code`` is what it names (None: no code)."""

    text: str
    code: str | None
    span: Span


@record
class Directive:
    """One ``REM mint: ignore[...]`` comment: ``line`` is the span of its physical line (line break excluded)."""

    whole_file: bool
    entries: tuple[Entry, ...]
    span: Span  # from REM to the closing bracket (to the end of the line when none closes the list)
    line: Span
    statement_end: int  # where the statements before the comment end (its line's start on a line of its own)
    next_line: int  # where the next physical line starts (the file's end after the last)
    closed: bool = True  # whether a ``]`` ends its list; one that does not names no code
    opener: str = "REM"  # what opens the comment: REM, or MintMT's '

    def names(self, code: str) -> bool:
        return any(entry.code == code for entry in self.entries)

    def shifted(self, offset: int) -> Directive:
        """The same comment ``offset`` characters further on: an edit before it moved it."""
        return Directive(
            self.whole_file,
            tuple(replace(entry, span=entry.span.shifted(offset)) for entry in self.entries),
            self.span.shifted(offset),
            self.line.shifted(offset),
            self.statement_end + offset,
            self.next_line + offset,
            self.closed,
            self.opener,
        )


def directives(document: Document, start: int = 0, end: int | None = None) -> tuple[Directive, ...]:
    """The suppression comments of a file, in order; only those on the physical lines that start
    from offset ``start`` up to ``end``, where given (the lines an edit touched)."""
    found: list[Directive] = []
    offsets = document.physical.offsets
    for index in _mentioning(document.source, offsets, start, len(document.source) if end is None else end):
        offset, lexed = offsets[index], document.physical.lexed(index)
        if lexed.comment_start < 0:
            continue
        match = _DIRECTIVE.match(lexed.text, lexed.comment_start, lexed.content_end)
        if match is None:
            continue
        closed = match["closed"] is not None
        entries = tuple(
            Entry(entry[0], code_named(entry[0]), Span(offset + entry.start(), offset + entry.end()))
            for entry in _ENTRY.finditer(lexed.text, match.start("codes"), match.end("codes"))
            if closed
        )
        before = lexed.text[: lexed.comment_start].rstrip()
        statement_end = offset + len(before.removesuffix(":").rstrip())
        found.append(
            Directive(
                whole_file=match["file"] is not None,
                entries=entries,
                span=Span(offset + match.start(), offset + match.end()),
                line=Span(offset, offset + lexed.content_end),
                statement_end=statement_end,
                next_line=offsets[index + 1] if index + 1 < len(offsets) else len(document.source),
                closed=closed,
                opener=match["opener"].rstrip(),
            )
        )
    return tuple(found)


def _mentioning(source: str, offsets: Sequence[int], start: int, end: int) -> Iterator[int]:
    """The physical lines starting from ``start`` up to ``end`` that mention ``mint:``, found in their
    text at once (at the speed of ``str.find``, not of a loop over lines): the few there are then read
    as the comments they may be."""
    first, last = bisect_left(offsets, start), bisect_left(offsets, end)
    if first == last:
        return
    text_end = offsets[last] if last < len(offsets) else len(source)
    text = source[offsets[first] : text_end].lower()
    base = offsets[first]
    line = -1
    at = text.find(_MENTION)
    while at >= 0:
        found = bisect_right(offsets, base + at) - 1
        if found != line:
            yield found
            line = found
        at = text.find(_MENTION, at + len(_MENTION))


def suppress(
    diagnostics: Sequence[Diagnostic], found: Sequence[Directive], selected: Callable[[str], bool]
) -> Sequence[Diagnostic]:
    """``diagnostics`` without those the suppression comments ``found`` in their file silence, and the
    unused suppressions; the very sequence given when the file has no suppression comment.

    A diagnostic is on the line its span starts on. ``selected`` says whether a code is
    checked at all: a suppression of a code not checked silences nothing and is reported
    so (as ruff reports a ``noqa`` of a rule not enabled).
    """
    if not found:
        return diagnostics
    by_line = [directive for directive in found if not directive.whole_file]
    starts = [directive.line.start for directive in by_line]
    whole_file = [directive for directive in found if directive.whole_file]
    used: set[tuple[Span, str]] = set()  # (the directive's place, a code it silenced)

    def silenced(diagnostic: Diagnostic) -> bool:
        candidates = [directive for directive in whole_file if directive.names(diagnostic.code)]
        place = bisect_right(starts, diagnostic.span.start) - 1
        if place >= 0 and diagnostic.span.start <= by_line[place].line.end and by_line[place].names(diagnostic.code):
            candidates.append(by_line[place])
        used.update((directive.span, diagnostic.code) for directive in candidates)
        return bool(candidates)

    kept = [diagnostic for diagnostic in diagnostics if not silenced(diagnostic)]
    unused = [
        _unused(directive, entry, selected)
        for directive in found
        for entry in directive.entries
        if entry.code != UNUSED_SUPPRESSION and (directive.span, entry.code) not in used
    ]
    unused.extend(_naming_nothing(directive) for directive in found if not directive.entries)
    kept.extend(report for report in unused if selected(UNUSED_SUPPRESSION) and not silenced(report))
    return kept


def _unused(directive: Directive, entry: Entry, selected: Callable[[str], bool]) -> Diagnostic:
    where = "in this file" if directive.whole_file else "on this line"
    if entry.code is None:
        detail = f"unused suppression: '{entry.text}' is no code"
    elif not selected(entry.code):
        detail = f"unused suppression: {entry.code} is not checked"
    else:
        detail = f"unused suppression: no {entry.code} {where}"
    # A code this run does not check may be one a wider selection checks (the editor's, --select I): its
    # removal is left to the author.
    safe = entry.code is None or selected(entry.code)
    return own(UNUSED_SUPPRESSION, entry.span, detail, fixes=(_removal(directive, entry, safe=safe),))


def _naming_nothing(directive: Directive) -> Diagnostic:
    """A comment that silences nothing because it names nothing: an empty list goes (safe: it could not
    silence anything), one left open is the author's to close."""
    if not directive.closed:
        detail = "unused suppression: no ']' closes its list of codes, so it names none"
        return own(UNUSED_SUPPRESSION, directive.span, detail)
    removal = Fix("Remove the suppression comment", (_without_comment(directive),), safe=True)
    return own(UNUSED_SUPPRESSION, directive.span, "unused suppression: it names no code", fixes=(removal,))


def _removal(directive: Directive, entry: Entry, *, safe: bool) -> Fix:
    """Take the entry out of its list, or the whole comment when it is the only entry."""
    entries = directive.entries
    if len(entries) == 1:
        return Fix("Remove the suppression comment", (_without_comment(directive),), safe=safe)
    index = entries.index(entry)
    if index + 1 < len(entries):
        span = Span(entry.span.start, entries[index + 1].span.start)  # the entry, its comma and the space after
    else:
        span = Span(entries[index - 1].span.end, entry.span.end)  # the comma before the last entry
    return Fix(f"Remove {entry.text} from the suppression", (Edit(span, ""),), safe=safe)


def _without_comment(directive: Directive) -> Edit:
    """The directive's removal: with the ``:`` and space before it after a statement, with its whole line
    (line break included) when it is alone there; any text after it stays."""
    rest_of_line = directive.span.end < directive.line.end
    if rest_of_line:
        return Edit(directive.span, directive.opener)  # REM mint: ignore[W103] because ... -> REM because ...
    if directive.statement_end == directive.line.start:
        return Edit(Span(directive.line.start, directive.next_line), "")
    return Edit(Span(directive.statement_end, directive.span.end), "")


def suppression_fix(document: Document, offset: int, code: str, *, name_the_line: bool = False) -> Fix | None:
    """Silence ``code`` on the line holding ``offset``: the line's directive extended, or one added; None where
    no comment can go (v3's ``PROTECT abc``, whose password is the rest of its line, 001:11089-11092).

    A comment already on the line keeps its words after the directive; a line with
    statements gets ``: REM mint: ignore[...]`` after them, as the manual writes comments.
    ``name_the_line``: the title says which line ("on line 12"), for a list of fixes from several lines.
    """
    index = document.physical_between(offset, offset)[0]
    title = f"Ignore {code} on {f'line {index + 1}' if name_the_line else 'this line'}"
    line_offset, lexed = document.physical[index]
    if document.dialect is Dialect.V3 and lexed.text.startswith("PROTECT") and lexed.kinds[1:] == (TokenKind.NAME,):
        return None
    for directive in directives(document):
        if not directive.whole_file and directive.closed and directive.line.start == line_offset:
            end = directive.entries[-1].span.end if directive.entries else directive.span.end - 1
            separator = ", " if directive.entries else ""
            return Fix(title, (Edit(Span(end, end), f"{separator}{code}"),), safe=True)
    comment = f"REM mint: ignore[{code}]"
    if lexed.comment_start >= 0:  # the directive becomes the comment's first words, after its REM or '
        start = line_offset + lexed.comment_start
        opener = "'" if lexed.text.startswith("'", lexed.comment_start) else "REM"
        return Fix(title, (Edit(Span(start, start + len(opener)), f"{opener} mint: ignore[{code}]"),), safe=True)
    content = lexed.text[: lexed.content_end].rstrip()
    end = line_offset + len(content)
    if not content.strip():
        return Fix(title, (Edit(Span(end, end), comment),), safe=True)
    # After a trailing comma (a DIM list going on to the next line, guide 3.3) a colon would end the
    # statement there, and after MintMT's block ``If .. Then`` give it an empty one, making the If one line
    # long; a REM needs no colon after code (REM in the keyword reference).
    separator = " " if lexed.kinds and lexed.kinds[-1] in _GOES_ON else " : "
    return Fix(title, (Edit(Span(end, end), f"{separator}{comment}"),), safe=True)
