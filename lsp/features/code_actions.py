"""Code actions: the core's quick fixes, and "Migrate this file to Mint v4".

Quick fixes come from the ``fixes`` of the core's diagnostics (declare with
DIM, replace a v3 keyword, plain quotes, dot syntax). The migration is a
source action resolved lazily: ``mintlang.migrate`` runs only when the user
picks it, and its minimal edits leave unchanged lines alone.
"""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

import mintlang
from mintlang.dialect import Dialect
from mintlang.lsp.features import abbreviations
from mintlang.lsp.features.diagnostics import to_lsp
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.units import Unit

MIGRATE_KIND = f"{types.CodeActionKind.Source.value}.migrateToV4"
MIGRATE_TITLE = "Migrate this file to Mint v4"


def _overlaps(span: mintlang.Span, start: int, end: int) -> bool:
    return span.start <= end and start <= span.end


def _edits(snapshot: Snapshot, edits: tuple[mintlang.Edit, ...]) -> types.WorkspaceEdit:
    positions = snapshot.positions
    changes = [types.TextEdit(range=positions.range(edit.span), new_text=edit.text) for edit in edits]
    return types.WorkspaceEdit(changes={snapshot.uri: changes})


def quick_fixes(snapshot: Snapshot, selection: types.Range) -> Iterator[types.CodeAction]:
    start, end = snapshot.positions.span(selection)
    for diagnostic in snapshot.diagnostics:
        if not _overlaps(diagnostic.span, start, end):
            continue
        for fix in diagnostic.fixes:
            yield types.CodeAction(
                title=fix.title,
                kind=types.CodeActionKind.QuickFix,
                diagnostics=[to_lsp(diagnostic, snapshot)],
                edit=_edits(snapshot, fix.edits),
                is_preferred=len(diagnostic.fixes) == 1,
            )


def _wants_migration(snapshot: Snapshot) -> bool:
    if snapshot.unit is not Unit.PROGRAM or snapshot.skipped is not None:
        return False
    return snapshot.settings.dialect is Dialect.V3 or any(d.from_v3 for d in snapshot.diagnostics)


def _wanted(kind: str, only: list[str] | None) -> bool:
    return only is None or any(kind == wanted or kind.startswith(f"{wanted}.") for wanted in only)


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION,
        types.CodeActionOptions(
            code_action_kinds=[types.CodeActionKind.QuickFix, abbreviations.KIND, MIGRATE_KIND], resolve_provider=True
        ),
    )
    def actions(params: types.CodeActionParams) -> list[types.CodeAction]:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return []
        only = [str(kind) for kind in params.context.only] if params.context.only else None
        found = list(quick_fixes(snapshot, params.range)) if _wanted(types.CodeActionKind.QuickFix, only) else []
        if _wanted(abbreviations.KIND, only):
            found.extend(abbreviations.actions(snapshot, params.range))
        if _wanted(MIGRATE_KIND, only) and _wants_migration(snapshot):
            data = {"uri": snapshot.uri, "version": snapshot.version}
            found.append(types.CodeAction(title=MIGRATE_TITLE, kind=MIGRATE_KIND, data=data))
        return found

    @server.feature(types.CODE_ACTION_RESOLVE)
    def resolve(action: types.CodeAction) -> types.CodeAction:
        data = action.data if isinstance(action.data, dict) else {}
        snapshot = server.snapshot(str(data.get("uri", "")))
        if action.title != MIGRATE_TITLE or snapshot is None or snapshot.version != data.get("version"):
            return action
        from mintlang.migrate import migrate  # noqa: PLC0415  (loaded only when the user asks)

        configuration = snapshot.files.get(Unit.CONFIGURATION)
        config = server.read_text(configuration.uri) if configuration is not None else None
        result = migrate(snapshot.document.source, config=config, controller=snapshot.settings.controller)
        action.edit = _edits(snapshot, result.edits())
        return action
