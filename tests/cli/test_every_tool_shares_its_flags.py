"""Every tool answers ``--version``, ``-h`` and ``--help``, and spells its shared options the same (issue 17, item 7).

The tools run as installed scripts in real processes, as a shell or an editor starts them.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

BIN = Path(sys.executable).parent
TOOLS = {
    "mint": [BIN / "mint"],
    "mint-run": [BIN / "mint-run"],
    "mint-migrate": [BIN / "mint-migrate"],
    "mint-lsp": [BIN / "mint-lsp"],
    "mint-dap": [BIN / "mint-dap"],
    "mint check": [BIN / "mint", "check"],
    "mint run": [BIN / "mint", "run"],
    "mint migrate": [BIN / "mint", "migrate"],
    "mint lsp": [BIN / "mint", "lsp"],
    "mint dap": [BIN / "mint", "dap"],
    "mint test": [BIN / "mint", "test"],
    "mint rule": [BIN / "mint", "rule"],
}
ESCAPE = "\x1b["
COLOUR = re.compile(r"\x1b\[(?:[0-9;]*;)?(?:3[0-8]|9[0-7])[;m]")  # a foreground colour; bold alone is no colour
UNDECLARED = "DIM a\na = 1\nPRINT b\n"  # b: an error (E3001) on line 3
V3 = "HMSPEED.0 = 10\n"  # a Mint v3 keyword: mint-migrate rewrites it (HOMESPEED)
DIVIDES_BY_ZERO = "DIM a = 0\nPRINT 1 / a\n"  # stops on an error when it runs


def run(command: list[str | Path], *arguments: str | Path, **environment: str) -> subprocess.CompletedProcess[str]:
    env = {key: value for key, value in os.environ.items() if key not in ("NO_COLOR", "FORCE_COLOR")} | environment
    return subprocess.run(
        [*map(str, command), *map(str, arguments)], capture_output=True, text=True, timeout=120, env=env, check=False
    )


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("tool", ["mint", "mint-run", "mint-migrate", "mint-lsp", "mint-dap"])
def test_every_script_prints_its_name_and_the_distribution_version(tool: str) -> None:
    from importlib.metadata import version  # noqa: PLC0415

    result = run(TOOLS[tool], "--version")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.strip() == f"{tool}, version {version('mintlang')}"


@pytest.mark.parametrize("tool", [tool for tool in TOOLS if " " in tool])
def test_every_subcommand_prints_the_distribution_version(tool: str) -> None:
    from importlib.metadata import version  # noqa: PLC0415

    result = run(TOOLS[tool], "--version")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.strip().endswith(f", version {version('mintlang')}")


@pytest.mark.parametrize("tool", list(TOOLS))
def test_dash_h_is_help_on_every_tool_and_subcommand(tool: str) -> None:
    short, long = run(TOOLS[tool], "-h"), run(TOOLS[tool], "--help")
    assert short.returncode == long.returncode == 0
    assert short.stdout == long.stdout
    assert short.stdout.startswith("Usage: ")
    assert "-h, --help" in short.stdout


def test_mint_lists_lsp_beside_check_migrate_and_run() -> None:
    commands = run(TOOLS["mint"], "--help").stdout.split("Commands:")[1].split()
    assert {"check", "lsp", "migrate", "run"} <= set(commands)


@pytest.mark.parametrize(
    ("tool", "flags"),
    [
        ("mint check", ["--format", "--output-file", "--exit-zero", "--statistics", "--quiet", "--verbose", "--color"]),
        ("mint-migrate", ["--format", "--output-file", "--exit-zero", "--quiet", "--verbose", "--color"]),
        ("mint-run", ["--format", "--output-file", "--exit-zero", "--quiet", "--verbose", "--color", "--dialect"]),
        ("mint-lsp", ["--quiet", "--verbose"]),
    ],
)
def test_the_shared_options_are_in_every_tools_help(tool: str, flags: list[str]) -> None:
    help_text = run(TOOLS[tool], "--help").stdout
    for flag in flags:
        assert flag in help_text, flag


# ------------------------------------------------------------------ --color


@pytest.mark.parametrize("tool", ["mint check", "mint-run"])
def test_color_always_colours_a_pipe_and_never_or_no_color_does_not(tmp_path: Path, tool: str) -> None:
    program = write(tmp_path, "bad.mnt", UNDECLARED if tool == "mint check" else DIVIDES_BY_ZERO)

    def output(*arguments: str, **environment: str) -> str:
        result = run(TOOLS[tool], program, *arguments, **environment)
        return result.stdout + result.stderr

    assert COLOUR.search(output("--color", "always"))
    assert COLOUR.search(output("--color", "always", NO_COLOR="1"))  # the option wins over the environment
    assert ESCAPE not in output("--color", "never")
    assert ESCAPE not in output()  # auto: a pipe is no terminal
    assert not COLOUR.search(output(FORCE_COLOR="1", NO_COLOR="1"))  # styled, as FORCE_COLOR asks, but not coloured


def test_color_always_keeps_the_report_readable(tmp_path: Path) -> None:
    result = run(TOOLS["mint check"], write(tmp_path, "bad.mnt", UNDECLARED), "--color", "always")
    plain = run(TOOLS["mint check"], write(tmp_path, "bad.mnt", UNDECLARED), "--color", "never")
    assert re.sub(r"\x1b\[[0-9;]*m", "", result.stdout) == plain.stdout


# ---------------------------------------------------- --exit-zero, --output-file, --format


def test_exit_zero_turns_findings_into_0_on_every_tool(tmp_path: Path) -> None:
    bad, v3, failing = (
        write(tmp_path, n, t) for n, t in [("b.mnt", UNDECLARED), ("v3.mnt", V3), ("f.mnt", DIVIDES_BY_ZERO)]
    )
    assert run(TOOLS["mint check"], bad).returncode == 1
    assert run(TOOLS["mint check"], bad, "--exit-zero").returncode == 0
    assert run(TOOLS["mint-migrate"], "--check", v3).returncode == 1
    assert run(TOOLS["mint-migrate"], "--check", v3, "--exit-zero").returncode == 0
    assert run(TOOLS["mint-run"], failing).returncode == 1
    assert run(TOOLS["mint-run"], failing, "--exit-zero").returncode == 0


def test_exit_zero_still_reports_a_usage_problem_with_2(tmp_path: Path) -> None:
    assert run(TOOLS["mint check"], tmp_path / "missing.mnt", "--exit-zero").returncode == 2
    assert run(TOOLS["mint-migrate"], tmp_path / "missing.mnt", "--exit-zero").returncode == 2
    assert run(TOOLS["mint-run"], tmp_path / "missing.mnt", "--exit-zero").returncode == 2


def test_output_file_takes_the_report_of_every_tool(tmp_path: Path) -> None:
    bad, v3, ok = (write(tmp_path, n, t) for n, t in [("b.mnt", UNDECLARED), ("v3.mnt", V3), ("ok.mnt", "PRINT 1\n")])
    checked = run(TOOLS["mint check"], bad, "--format", "json", "--output-file", tmp_path / "check.json")
    assert checked.stdout == ""
    assert [r["line"] for r in json.loads((tmp_path / "check.json").read_text())] == [3]
    migrated = run(TOOLS["mint-migrate"], v3, "--format", "json", "--output-file", tmp_path / "migrate.json")
    assert migrated.stdout == ""
    assert json.loads((tmp_path / "migrate.json").read_text())["totals"]["changed"] == 1
    ran = run(TOOLS["mint-run"], ok, "--format", "json", "--output-file", tmp_path / "run.json")
    assert ran.stdout.startswith("1")  # the program's output; the report goes to the file as well as after it
    assert json.loads((tmp_path / "run.json").read_text())["stopped"] == "end"


@pytest.mark.parametrize("tool", ["mint check", "mint-migrate", "mint-run"])
def test_output_format_is_ruffs_name_for_format(tool: str, tmp_path: Path) -> None:
    program = write(
        tmp_path, "v3.mnt" if tool == "mint-migrate" else "b.mnt", V3 if tool == "mint-migrate" else UNDECLARED
    )
    spelled = run(TOOLS[tool], program, "--output-format", "json")
    assert spelled.stdout == run(TOOLS[tool], program, "--format", "json").stdout
    assert spelled.returncode != 2 and "{" in spelled.stdout


def test_an_output_file_that_cannot_be_written_is_one_line_and_2(tmp_path: Path) -> None:
    bad = write(tmp_path, "b.mnt", UNDECLARED)
    result = run(TOOLS["mint check"], bad, "--output-file", tmp_path / "no" / "such" / "dir.txt")
    assert result.returncode == 2
    assert result.stderr.startswith("mint check: cannot write ") and len(result.stderr.splitlines()) == 1


@pytest.mark.parametrize("tool", ["mint check", "mint-migrate"])
def test_list_options_take_commas_and_repeats_alike(tmp_path: Path, tool: str) -> None:
    if tool == "mint check":
        program = write(tmp_path, "p.mnt", "DIM spare\nPRINT b\n")  # W103 on line 1, E3001 on line 2
        commas = run(TOOLS[tool], program, "--format", "json", "--select", "W103,E3001")
        repeats = run(TOOLS[tool], program, "--format", "json", "--select", "W103", "--select", "E3001")
    else:
        program = write(tmp_path, "p.mnt", V3)
        commas = run(TOOLS[tool], program, "--format", "json", "--only", "nonesuch,other")
        repeats = run(TOOLS[tool], program, "--format", "json", "--only", "nonesuch", "--only", "other")
    assert (commas.returncode, commas.stdout) == (repeats.returncode, repeats.stdout)
    assert commas.stderr == repeats.stderr


@pytest.mark.parametrize("tool", ["mint check", "mint-migrate", "mint-run", "mint-lsp"])
def test_quiet_and_verbose_together_are_a_usage_error(tmp_path: Path, tool: str) -> None:
    program = [] if tool == "mint-lsp" else [write(tmp_path, "b.mnt", V3)]
    result = run(TOOLS[tool], *program, "-q", "-v")
    assert result.returncode == 2 and "--quiet and --verbose" in result.stderr


def test_verbose_adds_to_the_report_and_quiet_takes_from_it(tmp_path: Path) -> None:
    v3, ok = write(tmp_path, "v3.mnt", V3), write(tmp_path, "ok.mnt", "PRINT 1\n")
    migrated = run(TOOLS["mint-migrate"], v3, "-v").stdout
    assert f"{v3}:1 (original line 1): M-REN" in migrated  # each change with its rule (HMSPEED renamed)
    assert "(original line 1): M-REN" not in run(TOOLS["mint-migrate"], v3).stdout  # the totals name it alone
    assert "file: 1 changed" not in run(TOOLS["mint-migrate"], v3, "-q").stdout
    ran = run(TOOLS["mint-run"], ok, "-v")
    assert ran.stdout == "1\n" and "simulated 0 ms in " in ran.stderr
    assert run(TOOLS["mint-run"], ok, "-q").stderr == ""
