"""Incremental edits land where the editor made them, whatever line-breaking characters the text holds.

Python's ``str.splitlines`` also ends lines at \\v, \\f, \\x1c-\\x1e, NEL,
U+2028 and U+2029; an LSP client counts only ``\\n``, ``\\r\\n`` and ``\\r``.
The reference model below is the client's view, written independently of the
server's code.
"""

from __future__ import annotations

import pytest
import pytest_lsp
from hypothesis import given, settings
from hypothesis import strategies as st
from lsprotocol import types
from pytest_lsp import LanguageClient, client_capabilities

from mintlang.lsp.documents import LspWorkspace
from tests.lsp.conftest import EDITOR, document, units, uri_of

# str.splitlines breaks at these; the LSP does not
NOT_LINE_ENDS = ("\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029")
ENCODINGS = (types.PositionEncodingKind.Utf8, types.PositionEncodingKind.Utf16, types.PositionEncodingKind.Utf32)


# The editor's view of a text


def editor_lines(text: str) -> list[str]:
    """The lines with their ends, breaking at the first ``\\r\\n``, ``\\r`` or ``\\n`` only."""
    lines, start, at = [], 0, 0
    while at < len(text):
        if text[at] in "\r\n":
            at += 2 if text.startswith("\r\n", at) else 1
            lines.append(text[start:at])
            start = at
        else:
            at += 1
    if start < len(text):
        lines.append(text[start:])
    return lines


def _content(line: str) -> str:
    for end in ("\r\n", "\r", "\n"):
        if line.endswith(end):
            return line[: -len(end)]
    return line


def editor_offset(text: str, position: types.Position, encoding: str) -> int:
    """A position's offset; a column past its line means the line's end, a line past the text its end."""
    lines = editor_lines(text)
    if position.line >= len(lines):
        return len(text)
    content = _content(lines[position.line])
    column = 0
    while column < len(content) and units(content[: column + 1], encoding) <= position.character:
        column += 1
    return sum(map(len, lines[: position.line])) + column


def editor_position(text: str, offset: int, encoding: str) -> types.Position:
    start = 0
    for number, line in enumerate(editor_lines(text)):
        if offset <= start + len(_content(line)):
            return types.Position(line=number, character=units(text[start:offset], encoding))
        start += len(line)
    return types.Position(line=len(editor_lines(text)), character=units(text[start:offset], encoding))


def editor_range(text: str, start: int, end: int, encoding: str) -> types.Range:
    return types.Range(start=editor_position(text, start, encoding), end=editor_position(text, end, encoding))


# Unit: the workspace's documents


def _opened(text: str, encoding: str) -> LspWorkspace:
    workspace = LspWorkspace(None, position_encoding=encoding)
    workspace.put_text_document(types.TextDocumentItem(uri="file:///t.mnt", language_id="mint", version=1, text=text))
    return workspace


def _edit(workspace: LspWorkspace, where: types.Range, text: str) -> str:
    workspace.update_text_document(
        types.VersionedTextDocumentIdentifier(uri="file:///t.mnt", version=2),
        types.TextDocumentContentChangePartial(range=where, text=text),
    )
    return workspace.get_text_document("file:///t.mnt").source


@pytest.mark.parametrize("breaker", NOT_LINE_ENDS)
def test_an_edit_below_a_character_splitlines_breaks_at(breaker: str) -> None:
    text = f"REM page one{breaker}page two\nDIM x\nPRINT x\n"
    workspace = _opened(text, types.PositionEncodingKind.Utf16)
    where = types.Range(start=types.Position(line=2, character=6), end=types.Position(line=2, character=7))
    assert _edit(workspace, where, "x2") == f"REM page one{breaker}page two\nDIM x\nPRINT x2\n"
    assert len(workspace.get_text_document("file:///t.mnt").lines) == 3


_CHARACTERS = st.sampled_from(["a", " ", "é", "😀", "\n", "\r", *NOT_LINE_ENDS])
_TEXTS = st.lists(_CHARACTERS, max_size=30).map("".join)


