"""The command line's side of the project settings (``mintlang.settings``).

The options a user types win over the settings file: ``overrides`` turns
those of ``mint check`` into the layer above the file. A tool's own table
(``[tool.mint.run]``, ``[tool.mint.migrate]``) gives the defaults of the
tool's options, under their long names (``until-ms = 500`` for
``--until-ms 500``), through ``ProjectCommand``. ``describe`` is
``--show-settings``.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any, NoReturn

import click
from click.core import ParameterSource

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.settings import (
    FileSettings,
    Given,
    Overrides,
    ProjectSettings,
    SettingsError,
    Table,
    project_for,
    relative_globs,
    settings_for,
)

_SETTINGS_ERROR = 2
_TYPED = (ParameterSource.COMMANDLINE, ParameterSource.ENVIRONMENT)
_SHARED = ("controller", "dialect")  # top-level settings every tool's options of the same name default to
_FROM_SETTINGS = "mint.from_settings"  # the context's meta key: the options the settings file gave
_TOP_LEVEL_ONLY = frozenset({"exclude", "extend-exclude", "force-exclude"})  # options no tool's own table gives
_COMMANDS = {  # each tool's table and its command, by module and name: the command's options are the table's keys
    "run": ("mintlang.runtime.cli", "run"),
    "migrate": ("mintlang.migrate.cli", "migrate"),
    "format": ("mintlang.cli.formatter", "format_command"),
}
_tables_checked: dict[Path, ProjectSettings] = {}  # a settings file whose every table was checked, as it was then


def typed(context: click.Context, name: str) -> bool:
    """Whether the user gave the option ``name`` (by its parameter name), rather than its default applying."""
    return context.get_parameter_source(name) in _TYPED


def option_chosen(context: click.Context, name: str) -> bool:
    """Whether the option ``name`` was chosen: typed by the user, or given by the settings file (``ProjectCommand``)."""
    return typed(context, name) or name in context.meta.get(_FROM_SETTINGS, ())


def overrides(
    context: click.Context,
    *,
    select: tuple[str, ...] | None,
    extend_select: tuple[str, ...] | None,
    ignore: tuple[str, ...] | None,
    config_path: Path | None,
    no_config: bool,
    exclude: tuple[str, ...] | None = None,
    extend_exclude: tuple[str, ...] | None = None,
    force_exclude: bool | None = None,
) -> Overrides:
    """The options of ``mint check`` the user gave, as the layer above the settings file."""
    if no_config and config_path is not None:
        raise click.UsageError("--config names the configuration file and --no-config pairs none: give one")
    params = context.params
    layer = exclusions(exclude, extend_exclude, force_exclude)
    if no_config:
        layer = without_configuration(layer)
    elif config_path is not None:
        layer = replace(layer, config=Given(config_path, "--config"))
    return replace(
        layer,
        controller=Given(Controller(params["controller"]), "--controller") if typed(context, "controller") else None,
        dialect=Given(Dialect(params["dialect"]), "--dialect") if typed(context, "dialect") else None,
        select=Given(select, "--select") if select is not None else None,
        extend_select=Given(extend_select, "--extend-select") if extend_select is not None else None,
        ignore=Given(ignore, "--ignore") if ignore is not None else None,
    )


def without_configuration(layer: Overrides) -> Overrides:
    """``layer`` with ``--no-config``: each program alone, no configuration file paired with it."""
    return replace(layer, config_pairing=Given(None, "--no-config"), config=Given(None, "--no-config"))


def exclusions(
    exclude: tuple[str, ...] | None, extend_exclude: tuple[str, ...] | None, force_exclude: bool | None
) -> Overrides:
    """``options.exclude_options`` as given (None: not given), as the layer above the settings file; their globs
    are relative to the current folder, as ruff reads them."""
    return Overrides(
        exclude=Given(relative_globs(exclude, Path.cwd()), "--exclude") if exclude is not None else None,
        extend_exclude=Given(relative_globs(extend_exclude, Path.cwd()), "--extend-exclude")
        if extend_exclude is not None
        else None,
        force_exclude=Given(force_exclude, "--force-exclude" if force_exclude else "--no-force-exclude")
        if force_exclude is not None
        else None,
    )


def describe(path: Path, settings: FileSettings) -> list[str]:
    """``--show-settings``: what applies to ``path``, one setting a line with where its value came from."""
    project = settings.project
    rows = [("settings file", str(project.table.path) if project else "none", "")]
    rows += settings.rows()
    _, configuration = settings.partner(path)
    rows.append(("configuration file", str(configuration) if configuration else "none", _how(settings, configuration)))
    width = max(len(name) for name, _, _ in rows)
    value_width = max(len(value) for _, value, _ in rows)
    lines = [f"{path}:"]
    lines += [f"  {name:<{width}}  {value:<{value_width}}  {origin}".rstrip() for name, value, origin in rows]
    return lines


def _how(settings: FileSettings, configuration: Path | None) -> str:
    if configuration is None:
        return ""
    if settings.config.value is not None:
        return f"config ({settings.config.origin})"
    return f"paired by config-pairing ({settings.config_pairing.origin})"


def settings_failed(tool: str, error: SettingsError) -> NoReturn:
    """A settings file that cannot be used ends the command with one line (exit 2)."""
    click.echo(f"{tool}: {error}", err=True)
    sys.exit(_SETTINGS_ERROR)


class ProjectCommand(click.Command):
    """A command whose options default to its table of the settings file, and then to the shared settings.

    ``start(params)`` names where to look for the settings file (the program run,
    the first path migrated). An option the user typed wins over the file.
    ``tool`` names the command in a message (``mint-run``).
    """

    def __init__(
        self, *args: Any, tool: str, table: str, start: Callable[[Mapping[str, Any]], Path], **kwargs: Any
    ) -> None:
        super().__init__(*args, **kwargs)
        self.tool = tool
        self.table = table
        self.start = start

    def invoke(self, ctx: click.Context) -> Any:
        try:
            project = project_for(self.start(ctx.params))
            if project is not None:
                defaults = self._defaults(ctx, project)
                check_tool_tables(project)
                ctx.params.update(defaults)
                ctx.meta[_FROM_SETTINGS] = frozenset(defaults)
        except SettingsError as error:
            settings_failed(self.tool, error)
        return super().invoke(ctx)

    def _defaults(self, context: click.Context, project: ProjectSettings) -> dict[str, Any]:
        options = _options(self)
        table = project.tool(self.table)
        values: dict[str, Any] = {}
        for key in _SHARED:
            if key in options and key in project.values:
                values[options[key].name or key] = str(project.values[key].value)
        for key, value in table.values.items():
            param = _option(table, key, options)
            values[param.name or key] = _converted(context, param, table, key, value)
        return {name: value for name, value in values.items() if not typed(context, name)}


def whole_settings(path: Path, overrides: Overrides) -> FileSettings:
    """What applies to ``path`` (``settings_for``), its settings file checked whole, every tool's table too."""
    settings = settings_for(path, overrides)
    check_tool_tables(settings.project)
    return settings


