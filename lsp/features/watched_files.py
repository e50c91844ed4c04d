"""Files changed on disk: a configuration file saved by any editor re-checks the programs paired with it.

A program is checked with its configuration file, read from disk when it is
not open (and the reverse). When that file changes on disk, the open
documents that read it are checked again. A client that can watch files
(``workspace/didChangeWatchedFiles`` with dynamic registration: VS Code,
Neovim 0.9+) is asked to watch programs and configuration files and says
what changed; for the others the server looks itself, once a second, at the
size and time of the partner files of the open documents only. A new
``mint.configPairing`` replaces the client's watch.
"""

from __future__ import annotations

import asyncio
import logging
import os
from collections.abc import Iterable
from urllib.parse import unquote

from lsprotocol import types
from pygls.uris import to_fs_path

from mintlang.lsp.features.diagnostics import recheck
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import partner
from mintlang.pairing import PROGRAM_SUFFIX, Pairing

log = logging.getLogger(__name__)

REGISTRATION = "mint.watchedFiles"
POLL_S = 1.0
Stamp = tuple[int, int] | None  # modification time and size; None: no such file


def _any_case(name: str) -> str:
    """A glob matching ``name`` in any letter case (``.cfg``: ``.[cC][fF][gG]``), as the controller's PC does."""
    return "".join(f"[{c.lower()}{c.upper()}]" if c.isalpha() else c for c in name)


def globs(config_pairing: str) -> list[str]:
    """What to watch: every program, and every file the pairing names (``<name>.cfg``: ``**/*.cfg``)."""
    found = [f"**/*{_any_case(PROGRAM_SUFFIX)}"]
    pairing = Pairing.from_pattern(config_pairing)
    if pairing is not None:
        found.append(f"**/{_any_case(pairing.prefix)}*{_any_case(pairing.suffix)}")
    return found


def _key(uri: str) -> str:
    return unquote(uri).casefold()  # APP.CFG and app.cfg are one file to the pairing


def _partners(server: MintServer) -> list[tuple[str, str]]:
    """Each open document with its partner file, where that file is not open (an open file is the
    editor's, not the disk's)."""
    opened = server.opened()
    settings = server.analyses.settings
    pairs = []
    for uri in list(opened):
        other = partner(uri, settings, opened)[1]
        if other is not None and other not in opened:
            pairs.append((uri, other))
    return pairs


def readers(server: MintServer, changed: Iterable[str]) -> list[str]:
    """The open documents that read one of the ``changed`` files from disk."""
    wanted = {_key(uri) for uri in changed}
    return [uri for uri, other in _partners(server) if _key(other) in wanted]


def _stamp(uri: str) -> Stamp:
    path = to_fs_path(uri)
    try:
        status = os.stat(path) if path is not None else None
    except OSError:
        return None
    return (status.st_mtime_ns, status.st_size) if status is not None else None


class Poller:
    """Looks at the partner files of the open documents once a second, for clients that cannot watch files."""

    def __init__(self, server: MintServer) -> None:
        self.server = server
        self.stamps: dict[str, Stamp] = {}

    def look(self) -> None:
        """Re-check the documents whose partner changed since the last look; remember the partners of the open ones."""
        stamps = {other: _stamp(other) for _, other in _partners(self.server)}
        changed = [other for other, stamp in stamps.items() if other in self.stamps and self.stamps[other] != stamp]
        self.stamps = stamps
        if changed:
            recheck(self.server, readers(self.server, changed))

    async def run(self) -> None:
        while True:
            await asyncio.sleep(POLL_S)
            try:
                self.look()
            except Exception:  # a task of our own: nobody else would see the failure
                log.exception("looking at the partner files failed")


def _watches(server: MintServer) -> bool:
    workspace = server.client_capabilities.workspace
    watched = workspace.did_change_watched_files if workspace is not None else None
    return bool(watched and watched.dynamic_registration)


class Watching:
    """The client's watch on programs and paired files: registered once the client is ready, and again
    under a new ``mint.configPairing``."""

    def __init__(self, server: MintServer) -> None:
        self.server = server
        self.pairing: str | None = None  # what the client watches for

    async def follow(self) -> None:
        pairing = self.server.analyses.settings.config_pairing
        if not _watches(self.server) or pairing == self.pairing:
            return
        method = types.WORKSPACE_DID_CHANGE_WATCHED_FILES
        watchers = [types.FileSystemWatcher(glob_pattern=glob) for glob in globs(pairing)]
        options = types.DidChangeWatchedFilesRegistrationOptions(watchers=watchers)
        registration = types.Registration(id=REGISTRATION, method=method, register_options=options)
        try:
            if self.pairing is not None:
                old = types.Unregistration(id=REGISTRATION, method=method)
                await self.server.client_unregister_capability_async(types.UnregistrationParams(unregisterations=[old]))
            await self.server.client_register_capability_async(types.RegistrationParams(registrations=[registration]))
        except Exception as error:  # a client that refuses leaves files unwatched, as before
            log.warning("the client did not watch files: %s", error)
            return
        self.pairing = pairing


def register(server: MintServer) -> None:
    tasks: set[asyncio.Task[None]] = set()
    watching = Watching(server)

    async def start() -> None:
        if _watches(server):
            await watching.follow()
        else:
            tasks.add(asyncio.get_running_loop().create_task(Poller(server).run()))  # kept: the loop holds tasks weakly

    server.when_initialized.append(start)
    server.when_settings_changed.append(watching.follow)

    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def changed(params: types.DidChangeWatchedFilesParams) -> None:
        recheck(server, readers(server, (event.uri for event in params.changes)))
