"""Stimulus for an axis or channel the controller lacks is a mistake at its line, not a vanished or crashed run."""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.controllers import profile
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import ScenarioFileError, load_scenario, parse_directives

BX = profile("nextmove-bx")  # axes 0-7, inputs 0-15, ADC 0-7, fast inputs 0-3


@pytest.mark.parametrize(
    ("directive", "message"),
    [
        ("plant 8 torque", "the NextMove BX has no axis 8 (it has axes 0 to 7)"),
        ("index 9 every 100", "the NextMove BX has no axis 9 (it has axes 0 to 7)"),
        ("input 16 1 at 5", "the NextMove BX has no input 16 (it has inputs 0 to 15)"),
        ("input 20 when enc 0 >= 5", "the NextMove BX has no input 20 (it has inputs 0 to 15)"),
        ("input 5 when enc 99 >= 5", "the NextMove BX has no axis 99 (it has axes 0 to 7)"),
        ("fastin 4 at 1", "the NextMove BX has no fast input 4 (it has fast inputs 0, 1, 2, 3)"),
        ("adc 8 50 at 1", "the NextMove BX has no ADC channel 8 (it has ADC channels 0 to 7)"),
    ],
)
def test_a_directive_beyond_the_controller_is_an_error_at_its_line(directive: str, message: str) -> None:
    _, errors = parse_directives(f"PRINT 1\nREM @sim {directive}\n", controller=BX)
    assert [(error.line, error.message) for error in errors] == [(2, message)]


def test_the_same_directive_fits_a_controller_that_has_the_channel() -> None:
    _, errors = parse_directives("REM @sim input 20 1 at 5\n", controller=profile("nextmove-pci"))
    assert errors == []


def test_a_file_entry_beyond_the_controller_names_the_line_of_its_channel_or_axis(tmp_path: Path) -> None:
    path = tmp_path / "ranges.toml"
    path.write_text(
        "[[input]]\nchannel = 1\nlevel = 1\nat_ms = 5\n\n[[adc]]\npercent = 5\nchannel = 50\nat_ms = 1\n"
        "\n[[input]]\nchannel = 2\nwhen = 'enc 99 >= 5'\n\n[[index]]\nevery = 100\naxis = 9\n"
    )
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path, BX)
    assert [(error.line, error.message) for error in raised.value.errors] == [
        (8, "the NextMove BX has no ADC channel 50 (it has ADC channels 0 to 7)"),
        (13, "the NextMove BX has no axis 99 (it has axes 0 to 7)"),
        (17, "the NextMove BX has no axis 9 (it has axes 0 to 7)"),
    ]


def test_a_run_refuses_a_position_input_on_a_missing_axis_before_it_starts() -> None:
    with pytest.raises(ScenarioFileError, match="program:1:18: the NextMove BX has no axis 99"):
        run_source("REM @sim input 5 when enc 99 >= 5\nWAIT = 10\n", controller="nextmove-bx")