def check_tool_tables(project: ProjectSettings | None) -> None:
    """Check every tool's table of the settings file, as ruff checks its whole file whatever command runs: a key
    that no option of the tool has, or a value of the wrong kind, stops each tool, not only the one that reads
    the table. What a value means (a scenario file to read) is left to the tool. Raises SettingsError."""
    if project is None or _tables_checked.get(project.table.path) is project:
        return
    for name, (module, command) in _COMMANDS.items():
        table = project.tool(name)
        if table.values:  # the command is imported only for a table the file has
            options = _options(getattr(importlib.import_module(module), command))
            for key, value in table.values.items():
                _shaped(_option(table, key, options), table, key, value)
    _tables_checked[project.table.path] = project


def _options(command: click.Command) -> dict[str, click.Parameter]:
    """A command's options by their long names, the keys of its table; an eager option (--version) does its work
    as it is parsed: no setting can give it."""
    return {
        name.removeprefix("--"): param
        for param in command.params
        if not param.is_eager
        for name in param.opts
        if name.startswith("--")
    }


def _option(table: Table, key: str, options: Mapping[str, click.Parameter]) -> click.Parameter:
    """The option a table's key gives."""
    if key in _TOP_LEVEL_ONLY:  # its globs are the settings file's, not a tool's: one list for every tool
        raise table.error(
            "a setting of every tool: write it beside select, not in a tool's table", key, key_at_fault=True
        )
    param = options.get(key)
    if param is None or param.name is None:
        raise table.error(f"unknown key (known: {', '.join(sorted(options))})", key, key_at_fault=True)
    return param


def _shaped(param: click.Parameter, table: Table, key: str, value: object) -> bool | list[str]:
    """A table value as the option takes it typed: a flag true or false, otherwise a string or a number (a list
    of them for a repeatable option), as text; a path is relative to the settings file's folder."""
    if isinstance(param.type, click.types.BoolParamType):
        if not isinstance(value, bool):
            raise table.error("must be true or false", key)
        return value
    items = value if isinstance(value, list) and param.multiple else [value]
    if not all(isinstance(item, str | int | float) and not isinstance(item, bool) for item in items):
        raise table.error("must be a string or a number" + (", or a list of them" if param.multiple else ""), key)
    return [str(table.relative(key, str(item))) if isinstance(param.type, click.Path) else str(item) for item in items]


def _converted(context: click.Context, param: click.Parameter, table: Table, key: str, value: object) -> Any:
    """A table value as the option's own type converts it."""
    shaped = _shaped(param, table, key, value)
    try:
        if isinstance(shaped, bool) or param.multiple:
            return param.process_value(context, shaped)
        return param.process_value(context, shaped[0])
    except click.BadParameter as error:
        raise table.error(error.message, key) from None
