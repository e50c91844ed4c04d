"""Rename variables, arrays, labels and macros; keywords and colliding names are refused.

A new name must lex as a user name of the dialect (not a keyword, constant or
abbreviation; a label's may be digits alone) and must not equal another symbol in its first ten characters,
which the controller would take for the same name; nor may a label and a macro
share a name, as the macro's text would replace the label's name. Event handlers keep their
names, and no subroutine is renamed into one: the controller calls handlers
by name. A symbol written with two spellings the controller takes for one
(``thisIsAVariable1``, ``thisIsAVaraible2``) is written one way after the
rename; the user is told so before anything changes: a change annotation that
needs confirmation where the client supports them, else a question. A variable
or array is renamed in the program's ``REM @expect`` comments too, and in the
``what`` of its scenario file (``cell.scenario.toml`` beside ``cell.mnt``):
``mint test`` reads the value by that name, and would find none after the rename.
"""

from __future__ import annotations

import asyncio
import logging
import re
from collections.abc import Iterator
from pathlib import Path

from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pygls.uris import from_fs_path, to_fs_path

from mintlang.diagnostics import Span
from mintlang.lsp import confirmation
from mintlang.lsp.lookup import abbreviated, token_at
from mintlang.lsp.mintmt_words import names_an_event_block
from mintlang.lsp.occurrences import symbol_at, written
from mintlang.lsp.positions import Positions
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings, Snapshot
from mintlang.pairing import listed_as, names_in
from mintlang.semantic.events import event_of
from mintlang.semantic.symbols import Occurrence, Symbol, SymbolKind, SymbolTable
from mintlang.semantic.units import Unit
from mintlang.syntax.lexer import lex
from mintlang.syntax.nodes import identity
from mintlang.syntax.tokens import TokenKind


class RenameRefused(JsonRpcException):
    CODE = -32803  # LSP RequestFailed: the request was valid but cannot be honoured


class _RefusalsAreAnswers(logging.Filter):
    """pygls logs every error response with a traceback; a refused rename is the user's answer, not a
    fault of the server, and a log full of them would hide the real ones."""

    def filter(self, record: logging.LogRecord) -> bool:
        return not (record.exc_info and isinstance(record.exc_info[1], RenameRefused))


def _spelling(occurrence: Occurrence) -> Span:
    """The span of the name itself (a label definition's span also covers its ``#``)."""
    return Span(occurrence.span.end - len(occurrence.spelling), occurrence.span.end)


def _target(snapshot: Snapshot, offset: int) -> tuple[Symbol, Occurrence]:
    found = symbol_at(snapshot, offset)
    if found is not None:
        symbol, occurrence = found
        if symbol.kind is SymbolKind.LABEL and event_of(occurrence.spelling, snapshot.settings.dialect) is not None:
            raise RenameRefused(f"#{occurrence.spelling} is an event handler: the controller calls it by this name")
        return found
    token = token_at(snapshot.document, offset)
    if token is not None and names_an_event_block(snapshot.document, token):
        raise RenameRefused(f"{token.text} is the event this block handles: the controller calls it by this name")
    if token is not None and token.kind not in (TokenKind.NAME, TokenKind.LABEL):
        raise RenameRefused(f"{token.text} is a Mint keyword or constant: only user names can be renamed")
    raise RenameRefused("There is no variable, array, label or macro here")


def _not_a_name(name: str, settings: Settings, kind: SymbolKind) -> str | None:
    """Why ``name`` cannot name a user's symbol of ``kind`` in the dialect, in words; None when it can."""
    tokens = [token for token in lex(name, settings.dialect).tokens if token.kind is not TokenKind.NEWLINE]
    single = len(tokens) == 1 and tokens[0].text == name
    found = tokens[0].kind if single else None
    digits = found is TokenKind.NUMBER and name.isascii() and name.isdigit()
    if found is TokenKind.NAME or (digits and kind is SymbolKind.LABEL):  # a label is alphanumeric (000:1843)
        return None
    taken = f"the {kind} cannot take its name"
    if found is TokenKind.CONSTANT:
        return f"'{name}' is the Mint constant {name.upper()}: {taken}"
    if digits:
        return f"'{name}' is a number: {taken}"
    if single and name.isalnum() and found is not TokenKind.INVALID:  # a keyword, REM and abbreviations included
        full = abbreviated(tokens[0], settings.words)
        what = f"the abbreviation of {full}" if full else f"the Mint keyword {name.upper()}"
        return f"'{name}' is {what}: {taken}"
    return (
        f"'{name}' is not a valid Mint name: a name starts with a letter, or _ and a letter or digit, "
        "and goes on with letters, digits and _"
    )


