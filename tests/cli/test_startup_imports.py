"""Start-up: a tool imports only what the command it was given uses.

``--help`` and ``--version`` of every tool load none of the heavy parts (the parser and
lark's runtime, the rules, the simulator, the migration rules, pygls, rich), and a check that writes
JSON, or text into a pipe (a pre-commit hook, CI), loads the checker but not rich, and
parses with lark's stand-alone runtime and tables, without importing lark. A Mint v4
run into a pipe loads neither rich nor the other dialects' machines nor the host port server,
and a migration without ``--verify`` loads no part of the simulator, nor does the language server
until its run lens is used (most editing sessions never run a program). Each case runs in a fresh
interpreter, which lists the modules it imported; how long start-up takes is measured by
``benchmarks/startup.py``, never here.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

# Runs a tool's main() as its script would, then prints what was imported after the tool's output.
_RUN_AND_LIST_MODULES = """
import importlib, sys
module, *arguments = sys.argv[1:]
sys.argv = [module, *arguments]
try:
    importlib.import_module(module).main()
except SystemExit:
    pass
imported = sorted(sys.modules)
import json
print()
print(json.dumps(imported))
"""

HEAVY = (
    "lark",
    "mintlang.syntax.lark_runtime",
    "mintlang.syntax.parser",
    "mintlang.analysis.rules",
    "mintlang.runtime.interpreter",
    "mintlang.migrate.rules",
    "pygls",
    "rich",
)


def run(module: str, *arguments: str, env: dict[str, str] | None = None) -> tuple[str, list[str]]:
    """What the tool wrote, and the heavy modules (or their packages) it imported."""
    output, imported = run_listing(module, *arguments, env=env)
    return output, loaded(HEAVY, imported)


def run_listing(module: str, *arguments: str, env: dict[str, str] | None = None) -> tuple[str, list[str]]:
    """What the tool wrote to its standard output (a pipe), and every module it imported."""
    command = [sys.executable, "-c", _RUN_AND_LIST_MODULES, module, *arguments]
    finished = subprocess.run(command, capture_output=True, text=True, check=True, env=env)
    output, _, modules = finished.stdout.rpartition("\n\n")
    return output, json.loads(modules)


def loaded(names: tuple[str, ...], imported: list[str]) -> list[str]:
    """Those of ``names`` imported, themselves or a module of theirs."""
    return [name for name in names if any(m == name or m.startswith(f"{name}.") for m in imported)]


@pytest.mark.parametrize(
    "command",
    [
        ("mintlang.cli", "--version"),
        ("mintlang.cli", "check", "--version"),
        ("mintlang.runtime.cli", "--version"),
        ("mintlang.migrate.cli", "--version"),
        ("mintlang.lsp.cli", "--version"),
    ],
    ids=" ".join,
)
def test_version_loads_nothing_heavy(command: tuple[str, ...]) -> None:
    output, imported = run_listing(*command)
    assert "version 0.1.0" in output
    assert loaded(HEAVY, imported) == []
    assert loaded(("importlib.metadata",), imported) == []  # the version is the package's own constant


@pytest.mark.parametrize(
    "command",
    [
        ("mintlang.cli", "--help"),  # lists every command, the tools' too
        ("mintlang.cli", "check", "--help"),
        ("mintlang.cli", "rule", "--help"),
        ("mintlang.cli", "test", "--help"),
        ("mintlang.runtime.cli", "--help"),
        ("mintlang.migrate.cli", "--help"),
        ("mintlang.lsp.cli", "--help"),
    ],
    ids=" ".join,
)
def test_help_loads_nothing_heavy(command: tuple[str, ...]) -> None:
    output, heavy = run(*command)
    assert output.startswith("Usage:")
    assert heavy == []


def test_a_json_check_loads_the_checker_and_not_rich(tmp_path: Path) -> None:
    program = tmp_path / "one_line.mnt"
    program.write_text("SPEED = 10\n", encoding="utf-8")
    output, heavy = run("mintlang.cli", "check", "--format", "json", str(program))
    assert json.loads(output) == []
    assert heavy == ["mintlang.syntax.lark_runtime", "mintlang.syntax.parser", "mintlang.analysis.rules"]


def test_a_text_report_into_a_pipe_loads_no_rich_unless_colour_is_forced(tmp_path: Path) -> None:
    program = tmp_path / "one_line.mnt"
    program.write_text("SPEED = 10\nDIM a\n", encoding="utf-8")
    plain = {key: value for key, value in os.environ.items() if key not in {"FORCE_COLOR", "TTY_COMPATIBLE"}}
    output, heavy = run("mintlang.cli", "check", str(program), env=plain)
    assert "warning[W103]" in output
    assert "\x1b" not in output
    assert "rich" not in heavy
    output, heavy = run("mintlang.cli", "check", str(program), env=plain | {"FORCE_COLOR": "1"})
    assert "\x1b[" in output  # rich decides, and colours
    assert "rich" in heavy


# What a check of a file with no settings file, and nothing misspelt, does not use: importlib.resources (the
# package's data is read through its loader), the TOML reader (a settings file), difflib (--diff, "did you mean"),
# tempfile (--fix writing a file), signal (the workers of -j), lark itself (the parser is its stand-alone runtime),
# logging (the runtime's logger, which lark sets to a level it never logs at), json (the JSON and SARIF reports;
# the keyword database is read from its marshalled copy).
NOT_FOR_A_PLAIN_CHECK = ("importlib.resources", "tomllib", "difflib", "tempfile", "signal", "lark", "logging", "json")


def test_a_plain_check_loads_none_of_what_only_other_checks_use(tmp_path: Path) -> None:
    output, imported = run_into_a_pipe(tmp_path, "mintlang.cli", "SPEED = 10\n", "check")
    assert "0 errors" in output
    assert loaded(NOT_FOR_A_PLAIN_CHECK, imported) == []


def run_into_a_pipe(tmp_path: Path, module: str, program: str, *options: str) -> tuple[str, list[str]]:
    """``run_listing`` of the tool on a file holding ``program``, with no colour forced on the pipe."""
    path = tmp_path / "program.mnt"
    path.write_text(program, encoding="utf-8")
    plain = {key: value for key, value in os.environ.items() if key not in {"FORCE_COLOR", "TTY_COMPATIBLE"}}
    return run_listing(module, *options, str(path), env=plain)


# What a run of one dialect does not use: the others' machines, the host port (--host-port), rich (colour,
# the progress bar on a terminal, the table of expectations), the trace (--trace, --plot), the scenario files'
# reader (--stimulus, --expect), what reads a program's own directives (it has none), the distribution's
# metadata (the plot's hint), logging (as for a check), json (--report json, --report-file).
NOT_FOR_A_PLAIN_V4_RUN = (
    "rich",
    "json",
    "logging",
    "mintlang.runtime.dialects.v3.machine",
    "mintlang.runtime.dialects.mintmt",
    "mintlang.runtime.comms.server",
    "mintlang.runtime.scenario.outcome_table",
    "mintlang.runtime.trace",
    "mintlang.runtime.scenario.files",
    "mintlang.runtime.scenario.directive_bodies",
    "mintlang.runtime.scenario.builders",
    "mintlang.runtime.scenario.phrase",
    "mintlang.extras",
    "socket",
    "importlib.metadata",
)


def test_a_tiny_v4_run_into_a_pipe_loads_only_the_v4_machine(tmp_path: Path) -> None:
    output, imported = run_into_a_pipe(tmp_path, "mintlang.runtime.cli", 'DIM count = 2\nPRINT "count: ", count * 3\n')
    assert output == "count: 6"  # the line the program printed
    assert "mintlang.runtime.dialects.v4" in imported
    assert loaded(NOT_FOR_A_PLAIN_V4_RUN, imported) == []


def test_a_v3_run_loads_the_v3_machine_and_not_mintmts(tmp_path: Path) -> None:
    output, imported = run_into_a_pipe(tmp_path, "mintlang.runtime.cli", "PRINT 1\n", "--dialect", "v3")
    assert output.strip() == "1"
    assert loaded(("mintlang.runtime.dialects.v3.machine", "mintlang.runtime.dialects.mintmt"), imported) == [
        "mintlang.runtime.dialects.v3.machine"
    ]


# What a migration from Mint v3 that flags nothing does not use: the simulator and the scenarios (--verify),
# the MintMT rewrites (--to mintmt), the table of the guides' headings (a flag's citation). It does use rich:
# its text summary is a rich table, into a pipe too. Nor logging, as for a check, nor json (--format json).
NOT_FOR_A_PLAIN_V3_MIGRATION = (
    "logging",
    "json",
    "mintlang.runtime.interpreter",
    "mintlang.runtime.controller",
    "mintlang.runtime.motion",
    "mintlang.runtime.dialects.v3.machine",
    "mintlang.runtime.scenario.directives",
    "mintlang.runtime.scenario.files",
    "mintlang.migrate.verification.runs",
    "mintlang.migrate.mintmt.verification",
    "mintlang.migrate.mintmt.api",
    "mintlang.manual.sections",
)


def test_a_tiny_v3_migration_into_a_pipe_loads_the_rules_and_not_the_simulator(tmp_path: Path) -> None:
    output, imported = run_into_a_pipe(tmp_path, "mintlang.migrate.cli", "PRINT 1\n")
    assert "1 file: 0 changed, 1 unchanged" in output
    assert loaded(("lark", "mintlang.migrate.rules"), imported) == ["mintlang.migrate.rules"]
    assert loaded(NOT_FOR_A_PLAIN_V3_MIGRATION, imported) == []


_CREATE_THE_SERVER = """
import json, sys
from mintlang.lsp.server import create_server
create_server()
print(json.dumps(sorted(sys.modules)))
"""


def test_the_language_server_starts_without_the_simulator() -> None:
    finished = subprocess.run([sys.executable, "-c", _CREATE_THE_SERVER], capture_output=True, text=True, check=True)
    imported = json.loads(finished.stdout)
    assert loaded(("pygls", "mintlang.lsp.features.simulator"), imported) == [
        "pygls",
        "mintlang.lsp.features.simulator",
    ]
    assert loaded(("mintlang.runtime",), imported) == []
