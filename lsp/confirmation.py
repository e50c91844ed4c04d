"""Workspace edits the user confirms before they apply: change annotations that need confirmation.

A client that supports them (VS Code) shows such an edit in a preview, with
each file's changes to tick, before anything changes; other clients apply
edits as they come, and the feature asks its question another way.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from lsprotocol import types

from mintlang.lsp.server import MintServer


def supported(server: MintServer) -> bool:
    """Whether the client reads annotated edits in ``documentChanges``."""
    workspace = server.client_capabilities.workspace
    edits = workspace.workspace_edit if workspace is not None else None
    return bool(edits and edits.document_changes and edits.change_annotation_support)


def confirmed(
    server: MintServer,
    changes: Mapping[str, Sequence[types.TextEdit]],
    annotation_id: str,
    annotation: types.ChangeAnnotation,
) -> types.WorkspaceEdit:
    """``changes`` under one annotation, each document at the version it has in the editor (none if closed)."""
    documents = []
    for uri, edits in changes.items():
        opened = server.document(uri)
        identifier = types.OptionalVersionedTextDocumentIdentifier(
            uri=uri, version=opened.version if opened is not None else None
        )
        marked = [
            types.AnnotatedTextEdit(range=edit.range, new_text=edit.new_text, annotation_id=annotation_id)
            for edit in edits
        ]
        documents.append(types.TextDocumentEdit(text_document=identifier, edits=marked))
    return types.WorkspaceEdit(document_changes=documents, change_annotations={annotation_id: annotation})
