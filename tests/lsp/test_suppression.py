"""Suppression comments in the editor: silenced diagnostics, unused suppressions, "Ignore W103 on this line"."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio

UNUSED = "DIM total\nDIM spare\n"  # W103 on lines 1 and 2


def codes(diagnostics: list[types.Diagnostic]) -> list[tuple[str, int]]:
    return sorted((str(d.code), d.range.start.line + 1) for d in diagnostics)


async def ignore_action(client, uri: str, diagnostic: types.Diagnostic) -> types.CodeAction:
    context = types.CodeActionContext(diagnostics=[diagnostic])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=diagnostic.range, context=context)
    )
    [action] = [a for a in found if a.title == f"Ignore {diagnostic.code} on this line"]
    assert action.kind == types.CodeActionKind.QuickFix
    return action


def applied(text: str, edit: types.TextEdit) -> str:
    lines = text.splitlines(keepends=True)
    start = sum(len(line) for line in lines[: edit.range.start.line]) + edit.range.start.character
    end = sum(len(line) for line in lines[: edit.range.end.line]) + edit.range.end.character
    return text[:start] + edit.new_text + text[end:]


async def test_a_comment_silences_its_line_only(client, tmp_path):
    uri = uri_of(tmp_path / "unused.mnt")
    diagnostics = await open_document(client, uri, "DIM total : REM mint: ignore[W103]\nDIM spare\n")
    assert codes(diagnostics) == [("W103", 2)]


async def test_an_unused_suppression_is_reported_with_its_removal(client, tmp_path):
    uri = uri_of(tmp_path / "used.mnt")
    text = "DIM total : REM mint: ignore[W103]\ntotal = 1\nPRINT total\n"
    [diagnostic] = await open_document(client, uri, text)
    assert (diagnostic.code, diagnostic.range.start.character) == ("W117", 29)  # at W103 in the comment
    context = types.CodeActionContext(diagnostics=[diagnostic])
    found = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=diagnostic.range, context=context)
    )
    [removal] = [a for a in found if a.title == "Remove the suppression comment"]
    [edit] = removal.edit.changes[uri]
    assert applied(text, edit) == "DIM total\ntotal = 1\nPRINT total\n"


@pytest.mark.parametrize(
    ("line", "after"),
    [
        ("DIM total", "DIM total : REM mint: ignore[W103]"),
        ("DIM total : REM running sum", "DIM total : REM mint: ignore[W103] running sum"),
        ("DIM total : REM mint: ignore[W111]", "DIM total : REM mint: ignore[W111, W103]"),
    ],
)
async def test_ignore_on_this_line_adds_or_extends_the_comment(client, tmp_path, line, after):
    uri = uri_of(tmp_path / "ignore.mnt")
    text = f"{line}\nPRINT 1\n"
    diagnostics = await open_document(client, uri, text)
    [unused] = [d for d in diagnostics if d.code == "W103"]
    [edit] = (await ignore_action(client, uri, unused)).edit.changes[uri]
    assert applied(text, edit) == f"{after}\nPRINT 1\n"


async def test_over_several_lines_each_ignore_action_names_its_line(client, tmp_path):
    """Two W103 on lines 1 and 2, both selected: "on this line" twice would not say which is which."""
    uri = uri_of(tmp_path / "two.mnt")
    diagnostics = await open_document(client, uri, UNUSED)
    selection = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=1, character=9))
    found = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=document(uri), range=selection, context=types.CodeActionContext(diagnostics=diagnostics)
        )
    )
    ignores = {a.title: a.edit.changes[uri] for a in found if a.title.startswith("Ignore")}
    assert sorted(ignores) == ["Ignore W103 on line 1", "Ignore W103 on line 2"]
    [on_line_2] = ignores["Ignore W103 on line 2"]
    assert applied(UNUSED, on_line_2) == "DIM total\nDIM spare : REM mint: ignore[W103]\n"


async def test_two_diagnostics_of_one_code_on_a_line_are_ignored_by_one_action(client, tmp_path):
    uri = uri_of(tmp_path / "pair.mnt")
    text = "DIM total : DIM spare\n"  # W103 for each name, one comment silences both
    diagnostics = await open_document(client, uri, text)
    assert codes(diagnostics) == [("W103", 1), ("W103", 1)]
    selection = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=0, character=21))
    found = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=document(uri), range=selection, context=types.CodeActionContext(diagnostics=diagnostics)
        )
    )
    assert [a.title for a in found if a.title.startswith("Ignore")] == ["Ignore W103 on this line"]


async def test_ignoring_a_finding_on_a_line_that_a_dim_list_continues_keeps_the_list_going(client, tmp_path):
    """The guide's arrays (3.3, 000:1095-1097): a list of initial values goes on to the next line after a
    trailing comma, so ``: REM`` there would end the DIM and leave ``3, 4`` a line of its own. A REM after
    code needs no colon (the REM entry, 000:15510-15512): the comment goes straight after the comma."""
    uri = uri_of(tmp_path / "table.mnt")
    text = "DIM table(4) = 1, 2,\n  3, 4\n"
    [unused] = await open_document(client, uri, text)
    assert (unused.code, unused.range.start.line) == ("W103", 0)
    [edit] = (await ignore_action(client, uri, unused)).edit.changes[uri]
    ignored = applied(text, edit)
    assert ignored == "DIM table(4) = 1, 2, REM mint: ignore[W103]\n  3, 4\n"
    assert await open_document(client, uri_of(tmp_path / "ignored.mnt"), ignored) == []