def _rivals(table: SymbolTable, symbol: Symbol) -> list[Symbol]:
    """The symbols a new name of ``symbol`` must not equal: a label's siblings in its file, a variable's
    fellow variables; and the macros for both, the labels too for a macro, as the controller puts a
    macro's text wherever its name is written, after GOSUB and GOTO as anywhere (000:9110)."""
    if symbol.kind is SymbolKind.LABEL:
        return [*table.labels[symbol.unit].values(), *table.macros.values()]
    if symbol.kind is SymbolKind.MACRO:
        labels = (label for file in table.labels.values() for label in file.values())
        return [*table.variables.values(), *table.macros.values(), *labels]
    return [*table.variables.values(), *table.macros.values()]


def _clash(name: str, symbol: Symbol, other: Symbol) -> str:
    written = f"#{other.name}" if other.kind is SymbolKind.LABEL else f"'{other.name}'"
    alike = name.upper() == other.name.upper()
    if SymbolKind.MACRO not in (symbol.kind, other.kind) or symbol.kind is other.kind:
        if alike:
            return f"'{name}' is already the name of the {other.kind} {written}"
        return f"'{name}' would be the same name as '{other.name}' to the controller (first ten characters count)"
    replaced = symbol.kind if other.kind is SymbolKind.MACRO else other.kind
    ten = "" if alike else " (the first ten characters count)"
    return (
        f"'{name}' is the name of the {other.kind} {written}{ten}: the controller would put the macro's text "
        f"in place of the {replaced}'s name"
    )


def _check_name(snapshot: Snapshot, symbol: Symbol, name: str) -> None:
    refusal = _not_a_name(name, snapshot.settings, symbol.kind)
    if refusal is not None:
        raise RenameRefused(refusal)
    if symbol.kind is SymbolKind.LABEL and event_of(name, snapshot.settings.dialect) is not None:
        raise RenameRefused(f"#{name} names an event handler: the subroutine would become one")
    for other in _rivals(snapshot.model.symbols, symbol):
        if other is not symbol and other.identity == identity(name):
            raise RenameRefused(_clash(name, symbol, other))


# What an expectation reads (runtime/scenario/README.md, "Directives in the program"): ``count = 3``,
# ``no count``, ``table(2) >= 1``; ``terminal`` and ``stopped`` begin the other forms.
_EXPECTED_NAME = re.compile(r"\s*(?:no\s+)?(?P<name>[A-Za-z_]\w*)", re.IGNORECASE)
_OTHER_FORMS = frozenset({"TERMINAL", "STOPPED"})


def _expected(snapshot: Snapshot, symbol: Symbol) -> Iterator[Span]:
    """Where the program's ``REM @expect`` comments name the variable or array ``symbol``."""
    if symbol.kind not in (SymbolKind.VARIABLE, SymbolKind.ARRAY):
        return
    from mintlang.runtime.scenario.directive_words import DIRECTIVE  # noqa: PLC0415 - the server starts without the runtime

    for offset, line in snapshot.model.document(Unit.PROGRAM).physical:
        if line.comment_start < 0:
            continue
        directive = DIRECTIVE.match(line.text, line.comment_start, line.content_end)
        if directive is None or directive["word"].lower() != "expect":
            continue
        named = _EXPECTED_NAME.match(line.text, directive.start("body"), line.content_end)
        if (
            named is not None
            and named["name"].upper() not in _OTHER_FORMS
            and identity(named["name"]) == symbol.identity
        ):
            yield Span(offset + named.start("name"), offset + named.end("name"))


# A scenario file's expectation names what it reads in its ``what`` key (runtime/scenario/README.md), a key of
# a table of its own (``[[expect]]``) or of an inline one (``expect = [{ what = "count", equals = 3 }]``).
_WHAT = re.compile(r"""(?:^|[{,])[ \t]*what[ \t]*=[ \t]*["'](?P<name>[A-Za-z_]\w*)""", re.MULTILINE)


