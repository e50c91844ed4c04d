"""``mint check`` checks a program with the configuration file beside it, as the editor does (``<name>.cfg``
beside ``<name>.mnt``, names in any case); ``--config`` names another, ``--no-config`` none; a configuration file
is reported once, as its programs see it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tests.cli.invoking import mint_check, numbered, records, write

CONFIGURATION = "DIM counter\nDEFINE fast = 500\nDIM spare\n"  # spare: used by no program (W103)
USES_IT = "counter = fast\nPRINT counter\n"


def findings(*arguments: str | Path) -> list[tuple[str, int, str]]:
    """(file name, line, code) of each finding."""
    return [(Path(r["path"]).name, r["line"], numbered(r["code"])) for r in records(*arguments)]


def test_a_program_is_checked_with_the_configuration_file_beside_it(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    assert findings(write(tmp_path / "cell.mnt", USES_IT)) == [("cell.cfg", 3, "W103")]


def test_the_pair_is_found_whatever_the_case_of_the_names(tmp_path: Path) -> None:
    write(tmp_path / "app.cfg", CONFIGURATION)
    assert findings(write(tmp_path / "APP.MNT", USES_IT)) == [("app.cfg", 3, "W103")]


def test_a_directory_run_reports_each_configuration_file_once_before_its_program(tmp_path: Path) -> None:
    write(tmp_path / "a" / "cell.cfg", CONFIGURATION)
    write(tmp_path / "a" / "cell.mnt", USES_IT)
    write(tmp_path / "b" / "lonely.mnt", "counter = 1\n")
    assert findings(tmp_path) == [("cell.cfg", 3, "W103"), ("lonely.mnt", 1, "E3001")]
    assert findings(tmp_path, tmp_path / "a" / "cell.cfg", tmp_path / "a" / "cell.mnt") == findings(tmp_path)


def test_a_configuration_file_named_alone_is_checked_with_its_program(tmp_path: Path) -> None:
    configuration = write(tmp_path / "cell.cfg", CONFIGURATION)
    write(tmp_path / "cell.mnt", USES_IT + "PRINT missing\n")  # the program's own error is not reported
    assert findings(configuration) == [("cell.cfg", 3, "W103")]
    result = mint_check(configuration)
    assert "1 file checked" in result.stdout


def test_a_configuration_file_without_a_program_is_checked_on_its_own(tmp_path: Path) -> None:
    configuration = write(tmp_path / "spare.cfg", "DIM counter\n")
    assert findings(configuration) == [("spare.cfg", 1, "W103")]


def test_no_config_pairs_no_file(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", CONFIGURATION)
    program = write(tmp_path / "cell.mnt", USES_IT)  # each name undeclared once on each line
    assert findings("--no-config", program) == [
        ("cell.mnt", 1, "E3001"),
        ("cell.mnt", 1, "E3001"),
        ("cell.mnt", 2, "E3001"),
    ]


def test_config_names_the_configuration_file_instead_of_the_paired_one(tmp_path: Path) -> None:
    write(tmp_path / "cell.cfg", "DIM other\n")
    shared = write(tmp_path / "shared" / "line.cfg", CONFIGURATION)
    assert findings("--config", shared, write(tmp_path / "cell.mnt", USES_IT)) == [("line.cfg", 3, "W103")]


def test_config_and_no_config_together_are_a_usage_error(tmp_path: Path) -> None:
    result = mint_check("--config", write(tmp_path / "a.cfg", "DIM a\n"), "--no-config", write(tmp_path / "a.mnt", ""))
    assert result.exit_code == 2
    assert "--config names the configuration file and --no-config pairs none" in result.stderr


def test_the_settings_file_can_name_the_pairing_turn_it_off_or_name_one_configuration(tmp_path: Path) -> None:
    program = write(tmp_path / "press.mnt", USES_IT)
    write(tmp_path / "setup_press.txt", CONFIGURATION)
    write(tmp_path / "mint.toml", 'config-pairing = "setup_<name>.txt"\n')
    assert findings(program) == [("setup_press.txt", 3, "W103")]
    write(tmp_path / "press.cfg", CONFIGURATION)
    write(tmp_path / "mint.toml", "config-pairing = false\n")
    assert {code for _, _, code in findings(program)} == {"E3001"}
    write(tmp_path / "shared" / "line.cfg", CONFIGURATION)
    write(tmp_path / "mint.toml", 'config = "shared/line.cfg"\n')  # relative to the settings file
    assert findings(program) == [("line.cfg", 3, "W103")]


def test_a_paired_configuration_that_cannot_be_read_leaves_its_program_unchecked(tmp_path: Path) -> None:
    (tmp_path / "cell.cfg").write_bytes(b"DIM a\x00\x01")
    write(tmp_path / "other.mnt", "PRINT 1\n")
    result = mint_check(write(tmp_path / "cell.mnt", USES_IT), tmp_path / "other.mnt")
    assert result.exit_code == 2
    assert "not checked" in result.stderr
    assert "1 file checked" in result.stdout


def test_the_real_command_pairs_in_a_directory_run(tmp_path: Path) -> None:
    write(tmp_path / "line" / "Cell.CFG", CONFIGURATION)
    write(tmp_path / "line" / "cell.mnt", USES_IT)
    mint = Path(sys.executable).with_name("mint")
    run = subprocess.run([mint, "check", "line"], cwd=tmp_path, capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "2 files checked: 0 errors, 1 warning" in run.stdout
    assert "E3001" not in run.stdout
