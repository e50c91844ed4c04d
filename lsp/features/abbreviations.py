"""Expand abbreviated keywords (``SP`` → ``SPEED``): a rewrite of those at the cursor or in the selection.

Abbreviations save typing at the controller's command line, but a program is
read more often than typed, and ``HP`` means HOMEPOS on one controller and
HANDLERPENDING on another (README). The keyword the checker resolved is written
in full, in upper case. Offered through the code action handler of ``code_actions``, which calls
``actions``.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.lsp.lookup import abbreviated, token_index
from mintlang.lsp.workspace import Snapshot
from mintlang.syntax.tokens import in_a_word

KIND = types.CodeActionKind.RefactorRewrite


def _spaced(source: str, start: int, end: int, name: str) -> str:
    """``name`` with a space on each side a word touches: ``?`` needs none before the word it prints
    (``?FASTPOS.2``, 000:10452), but ``PRINTFASTPOS`` would be one name."""
    before = " " if start > 0 and in_a_word(source[start - 1]) else ""
    after = " " if end < len(source) and in_a_word(source[end]) else ""
    return f"{before}{name}{after}"


def edits(snapshot: Snapshot, span: Span) -> list[types.TextEdit]:
    """One edit per abbreviation that touches ``span``."""
    document, words, positions = snapshot.document, snapshot.settings.words, snapshot.positions
    tokens = document.tokens_in(span.start, span.end)
    found = []
    for token in tokens[max(0, token_index(tokens, span.start)) :]:
        if token.start > span.end:
            break
        name = abbreviated(token, words) if token.end >= span.start else None
        if name is not None:
            new_text = _spaced(document.source, token.start, token.end, name)
            found.append(types.TextEdit(range=positions.range(Span(token.start, token.end)), new_text=new_text))
    return found


def actions(snapshot: Snapshot, selection: types.Range) -> list[types.CodeAction]:
    """ "Expand SP to SPEED" for one abbreviation, "Expand 3 abbreviations" for several."""
    if snapshot.skipped is not None:
        return []
    found = edits(snapshot, snapshot.positions.span(selection))
    if not found:
        return []
    if len(found) == 1:
        old = snapshot.document.source[slice(*snapshot.positions.span(found[0].range))]
        title = f"Expand {old} to {found[0].new_text.strip()}"
    else:
        title = f"Expand {len(found)} abbreviations"
    return [types.CodeAction(title=title, kind=KIND, edit=types.WorkspaceEdit(changes={snapshot.uri: found}))]
