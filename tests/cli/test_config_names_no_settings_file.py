"""``--config`` names the Mint configuration file (.cfg) a program sees; ruff's ``--config`` names the settings
file. A ``mint.toml`` or ``pyproject.toml`` given to it is refused with what to do, instead of read as Mint."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main


@pytest.mark.parametrize(
    "settings_file",
    [pytest.param("mint.toml", id="mint.toml"), pytest.param("pyproject.TOML", id="pyproject.toml, any case")],
)
@pytest.mark.parametrize(
    "command",
    [
        pytest.param(["check", "--config", "{settings}", "{program}"], id="check"),
        pytest.param(["run", "{program}", "--config", "{settings}"], id="run"),
        pytest.param(["migrate", "--config", "{settings}", "{program}"], id="migrate"),
    ],
)
def test_a_settings_file_given_as_config_is_refused(tmp_path: Path, command: list[str], settings_file: str) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text("PRINT 1\nEND\n", encoding="utf-8")
    settings = tmp_path / settings_file
    settings.write_text('controller = "mintdrive"\n', encoding="utf-8")
    arguments = [part.format(settings=settings, program=program) for part in command]
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code == 2, result.output
    assert "is a settings file" in result.stderr
    assert "Traceback" not in result.output
