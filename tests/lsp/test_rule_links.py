"""Each diagnostic's code links to its page (``codeDescription``), wherever ``mint.rulesUrl`` says they are."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.workspace import Settings
from tests.lsp.conftest import open_document, published, uri_of


@pytest.mark.asyncio
async def test_a_diagnostic_links_its_codes_page(client, tmp_path):
    uri = uri_of(tmp_path / "links.mnt")
    (undeclared,) = await open_document(client, uri, "PRINT speed_limit\n")
    assert undeclared.code == "E3001"
    assert undeclared.code_description is not None
    assert undeclared.code_description.href.endswith("/docs/rules/E3001.md")


@pytest.mark.asyncio
async def test_the_rules_url_setting_moves_the_links(client, tmp_path):
    uri = uri_of(tmp_path / "moved.mnt")
    await open_document(client, uri, "PRINT speed_limit\n")
    settings = {"mint": {"rulesUrl": "https://intranet.example/mint/{code}.html"}}
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings=settings))
    (undeclared,) = await published(client, uri)
    assert undeclared.code_description.href == "https://intranet.example/mint/E3001.html"


def test_the_setting_is_read_from_the_editors_options():
    assert Settings.from_options({"mint": {"rulesUrl": "https://example.org/rules/"}}).rules_url == (
        "https://example.org/rules/"
    )
    assert Settings().rules_url is None
