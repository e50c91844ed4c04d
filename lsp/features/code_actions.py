"""Code actions: the core's quick fixes, abbreviations expanded, and the v3 → v4 source actions.

Quick fixes come from the ``fixes`` of the core's diagnostics (declare with
DIM, replace a v3 keyword, plain quotes, dot syntax), and each diagnostic can
be silenced on its line ("Ignore W103 on this line": a ``REM mint: ignore``
comment added or extended). "Fix all" is ``fix_all``'s: the safe fixes, as
``mint check --fix`` makes them. "Replace v3 keywords" and "Migrate this file
to Mint v4" are ``migration``'s, resolved when picked.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from lsprotocol import types

import mintlang
from mintlang.analysis.suppression import UNUSED_SUPPRESSION, suppression_fix
from mintlang.lsp.features import abbreviations, fix_all, migration
from mintlang.lsp.features.diagnostics import to_lsp
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot


def _overlaps(span: mintlang.Span, start: int, end: int) -> bool:
    return span.start <= end and start <= span.end


def _named(code: str, where: types.Range) -> tuple[str, int, int, int, int]:
    """A diagnostic as a client names it back: its code and range (lsprotocol's ranges are unhashable)."""
    return code, where.start.line, where.start.character, where.end.line, where.end.character


def _edits(snapshot: Snapshot, edits: tuple[mintlang.Edit, ...]) -> types.WorkspaceEdit:
    positions = snapshot.positions
    changes = [types.TextEdit(range=positions.range(edit.span), new_text=edit.text) for edit in edits]
    return types.WorkspaceEdit(changes={snapshot.uri: changes})


def quick_fixes(
    snapshot: Snapshot, selection: types.Range, named: Sequence[types.Diagnostic] = ()
) -> Iterator[types.CodeAction]:
    """The fixes of the diagnostics in ``selection``, or ``named`` by the client on its lines, each once: one DIM
    declares a name for all its uses, and one "Ignore" comment silences a code for every diagnostic of it on its
    line. Neovim asks at its cursor and names every diagnostic of the cursor's line, wherever it stands on it."""
    start, end = snapshot.positions.span(selection)
    several_lines = selection.start.line != selection.end.line
    lines = range(selection.start.line, selection.end.line + 1)
    wanted = {_named(str(d.code), d.range) for d in named if d.range.start.line in lines}
    offered: set[tuple[str, tuple[mintlang.Edit, ...]]] = set()
    for diagnostic in snapshot.diagnostics:
        if not _overlaps(diagnostic.span, start, end) and (
            _named(diagnostic.code, snapshot.positions.range(diagnostic.span)) not in wanted
        ):
            continue
        fixes: list[tuple[mintlang.Fix, bool | None]] = [(fix, len(diagnostic.fixes) == 1) for fix in diagnostic.fixes]
        if diagnostic.code != UNUSED_SUPPRESSION:  # its own fix removes the comment
            # Over several lines, "on this line" would not say which: ruff's "Disable for this line" leaves such
            # titles alike, and an editor lists the actions without their lines.
            start_offset, code = diagnostic.span.start, diagnostic.code
            ignoring = suppression_fix(snapshot.document, start_offset, code, name_the_line=several_lines)
            fixes += [(ignoring, None)] if ignoring is not None else []
        for fix, preferred in fixes:
            if (fix.title, fix.edits) in offered:
                continue
            offered.add((fix.title, fix.edits))
            yield types.CodeAction(
                title=fix.title,
                kind=types.CodeActionKind.QuickFix,
                diagnostics=[to_lsp(diagnostic, snapshot)],
                edit=_edits(snapshot, fix.edits),
                is_preferred=preferred,
            )


def _wanted(kind: str, only: list[str] | None) -> bool:
    return only is None or any(kind == wanted or kind.startswith(f"{wanted}.") for wanted in only)


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION,
        types.CodeActionOptions(
            code_action_kinds=[types.CodeActionKind.QuickFix, abbreviations.KIND, fix_all.KIND, *migration.KINDS],
            resolve_provider=True,
        ),
    )
    def actions(params: types.CodeActionParams) -> list[types.CodeAction]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        only = [str(kind) for kind in params.context.only] if params.context.only else None
        found = (
            list(quick_fixes(snapshot, params.range, params.context.diagnostics))
            if _wanted(types.CodeActionKind.QuickFix, only)
            else []
        )
        if _wanted(abbreviations.KIND, only):
            found.extend(abbreviations.actions(snapshot, params.range))
        if only is not None and _wanted(fix_all.KIND, only):  # never for a lightbulb: it checks the text again
            found.extend(fix_all.actions(snapshot))
        found.extend(migration.actions(server, snapshot, [kind for kind in migration.KINDS if _wanted(kind, only)]))
        return found

    @server.feature(types.CODE_ACTION_RESOLVE)
    def resolve(action: types.CodeAction) -> types.CodeAction:
        return migration.resolve(server, action)
