"""A MintMT program given to a tool without ``--dialect`` is read as Mint v4, and its v4 errors never name
the option it needs: ``mint check``, ``mint-run`` and ``mint test`` say it once, on standard error, when the
dialect was chosen by no one (not the command line, not the settings file) and the text shows MintMT's forms.
The hint changes nothing else: the report, on standard output, and the exit status are those of v4, but for
mint check's count of what ``--fix`` would fix, as ``--fix`` leaves such a program as it is.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli.check import check
from mintlang.detection import MintMTForm, first_mintmt_form
from mintlang.runtime.cli import run
from mintlang.runtime.testing.cli import test as mint_test

# MintMT's forms (mintlang/MINTMT.md): a ' comment first, then Dim … As, an event block, round-bracket addressing.
MINTMT = """' cell controller
REM @expect count = 0
Dim count As Integer
Event Comms1
  count = count + 1
End Event
If count = 0 Then
  MOVER(0) = 10
End If
"""
V4 = """REM cell controller
REM @expect count = 0
DIM count
IF count > 0 THEN PRINT "moved"
"""
TOOLS = {"mint check": (check, ("-j", "1")), "mint-run": (run, ()), "mint test": (mint_test, ("-j", "1"))}


def invoke(tool: str, *arguments: str | Path) -> Result:
    command, options = TOOLS[tool]
    return CliRunner().invoke(command, [*options, *(str(argument) for argument in arguments)])


def hints(result: Result) -> list[str]:
    return [line for line in result.stderr.splitlines() if line.startswith("hint:")]


def program(folder: Path, text: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "cell.mnt"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("tool", TOOLS)
def test_a_mintmt_program_gets_one_hint_naming_the_file_what_was_seen_and_the_option(tool: str, tmp_path: Path):
    path = program(tmp_path, MINTMT)
    result = invoke(tool, path)
    assert hints(result) == [
        f"hint: {path} looks like MintMT (a ' comment on line 1) but was read as Mint v4: run with --dialect mintmt"
    ]
    assert "hint:" not in result.stdout


@pytest.mark.parametrize("tool", TOOLS)
def test_the_hint_leaves_the_report_and_the_exit_status_as_an_explicit_v4_gives_them(tool: str, tmp_path: Path):
    path = program(tmp_path, MINTMT)
    hinted, explicit = invoke(tool, path), invoke(tool, "--dialect", "v4", path)
    assert hints(hinted) and not hints(explicit)
    assert hinted.exit_code == explicit.exit_code != 0
    if tool != "mint test":  # its report times the run
        promised = [line for line in explicit.stdout.splitlines(keepends=True) if "fixable with --fix" in line]
        assert hinted.stdout == explicit.stdout.replace("".join(promised), "")


# SUSPEND reads back in MintMT (MT-16); in v4 it is a command (000:17775), so the expectation is refused
SUSPENDED_EXPECTED = "' cell controller\nDim count\n"
DIRECTIVE = "REM @expect SUSPEND(0) = 0\n"
SCENARIO = '[[expect]]\nwhat = "SUSPEND(0)"\nequals = 0\n'


@pytest.mark.parametrize("tool", ["mint-run", "mint test"])
@pytest.mark.parametrize("written", ["in the program", "in a scenario file"])
def test_an_expectation_v4_refuses_still_gets_the_hint(tool: str, written: str, tmp_path: Path):
    if written == "in the program":
        path, arguments = program(tmp_path, SUSPENDED_EXPECTED + DIRECTIVE), ()
    else:
        path = program(tmp_path, SUSPENDED_EXPECTED)
        scenario = tmp_path / "cell.scenario.toml"  # mint test's scenario beside the program; mint-run's --expect
        scenario.write_text(SCENARIO, encoding="utf-8")
        arguments = ("--expect", scenario) if tool == "mint-run" else ()
    result = invoke(tool, path, *arguments)
    assert "SUSPEND is a command" in result.output
    assert result.exit_code != 0
    assert hints(result) == [
        f"hint: {path} looks like MintMT (a ' comment on line 1) but was read as Mint v4: run with --dialect mintmt"
    ]


@pytest.mark.parametrize("tool", TOOLS)
def test_a_v4_program_gets_no_hint(tool: str, tmp_path: Path):
    result = invoke(tool, program(tmp_path, V4))
    assert result.exit_code == 0, result.output
    assert hints(result) == []


@pytest.mark.parametrize("tool", TOOLS)
@pytest.mark.parametrize("dialect", ["v4", "mintmt"])
def test_a_dialect_given_on_the_command_line_gets_no_hint(tool: str, dialect: str, tmp_path: Path):
    assert hints(invoke(tool, "--dialect", dialect, program(tmp_path, MINTMT))) == []


@pytest.mark.parametrize("tool", TOOLS)
def test_a_dialect_given_by_the_settings_file_gets_no_hint(tool: str, tmp_path: Path):
    (tmp_path / "mint.toml").write_text('dialect = "v4"\n', encoding="utf-8")
    result = invoke(tool, program(tmp_path, MINTMT))
    assert "2003" in result.output  # the program was read as v4: its ' comment is a syntax error (E2003, C2003)
    assert hints(result) == []


@pytest.mark.parametrize("tool", TOOLS)
def test_quiet_leaves_the_hint_out(tool: str, tmp_path: Path):
    assert hints(invoke(tool, "--quiet", program(tmp_path, MINTMT))) == []


@pytest.mark.parametrize("output_format", ["json", "sarif"])
def test_a_machine_readable_report_stays_whole_on_standard_output(output_format: str, tmp_path: Path):
    result = invoke("mint check", "--format", output_format, program(tmp_path, MINTMT))
    assert len(hints(result)) == 1
    json.loads(result.stdout)


def test_mint_check_hints_once_per_program_and_not_for_a_v4_one_beside_it(tmp_path: Path):
    mintmt, v4 = program(tmp_path / "mintmt", MINTMT), program(tmp_path / "v4", V4)
    result = invoke("mint check", mintmt, v4, mintmt)
    assert [hint.split()[1] for hint in hints(result)] == [str(mintmt)]


@pytest.mark.parametrize(
    ("text", "form"),
    [
        pytest.param("x = 1\nPRINT x ' the count\n", MintMTForm(2, "a ' comment"), id="comment-after-code"),
        pytest.param("DIM x\nx = 1\nEnd  If\n", MintMTForm(3, "End If"), id="closer-as-written"),
        pytest.param("x = 1\nEvent Comms1\n", MintMTForm(2, "Event Comms1"), id="event-block"),
        pytest.param("Startup\n", MintMTForm(1, "Startup"), id="startup-block"),
        pytest.param("MOVER(0) = 10\n", MintMTForm(1, "MOVER(…)"), id="round-bracket-addressing"),
        pytest.param("PRINT 'A'\n", None, id="v4-character-constant"),
        pytest.param("event = 1\nENDIF\n", None, id="v4-variable-and-closer"),
    ],
)
def test_the_first_mintmt_form_is_named_with_its_line(text: str, form: MintMTForm | None):
    assert first_mintmt_form(text) == form
