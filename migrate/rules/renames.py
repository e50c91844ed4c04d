"""Renames: keywords, event labels, constants and user names whose meaning did not change.

Only words are replaced here, never the statement around them, so every
rename is a one-token edit and the rest of the line is copied as written.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from types import MappingProxyType

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.migrate.context import LABEL, Context, FileView, constant_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.recognise import Evidence, shows_v4, v4_evidence
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.vocabulary import (
    is_assigned_and_read,
    is_migrator_read,
    is_reserved_user_name,
    is_v4_word,
    unique_rename,
)
from mintlang.semantic.events import EventKind, event_of
from mintlang.semantic.symbols import Symbol
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

# v3 name -> (v4 name, the v4 guide's "replaced by" line). Values keep their meaning
# (STOPMODE 1/2: v3:11920-11929 = v4:16489-16504); gains and defaults differ (X-UNITS, S-DEFAULTS).
KEYWORD_RENAMES: Mapping[str, tuple[str, int]] = MappingProxyType(
    {
        "BACKOFF": ("HOMEBACKOFF", 7312),
        "HMSPEED": ("HOMESPEED", 11357),
        "GAIN": ("KPROP", 10945),
        "KINTRANGE": ("KINTLIMIT", 12909),
        "MASTERINC": ("MASTERDISTANCE", 13893),
        "FOLERR": ("FOLERROR", 10584),
        "STOPSW": ("STOPSWITCH", 16544),
        "STOPMODE": ("STOPINPUTMODE", 16539),
        "MFOLERR": ("FOLERRORFATAL", 14002),
    }
)


class RenameKeywords(Rule):
    """A v3 keyword the v4 guide says was "replaced by" another name, with the same values.

    Refused (manual item) when the target controller lacks the new keyword.
    """

    id = "M-REN"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    summary = "BACKOFF HMSPEED GAIN KINTRANGE MASTERINC FOLERR STOPSW STOPMODE MFOLERR -> their v4 names"
    evidence = "spec M-REN; v4:7312, 11357, 10945, 12909, 13893, 10584, 16544, 16539, 14002"
    writes = frozenset(new for new, _ in KEYWORD_RENAMES.values())

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses(*KEYWORD_RENAMES):
            new, line = KEYWORD_RENAMES[use.keyword.keyword]
            if context.supports(new):
                yield self.replace(file, use.keyword.spelling_span, like(use.keyword.spelling, new))
            else:
                yield self.flag(
                    file,
                    use.keyword.span,
                    f"{use.keyword.keyword} became {new} (v4:{line}), which {context.controller.title} does not have",
                )


class RenameFastPos(Rule):
    """``#FASTPOS`` becomes ``#FASTIN``: v3 has one fast latch input, and v4 calls the
    generic #FASTIN for any fast input (defining #FASTIN0 as well would be error 3006).
    A GOSUB or GOTO to it in its file follows it (v3:2461), or it would name no label."""

    id = "M-FASTPOS"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    summary = "#FASTPOS handler -> #FASTIN, with the jumps to it"
    evidence = "spec M-FASTPOS; v4:5910, v4:4955, v4:19108"

    def apply(self, context: Context) -> Iterator[Action]:
        defined: set[Unit] = set()
        for file, line in context.placed(LABEL):
            label = line.syntax.label
            if label is not None and label.identity == "FASTPOS":
                defined.add(file.unit)
                yield self.replace(file, line.span(_label_name_span(label)), like(label.text, "FASTIN"))
        for file, line in context.placed(n.Jump):
            for statement in n.flatten_statements(line.syntax.statements):
                if isinstance(statement, n.Jump) and statement.label.identity == "FASTPOS" and file.unit in defined:
                    yield self.replace(file, line.span(statement.label.span), like(statement.label.text, "FASTIN"))


class RenameConstants(Rule):
    """A v3 constant whose v4 counterpart has the same value (``_servo`` → ``_cfSERVO``,
    ``_neg`` → ``_hmNEGATIVE_SWITCH``).

    Constants whose value changed (MODE, ERROR and TERM constants became bit
    values) are left to the rules that understand their context (S-MODE,
    S-ERROR, S-TERM); the final pass flags any left over.
    """

    id = "M-CONST"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    summary = "v3 constant -> v4 constant of equal value (_servo -> _cfSERVO, _pos -> _hmPOSITIVE_SWITCH ...)"
    evidence = "spec M-CONST, v3-language §2.6; v3:1309-1336; values checked against the v4 constant table"

    def apply(self, context: Context) -> Iterator[Action]:
        renames = same_value_constants(context)
        for file, _, statement in context.statements(*map(constant_tag, renames)):
            for root in n.expressions_of(statement):
                for node in n.walk_expression(root):
                    if isinstance(node, n.ConstantRef) and node.name in renames:
                        written = file.slice(node.span)
                        if written.upper() != renames[node.name].upper():
                            yield self.replace(file, node.span, renames[node.name])


def same_value_constants(context: Context) -> dict[str, str]:
    """Upper-case v3 constant -> v4 name, for the constants whose value is the same in v4."""
    found = {}
    for name, constant in context.db.v3_constants.items():
        v4 = context.db.constants.get((constant.v4_name or "").upper())
        if v4 is not None and v4.value == constant.value:
            found[name] = v4.name
    return found


class RenameEventLabels(Rule):
    """A user label that v4 would call as an event handler (``#TIMER``, ``#CAN1``,
    ``#COMMS3``, ``#FASTIN2`` ...) is renamed, with every GOSUB/GOTO to it.

    v3 calls no ``#FASTIN`` (its latch handler is #FASTPOS, v3:2585-2587), so a v3 ``#FASTIN`` is
    a subroutine too. It runs with the abbreviations, before M-FASTPOS writes its ``#FASTIN``, and
    keeps only the one a migration wrote, in a file with no ``#FASTPOS`` left to rename: one under
    X-FASTLATCH's marker, which every fast-latch handler of the output gets, or in an application
    showing Mint v4 beyond doubt (its markers dealt with and removed), so a second migration leaves
    it. A label jumped to but defined nowhere v3 reads (``a = 1 : #timer``, flagged X-COMMENTED) is
    left as written: its jumps renamed alone would name a label the user never wrote.
    """

    id = "M-LABEL"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.ABBREVIATIONS
    summary = "user label named like a v4 event (#TIMER, #CANn, #COMMSn, #FASTINn) -> renamed with its jumps"
    evidence = "spec M-LABEL; v4:1884-1900"

    def apply(self, context: Context) -> Iterator[Action]:
        if not any(map(_event_named, _label_names(context))):
            return  # the usual case: the symbol table (the semantic model) is not needed
        for labels in context.model.symbols.labels.values():
            taken = set(labels)
            fastpos = "FASTPOS" in labels and bool(labels["FASTPOS"].definitions)
            for symbol in labels.values():
                kept = not fastpos and _migrated_fastin(context, symbol)
                if _event_named(symbol.identity) and symbol.definitions and not kept:
                    yield from _rename_symbol(self, context.files, symbol, taken)


def _label_names(context: Context) -> Iterator[str]:
    """The identity of every label defined or jumped to: the names the symbol table's labels have."""
    for _, line in context.placed(LABEL, n.Jump):
        if line.syntax.label is not None:
            yield line.syntax.label.identity
        for statement in n.flatten_statements(line.syntax.statements):
            if isinstance(statement, n.Jump):
                yield statement.label.identity


def _event_named(label: str) -> bool:
    """Whether a label (by identity) is named like a v4 event handler v3 did not have."""
    return event_of(label, Dialect.V4) is not None and event_of(label, Dialect.V3) is None


def _migrated_fastin(context: Context, symbol: Symbol) -> bool:
    """Whether a label is the generic ``#FASTIN`` a migration wrote: marked by X-FASTLATCH, or in v4 text."""
    event = event_of(symbol.identity, Dialect.V4)
    if event is None or event.kind is not EventKind.FASTIN or event.number is not None:
        return False
    files = context.files
    if all("X-FASTLATCH" in files[place.unit].markers_on(place.span.start) for place in symbol.definitions):
        return True
    texts = {unit: file.text for unit, file in files.items()}
    return v4_evidence(texts, context.controller.controller) is Evidence.BEYOND_DOUBT


class RenameReservedNames(Rule):
    """A user variable or array named like a v4 keyword or abbreviation (``node``, ``view``,
    ``kp``) is renamed everywhere: v4 reserves those words (error 2006).

    The new name keeps the ten significant characters unique. It runs with the abbreviations,
    before any rule has written a v4 keyword, so a v3 ``homespeed`` that is assigned and read is
    the user's variable (v3 had HMSPEED, v4:98). Where the application shows v4 (a second run on
    the migrator's output) or one is only assigned, the names the migrator writes (KPROP,
    HOMESPEED ..., a NODE that is only read) are its keywords (see ``vocabulary``).
    """

    id = "M-IDENT"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.ABBREVIATIONS
    summary = "user variable named like a v4 keyword/abbreviation (node, view, kp ...) -> renamed everywhere"
    evidence = "spec M-IDENT; v4:882-890, v4:18940-18943 (#2006)"

    def apply(self, context: Context) -> Iterator[Action]:
        if not any(map(is_v4_word, context.spellings(context.names(_maybe_reserved)))):
            return  # the usual case: the symbol table (the semantic model) is not needed
        texts = {unit: file.text for unit, file in context.files.items()}
        v4 = shows_v4(texts, context.controller.controller)
        variables = context.model.symbols.variables
        taken = set(variables)
        for symbol in variables.values():
            users = is_reserved_user_name(symbol.name) or (
                not v4 and is_v4_word(symbol.name) and is_assigned_and_read(symbol)
            )
            if users and not is_migrator_read(symbol):
                yield from _rename_symbol(self, context.files, symbol, taken)


def _maybe_reserved(name: str) -> bool:
    """Whether a user name of this identity may be a v4 word: a longer name shares the first ten
    characters of its identity, so those are not known."""
    return len(name) >= n.SIGNIFICANT_CHARACTERS or is_v4_word(name)


def _rename_symbol(rule: Rule, files: Mapping[Unit, FileView], symbol: Symbol, taken: set[str]) -> Iterator[Action]:
    """Every occurrence of ``symbol`` renamed alike: its first characters, then a suffix."""
    keep, suffix = unique_rename(symbol.name, taken)
    taken.add(n.identity(symbol.name[:keep] + suffix))
    for occurrence in symbol.occurrences():
        file = files[occurrence.unit]
        span = occurrence.span
        if file.text.startswith("#", span.start):  # a label definition: keep the #
            span = Span(span.start + 1, span.end)
        yield rule.replace(file, span, file.slice(span)[:keep] + suffix)


def _label_name_span(label: n.Name) -> Span:
    """A label definition's span includes its ``#``; this is the name after it."""
    return Span(label.span.start + 1, label.span.end)
