"""``mint-run cell.mnt`` runs ``cell.cfg`` first, paired as ``mint check`` and the editor pair it; ``--config``
names another, ``--no-config`` none; ``[tool.mint.run]`` gives the options' defaults."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.cli.invoking import write

CONFIGURATION = "DIM counter = 5\nDEFINE twice = counter * 2\n"
PROGRAM = "PRINT twice\n"


def mint_run(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["run", *(str(argument) for argument in arguments)])


def test_the_configuration_file_beside_the_program_runs_first(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    result = mint_run(write(tmp_path / "cell.mnt", PROGRAM))
    assert (result.exit_code, result.stdout) == (0, "10\n")


def test_the_pair_is_found_whatever_the_case_of_the_names(tmp_path: Path) -> None:
    write(tmp_path / "Cell.CFG", CONFIGURATION)
    result = mint_run(write(tmp_path / "CELL.mnt", PROGRAM))
    assert (result.exit_code, result.stdout) == (0, "10\n")


def test_a_stop_in_the_configuration_names_the_file_paired(tmp_path: Path) -> None:
    # SCALE = -3 is invalid (000:4600-4602): the paired file, not the one named, stopped the run
    configuration = write(tmp_path / "Cell.CFG", "RESETALL\nSCALE = -3\n")
    result = mint_run(write(tmp_path / "cell.mnt", PROGRAM))
    assert result.exit_code == 1
    assert f"at configuration line 2 ({configuration}): SCALE = -3 — R0003" in result.stderr


def test_no_config_runs_the_program_alone(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    result = mint_run("--no-config", write(tmp_path / "cell.mnt", PROGRAM))
    assert result.exit_code == 1
    assert "3001" in result.stderr  # twice: an undeclared variable without the configuration's DEFINE


def test_config_names_another_configuration(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    other = write(tmp_path / "bench.cfg", "DIM counter = 1\nDEFINE twice = counter * 2\n")
    result = mint_run("--config", other, write(tmp_path / "cell.mnt", PROGRAM))
    assert (result.exit_code, result.stdout) == (0, "2\n")


def test_config_and_no_config_together_are_a_usage_error(tmp_path: Path) -> None:
    other = write(tmp_path / "bench.cfg", CONFIGURATION)
    result = mint_run("--config", other, "--no-config", write(tmp_path / "cell.mnt", PROGRAM))
    assert result.exit_code == 2
    assert "--config names the configuration file and --no-config runs none" in result.stderr


def test_the_settings_files_pairing_applies(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'config-pairing = "<name>_setup.mnc"\n')
    write(tmp_path / "cell_setup.mnc", CONFIGURATION)
    assert mint_run(write(tmp_path / "cell.mnt", PROGRAM)).stdout == "10\n"


def test_the_run_table_gives_the_options_defaults_and_the_command_line_wins(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", "[run]\nuntil-ms = 25\n")
    program = write(tmp_path / "tick.mnt", "LOOP\n  PRINT TIME\n  WAIT = 10\nENDL\n")
    assert mint_run(program).stdout == "0\n10\n20\n"
    assert mint_run("--until-ms", "15", program).stdout == "0\n10\n"


def test_the_shared_controller_applies_unless_the_run_table_or_the_command_line_says_otherwise(tmp_path: Path) -> None:
    program = write(tmp_path / "out.mnt", "OUT10 = 1\n")  # a NextMove PCI output; MintDrive has 0 to 8
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    assert "R0008" in mint_run(program).stderr
    assert mint_run("--controller", "nextmove-pci", program).exit_code == 0
    write(tmp_path / "mint.toml", 'controller = "mintdrive"\n[run]\ncontroller = "nextmove-pci"\n')
    assert mint_run(program).exit_code == 0


def test_a_path_in_the_run_table_is_relative_to_the_settings_file(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[run]\nstimulus = ["scenarios/start.toml"]\n')
    write(tmp_path / "scenarios" / "start.toml", "[[input]]\nat_ms = 5\nchannel = 3\nlevel = 1\n")
    program = write(tmp_path / "cells" / "wait.mnt", 'PAUSE IN3 = 1\nPRINT "started"\n')
    result = mint_run(program)
    assert (result.exit_code, result.stdout) == (0, "started\n"), result.stderr


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        pytest.param(
            '[run]\nuntil-ms = "soon"\n', "2:12: run.until-ms: 'soon' is not a valid integer range.", id="number"
        ),
        pytest.param("[run]\nrealtime = 1\nspeed = 2\n", "2:12: run.realtime: must be true or false", id="flag"),
        pytest.param(
            '[run]\nstimulus = ["a\\u0000.toml"]\n',
            "2:12: run.stimulus: a path cannot hold a NUL character",
            id="nul-path",
        ),
    ],
)
def test_a_bad_run_table_is_one_line_with_its_place(tmp_path: Path, text: str, problem: str) -> None:
    settings = write(tmp_path / "mint.toml", text)
    result = mint_run(write(tmp_path / "a.mnt", "PRINT 1\n"))
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: {settings.absolute()}:{problem}\n"


def test_the_real_command_runs_the_paired_configuration(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    write(tmp_path / "cell.mnt", PROGRAM)
    mint_run_script = Path(sys.executable).with_name("mint-run")
    run = subprocess.run([mint_run_script, "cell.mnt"], cwd=tmp_path, capture_output=True, text=True, check=False)
    assert (run.returncode, run.stdout) == (0, "10\n"), run.stderr
