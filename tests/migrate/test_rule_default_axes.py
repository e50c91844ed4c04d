"""M-AXES: ``AXES[0,1,2]`` first when the application relies on the default axes before it sets them.

v3 powered up with AXES[0,1,2] (v3:1029-1033), v4 with every axis of the controller (v4:605-608),
so an axis keyword written without its axes (``STOP``, ``GO``, ``SPEED = 10;``, ``x = POS``) would
address others in v4. A file that writes every axis, or names none, reads the same either way.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command
from tests.migrate.helpers import rewritten

NOOP = [
    pytest.param("", id="empty"),
    pytest.param("\n\n", id="blank lines"),
    pytest.param("REM title\nREM nothing else\n", id="comments only"),
    pytest.param("OUT.2 = 1\nWAIT = 100\nOUT.2 = 0\n", id="outputs and a wait"),
    pytest.param("MOVEA[0,1] = 10, 20 : GO[0,1]\nPRINT POS.1\n", id="every axis written"),
    pytest.param("AXES[0]\nSTOP\n", id="sets AXES itself"),
    pytest.param("MOVER.1 = 5 : AXES[0]\nSTOP\n", id="sets AXES before its first bracket-less keyword"),
]
FIXES = [
    pytest.param("STOP\n", "AXES[0,1,2]\nSTOP\n", id="a bracket-less command"),
    pytest.param("SPEED = 10;\n", "AXES[0,1,2]\nSPEED = 10;\n", id="a bracket-less write"),
    pytest.param("PRINT POS\n", "AXES[0,1,2]\nPRINT POS\n", id="a bracket-less read"),
    pytest.param(
        "OUT.2 = 1\nMOVER.0 = 5 : GO\n", "AXES[0,1,2]\nOUT.2 = 1\nMOVER.0 = 5 : GO\n", id="one GO without axes"
    ),
    # the JOG runs on the power-up default (v3:1035-1071) before AXES narrows it
    pytest.param("JOG = 10;\nAXES[0]\n", "AXES[0,1,2]\nJOG = 10;\nAXES[0]\n", id="a bracket-less write before AXES"),
    pytest.param("STOP : AXES[0]\n", "AXES[0,1,2]\nSTOP : AXES[0]\n", id="a command before AXES on its line"),
]


@pytest.mark.parametrize("source", NOOP)
def test_no_axes_line_when_the_default_decides_nothing(source: str) -> None:
    assert rewritten("M-AXES", source, controller="nextmove-pci") == source


@pytest.mark.parametrize(("source", "expected"), FIXES)
def test_an_axis_keyword_without_its_axes_gets_the_v3_default_first(source: str, expected: str) -> None:
    assert rewritten("M-AXES", source, controller="nextmove-pci") == expected


def test_an_axes_of_the_configuration_file_comes_before_the_program() -> None:
    """The configuration file runs first (v3:609), so its AXES sets the program's default."""
    result = migrate("JOG = 10;\n", config="AUTO\nAXES[0,1]\n", only=["M-AXES"], controller="nextmove-pci")
    assert (result.text, result.configuration.text) == ("JOG = 10;\n", "AUTO\nAXES[0,1]\n")


def test_a_program_before_its_own_axes_gets_the_default_in_the_configuration_file() -> None:
    result = migrate("JOG = 10;\nAXES[0]\n", config="AUTO\nSCALE.0 = 2\n", only=["M-AXES"], controller="nextmove-pci")
    assert (result.text, result.configuration.text) == ("JOG = 10;\nAXES[0]\n", "AUTO\nAXES[0,1,2]\nSCALE.0 = 2\n")


@pytest.mark.parametrize("text", ["", "OUT.2 = 1\nWAIT = 100\nOUT.2 = 0\n"], ids=["empty", "outputs and a wait"])
def test_check_passes_on_a_file_valid_in_v3_and_v4_alike(tmp_path: Path, text: str) -> None:
    path = tmp_path / "plain.mnt"
    path.write_text(text)
    result = CliRunner().invoke(command, ["--check", str(path)])
    assert result.exit_code == 0, result.output
    assert path.read_text() == text
