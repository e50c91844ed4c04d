"""Mint v3 words in a file: "Replace v3 keywords" anywhere, "Migrate this file to Mint v4" only in a v3 file.

The whole migration declares every variable it finds, renames names that v4
took as keywords (``ERL`` → ``ERL_u``) and adds ``AXES`` and prologue notes:
right for a v3 file, damage in a v4 one whose only v3 word is an ``HMSPEED``.
So a file is taken as v3 when the dialect setting says so, or when it has v3
words and no form only v4 has (a scalar ``DIM``, a v4-only keyword: the
migrator's own recogniser); elsewhere only the renames are offered, each one
kept only if the v4 checker finds no new error once it is made. The migration
is a workspace edit of the program and its configuration file under a change
annotation that needs confirmation, so a client that supports them previews
it before anything changes. Both actions are computed when picked (resolved).
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable, Mapping
from functools import lru_cache

from lsprotocol import types
from pygls.exceptions import JsonRpcException

import mintlang
from mintlang.dialect import Dialect
from mintlang.lsp import confirmation
from mintlang.lsp.positions import Positions
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.units import Unit

MIGRATE_KIND = f"{types.CodeActionKind.Source.value}.migrateToV4"
MIGRATE_TITLE = "Migrate this file to Mint v4"
REPLACE_KIND = f"{types.CodeActionKind.Source.value}.replaceV3Keywords"
REPLACE_TITLE = "Replace v3 keywords"
KINDS = (REPLACE_KIND, MIGRATE_KIND)
_MIGRATION = "mint.migrateToV4"  # the change annotation of the whole migration
_WORD = re.compile(r"#?\w+")


class MigrationRefused(JsonRpcException):
    CODE = -32803  # LSP RequestFailed: the migrator met a statement it cannot handle


Texts = Mapping[Unit, str]


def _texts(server: MintServer, snapshot: Snapshot) -> dict[Unit, tuple[str, str]]:
    """The URI and current text of each file of the application the snapshot belongs to."""
    found = {snapshot.unit: (snapshot.uri, snapshot.document.source)}
    for unit, file in snapshot.files.items():
        text = server.read_text(file.uri) if unit is not snapshot.unit else None
        if text is not None:
            found[unit] = (file.uri, text)
    return found


@lru_cache(maxsize=4)
def _shows_v4(program: str, config: str | None, controller: str) -> bool:
    from mintlang.migrate import shows_v4  # noqa: PLC0415  (the migrator loads only when a file has v3 words)

    texts = {Unit.PROGRAM: program} if config is None else {Unit.PROGRAM: program, Unit.CONFIGURATION: config}
    return shows_v4(texts, controller)


def is_v3(snapshot: Snapshot, texts: Texts) -> bool:
    """Whether the file is Mint v3: by the dialect setting, or v3 words and no form only v4 has."""
    if snapshot.settings.dialect is Dialect.V3:
        return True
    if not any(diagnostic.from_v3 for diagnostic in snapshot.diagnostics):
        return False
    return not _shows_v4(texts[Unit.PROGRAM], texts.get(Unit.CONFIGURATION), str(snapshot.settings.controller))


def _is_rename(fix: mintlang.Fix) -> bool:
    """A fix that writes one word in place of others (not a DIM to insert, nor code to remove)."""
    return all(edit.span.end > edit.span.start and _WORD.fullmatch(edit.text) for edit in fix.edits)


def renames(snapshot: Snapshot) -> list[mintlang.Fix]:
    """The rename offered for each v3 word the checker found, once per place."""
    found: dict[tuple[int, int], mintlang.Fix] = {}
    for diagnostic in snapshot.diagnostics:
        fix = next((fix for fix in diagnostic.fixes if _is_rename(fix)), None) if diagnostic.from_v3 else None
        if fix is not None:
            found.setdefault(min((edit.span.start, edit.span.end) for edit in fix.edits), fix)
    return list(found.values())


def _applied(text: str, edits: Iterable[mintlang.Edit]) -> str:
    for edit in sorted(edits, key=lambda edit: edit.span.start, reverse=True):
        text = text[: edit.span.start] + edit.text + text[edit.span.end :]
    return text


def _errors(snapshot: Snapshot, texts: Texts, fixes: Iterable[mintlang.Fix]) -> Counter[tuple[str, str]]:
    """The v4 checker's errors in the snapshot's file once ``fixes`` are made, by code and message."""
    edited = {**texts, snapshot.unit: _applied(texts[snapshot.unit], (e for fix in fixes for e in fix.edits))}
    analysis = mintlang.check_application(
        edited.get(Unit.PROGRAM, ""),  # a configuration file alone is checked with an empty program
        config=edited.get(Unit.CONFIGURATION),
        dialect=Dialect.V4,
        controller=snapshot.settings.controller,
    )
    own = analysis.configuration if snapshot.unit is Unit.CONFIGURATION else analysis.program
    return Counter((d.code, d.message) for d in own if d.severity is mintlang.Severity.ERROR)


def checked(snapshot: Snapshot, texts: Texts, fixes: list[mintlang.Fix]) -> list[mintlang.Fix]:
    """The renames after which the v4 checker finds no error it did not find before: all of them when
    together they add none, else those of each half that adds none, halved down to single renames (a
    rename the checker rejects is rare, so a few checks find it among hundreds)."""
    before = _errors(snapshot, texts, ())

    def accepted(group: list[mintlang.Fix]) -> list[mintlang.Fix]:
        if not _errors(snapshot, texts, group) - before:
            return group
        if len(group) == 1:
            return []
        middle = len(group) // 2
        return accepted(group[:middle]) + accepted(group[middle:])

    return accepted(fixes) if fixes else []


def actions(server: MintServer, snapshot: Snapshot, wanted: Iterable[str]) -> list[types.CodeAction]:
    """The actions of ``wanted`` kinds this file deserves, to be resolved when picked."""
    wanted = set(wanted)
    if snapshot.skipped is not None or not wanted:
        return []
    texts = {unit: text for unit, (_, text) in _texts(server, snapshot).items()}
    data = {"uri": snapshot.uri, "version": snapshot.version}
    found = []
    if REPLACE_KIND in wanted and renames(snapshot):
        found.append(types.CodeAction(title=REPLACE_TITLE, kind=REPLACE_KIND, data=data))
    if MIGRATE_KIND in wanted and snapshot.unit is Unit.PROGRAM and is_v3(snapshot, texts):
        found.append(types.CodeAction(title=MIGRATE_TITLE, kind=MIGRATE_KIND, data=data))
    return found


def resolve(server: MintServer, action: types.CodeAction) -> types.CodeAction:
    """The edit of an action ``actions`` offered, for the version it was offered on."""
    data = action.data if isinstance(action.data, dict) else {}
    snapshot = server.snapshot(str(data.get("uri", "")))
    if action.kind not in KINDS or snapshot is None or snapshot.version != data.get("version"):
        return action
    files = _texts(server, snapshot)
    texts = {unit: text for unit, (_, text) in files.items()}
    if action.kind == REPLACE_KIND:
        edits = [edit for fix in checked(snapshot, texts, renames(snapshot)) for edit in fix.edits]
        changes = {snapshot.uri: [_text_edit(snapshot.positions, edit) for edit in edits]}
        action.edit = types.WorkspaceEdit(changes=changes)
    else:
        action.edit = _migration(server, snapshot, files)
    return action


def _text_edit(positions: Positions, edit: mintlang.Edit) -> types.TextEdit:
    return types.TextEdit(range=positions.range(edit.span), new_text=edit.text)


def _migration(server: MintServer, snapshot: Snapshot, files: Mapping[Unit, tuple[str, str]]) -> types.WorkspaceEdit:
    from mintlang.migrate import MigrationFailed, migrate  # noqa: PLC0415  (loaded only when the user asks)

    program_uri, program = files[Unit.PROGRAM]
    config_uri, config = files.get(Unit.CONFIGURATION, (None, None))
    try:
        result = migrate(program, config=config, controller=snapshot.settings.controller)
    except MigrationFailed as error:
        raise MigrationRefused(f"mint-migrate could not migrate this file: {error}") from error
    encoding = server.analyses.encoding
    changes = {program_uri: [_text_edit(Positions(program, encoding), edit) for edit in result.edits()]}
    if config_uri is not None and config is not None and result.configuration is not None:
        changes[config_uri] = [_text_edit(Positions(config, encoding), e) for e in result.configuration.edits()]
    changes = {uri: edits for uri, edits in changes.items() if edits}
    if not confirmation.supported(server):
        return types.WorkspaceEdit(changes=changes)
    both = (result, result.configuration) if result.configuration is not None else (result,)
    made, manual = sum(len(file.changes) for file in both), sum(len(file.manual) for file in both)
    note = f"{made} changes by mint-migrate; {manual} places need you (REM MIGRATE lines)"
    annotation = types.ChangeAnnotation(label=MIGRATE_TITLE, needs_confirmation=True, description=note)
    return confirmation.confirmed(server, changes, _MIGRATION, annotation)
