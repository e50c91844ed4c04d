"""``mint.*`` settings from ``initializationOptions`` and ``workspace/configuration``."""

from __future__ import annotations

import asyncio
import logging

from lsprotocol import types

from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings

log = logging.getLogger(__name__)


def register(server: MintServer) -> None:
    @server.feature(types.INITIALIZE)
    def initialize(params: types.InitializeParams) -> None:
        server.analyses.settings = Settings.from_options(params.initialization_options)
        server.analyses.encoding = server.workspace.position_encoding or types.PositionEncodingKind.Utf16

    @server.feature(types.INITIALIZED)
    async def initialized(_: types.InitializedParams) -> None:
        await pull(server)
        for hook in server.when_initialized:
            await hook()

    @server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
    async def changed(params: types.DidChangeConfigurationParams) -> None:
        if params.settings:
            server.analyses.settings = Settings.from_options(params.settings, server.analyses.settings)
        await pull(server)
        from mintlang.lsp.features.diagnostics import refresh_all  # noqa: PLC0415  (a sibling feature)

        refresh_all(server)
        for hook in server.when_settings_changed:
            await hook()


async def pull(server: MintServer) -> None:
    """Ask for the editor's settings, the asking kept as ``settings_pull`` for the answers that wait for it."""
    server.settings_pull = asyncio.ensure_future(_pull(server))
    await server.settings_pull


async def settled(server: MintServer) -> None:
    """Once the editor's settings asked for, if they are, have come: an answer sent right after the editor
    said they changed (the pairing of a file, for one) follows the new settings, not the old."""
    if server.settings_pull is not None:
        await asyncio.shield(server.settings_pull)


async def _pull(server: MintServer) -> None:
    """Ask a client that supports it for the ``mint`` section; keep what we have otherwise."""
    workspace = server.client_capabilities.workspace
    if workspace is None or not workspace.configuration:
        return
    try:
        answer = await server.workspace_configuration_async(
            types.ConfigurationParams(items=[types.ConfigurationItem(section="mint")])
        )
    except Exception as error:  # a client that fails the request leaves the settings as they are
        log.warning("workspace/configuration failed: %s", error)
        return
    if answer:
        server.analyses.settings = Settings.from_options(answer[0], server.analyses.settings)
