"""Fix all (``source.fixAll.mint``): the program as ``mint check --fix`` writes it, as one edit.

Editors run it on save (VS Code's ``editor.codeActionsOnSave``). It makes the safe fixes alone, round after
round as the command line does (``mintlang.fixes``), each round's check starting from the last analysis. It
is offered only where some finding has a fix that ``--fix`` would make, and only to a request that names its
kind (on save, or the Source Action menu): a lightbulb's request at every cursor move names none, and the
rounds take seconds in a file of thousands of lines.
"""

from __future__ import annotations

from collections.abc import Callable

from lsprotocol import types

import mintlang
from mintlang.fixes import automatic_fix, fix_text
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.units import Unit
from mintlang.syntax.common import shared_ends

KIND = f"{types.CodeActionKind.SourceFixAll.value}.mint"
TITLE = "Fix all auto-fixable problems"


def actions(snapshot: Snapshot) -> list[types.CodeAction]:
    """The fix-all action of a program that has something ``--fix`` fixes (a configuration file is only
    checked by ``mint check``, never fixed)."""
    if snapshot.unit is not Unit.PROGRAM or snapshot.skipped is not None:
        return []
    if not any(automatic_fix(diagnostic, unsafe=False) for diagnostic in snapshot.diagnostics):
        return []
    old = snapshot.document.source
    new = fix_text(old, _checker(snapshot), unsafe=False).text
    if new == old:
        return []
    head, tail = shared_ends(old, new)
    span = mintlang.Span(head, len(old) - tail)
    edit = types.TextEdit(range=snapshot.positions.range(span), new_text=new[head : len(new) - tail])
    return [types.CodeAction(title=TITLE, kind=KIND, edit=types.WorkspaceEdit(changes={snapshot.uri: [edit]}))]


def _checker(snapshot: Snapshot) -> Callable[[str], tuple[mintlang.Diagnostic, ...]]:
    """The program's findings for a text, checked as the snapshot was (settings, configuration file)."""
    settings, configuration = snapshot.settings, snapshot.model.configuration
    last = [snapshot.analysis]

    def findings(text: str) -> tuple[mintlang.Diagnostic, ...]:
        last[0] = settings.check(text, configuration.source if configuration is not None else None, last[0])
        return last[0].program

    return findings
