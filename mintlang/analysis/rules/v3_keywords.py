"""Mint v3 words in v4 code: old keywords, labels and constants, with their replacements.

The v4 guide keeps an entry for each replaced keyword ("replaced by … in Mint
v4"); v4 reads such a word as an undeclared variable (error 3001, reported by
the declarations rule with what the word became) or, written with an axis
(``HMSPEED.0 = 10``) or alone as a command (``DINT``), as an unknown keyword: error 3007
here, saying what it became and offering the rename when there is exactly one. An old label
(``#FASTPOS``) compiles but is never called: W102.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts, LineScope, Use
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Keyword
from mintlang.records import record
from mintlang.semantic.events import EventKind, event_of
from mintlang.syntax import nodes as n

_V3 = "Mint v3"


# Replacements that read other units: renaming alone would change every value computed from them.
_OTHER_UNITS = {"ADC": "ADC reads percent of the input's range where v3 read counts"}
# Old keywords whose listed replacement does another job: renaming would compile and do something else.
_OTHER_JOB = {
    "PULSE": "v3's PULSE followed the pulse input, STEPPERIO drives pulse outputs: follow an input with "
    "FOLLOW on a MASTERSOURCE (mint-migrate marks it for review)"
}


@record
class Successor:
    """What a Mint v3 word became in v4, for a message, and the word to write instead where renaming is enough."""

    detail: str
    rename: str | None
    whole_keyword: bool  # the old keyword's full name, not an abbreviation that may be a user's variable

    def fixes(self, span: Span) -> tuple[Fix, ...]:
        return (Fix.replace(span, self.rename),) if self.rename else ()


def successor(word: str, controller: ControllerProfile) -> Successor | None:
    """What the v3 keyword or constant ``word`` became in v4 on ``controller`` ("a Mint v3 keyword, ...");
    None for other words."""
    db = database()
    rename = db.rename_of(word)
    if rename is not None:
        whole = rename.old == word.upper()
        if not rename.new:
            return Successor(f"a {_V3} keyword that v4 removed", None, whole)
        detail = f"a {_V3} keyword, replaced by {' or '.join(rename.new)} in v4"
        if len(rename.new) > 1:
            return Successor(detail, None, whole)
        new = rename.new[0]
        replacement = db.keywords.get(new)
        if replacement is not None and not replacement.available_on(controller.controller):
            lacking = f"{detail}, which {controller.title} lacks (mint-migrate knows the alternatives)"
            return Successor(lacking, None, whole)
        if rename.old in _OTHER_JOB:
            return Successor(f"{detail}; {_OTHER_JOB[rename.old]}", None, whole)
        if new in _OTHER_UNITS:
            return Successor(f"{detail}; {_OTHER_UNITS[new]} (mint-migrate converts)", None, whole)
        return Successor(detail, new, whole)
    old = db.lookup_v3(word)
    if old is not None and old.name == word.upper():  # the v4 guide has no entry for it
        if not old.v4_names:
            return Successor(f"a {_V3} keyword with no v4 equivalent", None, True)
        instead = " or ".join(old.v4_names)
        if not any(_on(db.keywords.get(name), controller) for name in old.v4_names):  # BOOSTON on a NextMove PCI
            return Successor(f"a {_V3} keyword; v4 has {instead} instead, which {controller.title} lacks", None, True)
        return Successor(f"a {_V3} keyword; v4 has {instead} instead (mint-migrate converts)", None, True)
    constant = db.v3_constants.get(word.upper())
    if constant is not None and word.startswith("_"):
        if constant.v4_name:
            return Successor(f"a {_V3} constant; v4 uses {constant.v4_name}", constant.v4_name, True)
        return Successor(f"a {_V3} constant with no v4 equivalent", None, True)
    return None


def _on(keyword: Keyword | None, controller: ControllerProfile) -> bool:
    """Whether a v4 keyword is one ``controller`` has (its "Controllers Supported" list)."""
    return keyword is not None and keyword.available_on(controller.controller)


def is_v3_word(word: str) -> bool:
    """Whether ``word``, which v4 reads as a user name, is a Mint v3 keyword, abbreviation or constant."""
    db = database()
    constant = word.startswith("_") and word.upper() in db.v3_constants
    return constant or db.rename_of(word) is not None or db.lookup_v3(word) is not None


def _old_word(word: str, span: Span, scope: LineScope, *, command: bool) -> Finding | None:
    """Error 3007 for a v3 word, with the rename when renaming keeps the statement valid: a v3 command
    whose replacement takes a value (``CONTON``: ``CONTOURMODE = 1``) is left to mint-migrate, and a word
    from a macro's text, reported at the macro's use, is renamed in the macro's text by hand."""
    found = successor(word, scope.controller)
    if found is None:
        return None
    detail = f"'{word}' is not a Mint v4 keyword: it is {found.detail}"
    renamed = scope.writes(span, word) and (not command or _is_command(found.rename, scope.controller))
    fixes = found.fixes(span) if renamed else ()
    return Finding(scope.unit, mint_error(3007, span, detail, fixes=fixes, from_v3=True))


def _is_command(name: str | None, controller: ControllerProfile) -> bool:
    keyword = database().keywords.get(name) if name is not None else None
    attributes = keyword.attributes_for(controller.controller) if keyword is not None else None
    return attributes is not None and attributes.command


def each_line(scope: LineScope) -> Iterator[Finding]:
    if not scope.dialect.modern:
        return
    keywords = database().keywords_of(scope.dialect)
    for use in scope.facts.keyword_uses:
        if use.keyword.keyword in keywords:
            continue
        finding = _old_word(use.keyword.spelling, use.keyword.spelling_span, scope, command=use.use is Use.COMMAND)
        if finding is not None:
            yield finding
    for statement in scope.facts.statements:
        # A v3 command alone (DINT, CONTON, STOPSW): a name v4 does not know, as a statement of its own.
        if isinstance(statement, n.BareName):
            finding = _old_word(statement.name.text, statement.name.span, scope, command=True)
            if finding is not None:
                yield finding


def check(facts: Facts) -> Iterator[Finding]:
    """W102, a v3 fast-latch label: its rename renames the GOSUBs and GOTOs that name it (those written out,
    not brought by a macro), which would otherwise name no label (3004)."""
    model = facts.model
    if not model.program.dialect.modern:
        return
    for unit, labels in model.symbols.labels.items():
        for symbol in labels.values():
            event = event_of(symbol.name, Dialect.V3) if symbol.definitions else None
            if event is None or event.kind is not EventKind.FASTPOS:
                continue
            source = model.document(unit).source
            new = f"FASTIN{event.number if event.number is not None else ''}"
            jumps = [Edit(jump.span, new) for jump in symbol.references if jump.written_in(source)]
            for label in symbol.definitions:
                # unsafe: the handler starts answering fast-latch events
                fix = Fix(f"Rename to #{new}", (Edit(label.span, f"#{new}"), *jumps), safe=False)
                detail = f"#{label.spelling} is {_V3}: v4 uses #{new}"
                yield Finding(unit, own("W102", label.span, detail, fixes=(fix,), from_v3=True))