@st.composite
def _positions(draw: st.DrawFn, text: str, encoding: str) -> types.Position:
    """Positions an editor can send: on a character boundary, past a line's end, or past the last line."""
    lines = editor_lines(text)
    line = draw(st.integers(0, len(lines) + 1))
    content = _content(lines[line]) if line < len(lines) else ""
    if draw(st.integers(0, 3)) == 0:
        return types.Position(line=line, character=units(content, encoding) + draw(st.integers(1, 3)))
    return types.Position(line=line, character=units(content[: draw(st.integers(0, len(content)))], encoding))


@settings(max_examples=300, deadline=None)
@given(text=_TEXTS, encoding=st.sampled_from(ENCODINGS), data=st.data())
def test_random_edits_give_the_editors_text(text: str, encoding: str, data: st.DataObject) -> None:
    workspace = _opened(text, encoding)
    for _ in range(data.draw(st.integers(1, 12))):  # each edit moves the line starts the one before kept
        first, second = data.draw(_positions(text, encoding)), data.draw(_positions(text, encoding))
        start, end = sorted((first, second), key=lambda position: (position.line, position.character))
        new = data.draw(_TEXTS)
        text = text[: editor_offset(text, start, encoding)] + new + text[editor_offset(text, end, encoding) :]
        assert _edit(workspace, types.Range(start=start, end=end), new) == text
        assert list(workspace.get_text_document("file:///t.mnt").lines) == editor_lines(text)


# End to end: an editor over stdio


@pytest_lsp.fixture(
    config=EDITOR,
    params=[types.PositionEncodingKind.Utf16, types.PositionEncodingKind.Utf8],
)
async def editor(lsp_client: LanguageClient, request: pytest.FixtureRequest):
    capabilities = client_capabilities("visual-studio-code")
    capabilities.general = types.GeneralClientCapabilities(position_encodings=[request.param])
    result = await lsp_client.initialize_session(types.InitializeParams(capabilities=capabilities))
    assert result.capabilities.position_encoding == request.param
    yield
    await lsp_client.shutdown_session()


def _report(diagnostics: list[types.Diagnostic]) -> list[tuple[object, ...]]:
    return [(d.code, d.range, d.message) for d in diagnostics]


@pytest.mark.asyncio
async def test_edits_after_each_character_match_the_editor(editor: LanguageClient, tmp_path) -> None:
    [encoding] = editor.capabilities.general.position_encodings  # the one the fixture saw negotiated
    for number, breaker in enumerate(NOT_LINE_ENDS):
        text = f'REM page one{breaker}page two\nDIM x : REM {breaker} tail\nPRINT "é😀", x\n'
        uri = uri_of(tmp_path / f"edited{number}.mnt")
        editor.text_document_did_open(
            types.DidOpenTextDocumentParams(types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=text))
        )
        # xy is no keyword's spelling in any dialect (x2 is v3's XIO2, which hover would describe)
        for version, (old, new) in enumerate([("two", "2"), ("tail", "end"), ("x\n", "xy\n")], start=2):
            start = text.rindex(old)
            where = editor_range(text, start, start + len(old), encoding)
            text = text[:start] + new + text[start + len(old) :]
            editor.text_document_did_change(
                types.DidChangeTextDocumentParams(
                    text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                    content_changes=[types.TextDocumentContentChangePartial(range=where, text=new)],
                )
            )
        fresh = uri_of(tmp_path / f"fresh{number}.mnt")  # the editor's text, sent whole
        editor.text_document_did_open(
            types.DidOpenTextDocumentParams(types.TextDocumentItem(uri=fresh, language_id="mint", version=1, text=text))
        )

        edited = await editor.text_document_diagnostic_async(types.DocumentDiagnosticParams(document(uri)))
        expected = await editor.text_document_diagnostic_async(types.DocumentDiagnosticParams(document(fresh)))
        xy = editor_position(text, text.rindex("xy"), encoding)
        assert _report(edited.items) == _report(expected.items), repr(breaker)
        assert [(d.code, d.range.start) for d in edited.items] == [
            ("W103", types.Position(line=1, character=4)),
            ("E3001", xy),
        ], repr(breaker)
        hover = await editor.text_document_hover_async(types.HoverParams(document(uri), xy))
        assert hover.contents.value.startswith("**xy** — variable"), repr(breaker)
        assert hover.range.start == xy, repr(breaker)