def _in_scenario(server: MintServer, program_uri: str, symbol: Symbol, encoding: str) -> tuple[str, list[types.Range]]:
    """The scenario file beside the program, and where its expectations name the variable or array ``symbol``."""
    if symbol.kind not in (SymbolKind.VARIABLE, SymbolKind.ARRAY):
        return "", []
    from mintlang.runtime.testing.discovery import SCENARIO_SUFFIX  # noqa: PLC0415 - as _expected

    program = Path(to_fs_path(program_uri) or "")
    name = listed_as(program.stem + SCENARIO_SUFFIX, names_in(program.parent))
    if name is None:
        return "", []
    uri = from_fs_path(str(program.parent / name)) or ""
    try:
        text = server.workspace.get_text_document(uri).source  # the editor's text when it is open
    except (OSError, UnicodeDecodeError):
        return uri, []
    positions = Positions(text, encoding)
    return uri, [
        positions.range(Span(what.start("name"), what.end("name")))
        for what in _WHAT.finditer(text)
        if identity(what["name"]) == symbol.identity
    ]


MERGE = "mint.mergeSpellings"
QUESTION_TIMEOUT_S = 120.0
_GO_ON = "Rename all"


def _spellings(occurrences: list[Occurrence]) -> list[str]:
    """The different spellings of the occurrences (case aside: the controller ignores it), in order."""
    return list({occurrence.spelling.upper(): occurrence.spelling for occurrence in occurrences}.values())


def _merge_note(spellings: list[str], name: str) -> str:
    quoted = " and ".join(f"'{spelling}'" for spelling in spellings)
    return (
        f"{quoted} are one name to the controller (only the first ten characters count): "
        f"the rename writes them all as '{name}'"
    )


def register(server: MintServer) -> None:
    pygls_log = logging.getLogger("pygls.protocol.json_rpc")
    if not any(isinstance(existing, _RefusalsAreAnswers) for existing in pygls_log.filters):  # once per process
        pygls_log.addFilter(_RefusalsAreAnswers())

    @server.feature(types.TEXT_DOCUMENT_PREPARE_RENAME)
    def prepare(params: types.PrepareRenameParams) -> types.PrepareRenamePlaceholder | None:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return None
        _, occurrence = _target(snapshot, snapshot.positions.offset(params.position))
        return types.PrepareRenamePlaceholder(
            range=snapshot.positions.range(_spelling(occurrence)), placeholder=occurrence.spelling
        )

    @server.feature(types.TEXT_DOCUMENT_RENAME, types.RenameOptions(prepare_provider=True))
    async def rename(params: types.RenameParams) -> types.WorkspaceEdit | None:
        snapshot = server.snapshot(params.text_document.uri)
        if snapshot is None:
            return None
        symbol, _ = _target(snapshot, snapshot.positions.offset(params.position))
        name = params.new_name.removeprefix("#") if symbol.kind is SymbolKind.LABEL else params.new_name
        _check_name(snapshot, symbol, name)
        occurrences = written(snapshot, symbol)
        changes: dict[str, list[types.TextEdit]] = {}
        for occurrence in occurrences:
            file = snapshot.files.get(occurrence.unit)
            if file is not None:
                edit = types.TextEdit(range=file.positions.range(_spelling(occurrence)), new_text=name)
                changes.setdefault(file.uri, []).append(edit)
        program = snapshot.files.get(Unit.PROGRAM)
        if program is not None:
            for span in _expected(snapshot, symbol):
                edit = types.TextEdit(range=program.positions.range(span), new_text=name)
                changes.setdefault(program.uri, []).append(edit)
            scenario, places = _in_scenario(server, program.uri, symbol, program.positions.encoding)
            for place in places:
                changes.setdefault(scenario, []).append(types.TextEdit(range=place, new_text=name))
        spellings = _spellings(occurrences)
        if len(spellings) < 2:
            return types.WorkspaceEdit(changes=changes)
        note = _merge_note(spellings, name)
        if confirmation.supported(server):
            annotation = types.ChangeAnnotation(label="Merge spellings", needs_confirmation=True, description=note)
            return confirmation.confirmed(server, changes, MERGE, annotation)
        question = types.ShowMessageRequestParams(
            type=types.MessageType.Warning,
            message=f"{note}. Rename all?",
            actions=[types.MessageActionItem(title=_GO_ON), types.MessageActionItem(title="Cancel")],
        )
        try:
            answer = await asyncio.wait_for(server.window_show_message_request_async(question), QUESTION_TIMEOUT_S)
        except TimeoutError:
            answer = None  # a client that never answers gets no edit rather than a request open for ever
        if answer is None or answer.title != _GO_ON:
            raise RenameRefused(f"Rename cancelled: {note}")
        return types.WorkspaceEdit(changes=changes)
