"""Which program and configuration file a file belongs with, as the server checks them: ``mint.applicationFiles``.

An editor that runs or debugs a program (``mint-run --config``, the debugger's
``config``), or decides whether a ``.cfg`` file is Mint, asks this command
rather than pairing files by a rule of its own: the answer follows the
editor's ``mint.configPairing`` over the project's settings file
(``config-pairing``, ``config``), so the editor's run, its debugger and its
checks pair a program with the same file. The command answers
``{"program": uri | null, "configuration": uri | null, "dialect": name | null}``:

- for a program, itself and its configuration file: the settings file's
  ``config`` as named (missing or not, so a run reports it missing as the
  command line does), else the paired file where it exists;
- for the configuration file of a program that exists (the file that
  program is paired with), or for the settings file's ``config``, the
  program (null for ``config``, which every program shares) and itself;
- for any other file, nulls.

A file counts as existing when it is open in the editor or on disk. ``dialect``
is the one the server reads the program in (null without a program): with
``mint.dialect`` ``auto``, the one its text shows, which the editor's run then
runs it in, as the server's checks and its own run read it.
"""

from __future__ import annotations

from pathlib import Path

from pygls.uris import to_fs_path

from mintlang.lsp.features.settings import settled
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings, partner
from mintlang.pairing import is_program
from mintlang.semantic.units import Unit

APPLICATION_FILES = "mint.applicationFiles"


def _path(uri: str) -> Path | None:
    path = to_fs_path(uri) if uri.startswith("file:") else None
    return Path(path) if path is not None else None


def _exists(server: MintServer, uri: str) -> bool:
    path = _path(uri)
    return uri in server.opened() or (path is not None and path.is_file())


def _is_named(uri: str, settings: Settings) -> bool:
    """Whether ``uri`` is the configuration file the settings file names outright (``config``)."""
    path = _path(uri)
    return settings.config_file is not None and path is not None and path.resolve() == settings.config_file.resolve()


def _files(server: MintServer, uri: str) -> tuple[str | None, str | None]:
    """The program and the configuration file of the application ``uri`` is part of (see the module's docstring)."""
    settings = server.analyses.settings_for(uri)
    unit, other = partner(uri, settings, server.opened())
    if is_program(uri.rpartition("/")[2]):
        named = settings.config_file is not None
        return uri, other if other and (named or _exists(server, other)) else None
    if _is_named(uri, settings):
        return None, uri
    if unit is Unit.CONFIGURATION and other is not None and _exists(server, other):
        _, its_configuration = partner(other, server.analyses.settings_for(other), server.opened())
        if its_configuration == uri:  # the program's own, not displaced by ``config`` or an exact spelling
            return other, uri
    return None, None


def application_files(server: MintServer, uri: str) -> dict[str, str | None]:
    """The answer of ``mint.applicationFiles`` for ``uri`` (see the module's docstring)."""
    program, configuration = _files(server, uri)
    text = server.read_text(program) if program is not None else None
    dialect = server.analyses.settings_for(program).for_text(text).dialect if program and text is not None else None
    return {"program": program, "configuration": configuration, "dialect": dialect.value if dialect else None}


def register(server: MintServer) -> None:
    @server.command(APPLICATION_FILES)
    async def answer(ls: MintServer, uri: str) -> dict[str, str | None]:
        await settled(ls)
        return application_files(ls, uri)
