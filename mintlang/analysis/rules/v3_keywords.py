"""Mint v3 words in v4 code: old keywords, labels and constants, with their replacements.

The v4 guide keeps an entry for each replaced keyword ("replaced by … in Mint
v4"); v4 reads such a word as an undeclared variable or an unknown keyword, so
this rule says what it became and offers the rename when there is exactly one.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic, Edit, Fix, Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.semantic.events import EventKind, event_of

# Replacements that read other units: renaming alone would change every value computed from them.
_OTHER_UNITS = {"ADC": "ADC reads percent of the input's range where v3 read counts"}


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    if model.program.dialect is not Dialect.V4:
        return
    declared = {identity for identity, symbol in model.symbols.variables.items() if symbol.definitions}
    db = database()
    controller = model.controller
    words = [(unit, name.text, name.span) for unit, name in facts.names if name.identity not in declared]
    # An old keyword written with a selector (HMSPEED.0 = 10) reads as an unknown keyword.
    words += [
        (use.unit, use.keyword.spelling, use.keyword.spelling_span)
        for use in facts.keyword_uses
        if use.keyword.keyword not in db.keywords
    ]
    for unit, word, span in words:
        diagnostic = _old_word(word, span, controller)
        if diagnostic is not None:
            yield Finding(unit, diagnostic)
    for unit, document in model.documents():
        for line in document.lines:
            label = line.label
            if label is not None:
                event = event_of(label.text, Dialect.V3)
                if event is not None and event.kind is EventKind.FASTPOS:
                    new = f"#FASTIN{event.number if event.number is not None else ''}"
                    fix = Fix(f"Rename to {new}", (Edit(label.span, new),))
                    yield Finding(
                        unit, own("W102", label.span, f"#{label.text} is Mint v3: v4 uses {new}", fixes=(fix,))
                    )


def _old_word(word: str, span: Span, controller: ControllerProfile) -> Diagnostic | None:
    db = database()
    rename = db.rename_of(word)
    if rename is not None:
        if len(rename.new) == 1:
            new = rename.new[0]
            replacement = db.keywords.get(new)
            if (
                replacement is not None
                and replacement.controllers
                and controller.controller not in replacement.controllers
            ):
                detail = f"{word} is a Mint v3 keyword: v4 replaced it by {new}, which {controller.title} lacks"
                return own("W102", span, detail + " (mint-migrate knows the alternatives)")
            if new in _OTHER_UNITS:
                detail = f"{word} is a Mint v3 keyword: v4 replaced it by {new}; {_OTHER_UNITS[new]}"
                return own("W102", span, detail + " (mint-migrate converts)")
            fix = Fix(f"Replace with {new}", (Edit(span, new),))
            return own("W102", span, f"{word} is a Mint v3 keyword: v4 replaced it by {new}", fixes=(fix,))
        replacement = " or ".join(rename.new) if rename.new else "nothing (it was removed)"
        return own("W102", span, f"{word} is a Mint v3 keyword: v4 replaced it by {replacement}")
    constant = db.v3_constants.get(word.upper())
    if constant is not None and word.startswith("_"):
        if constant.v4_name:
            fix = Fix(f"Replace with {constant.v4_name}", (Edit(span, constant.v4_name),))
            return own("W102", span, f"{word} is a Mint v3 constant: v4 uses {constant.v4_name}", fixes=(fix,))
        return own("W102", span, f"{word} is a Mint v3 constant with no v4 equivalent")
    return None
