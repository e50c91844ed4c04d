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

KIND = types.CodeActionKind.RefactorRewrite


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
            found.append(types.TextEdit(range=positions.range(Span(token.start, token.end)), new_text=name))
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
        title = f"Expand {old} to {found[0].new_text}"
    else:
        title = f"Expand {len(found)} abbreviations"
    return [types.CodeAction(title=title, kind=KIND, edit=types.WorkspaceEdit(changes={snapshot.uri: found}))]
