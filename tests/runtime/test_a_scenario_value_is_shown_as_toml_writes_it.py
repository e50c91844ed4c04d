"""A scenario file's value of the wrong type is quoted back as TOML writes it, not as Python prints it.

``channel = true`` was told "not True", a spelling TOML does not have (its booleans are ``true`` and
``false``), and a date "not datetime.date(2026, 11, 29)".
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.scenario import load_scenario
from mintlang.runtime.scenario.problems import ScenarioFileError
from tests.runtime.invoking import write


def _messages(tmp_path: Path, text: str) -> list[str]:
    path = write(tmp_path, "cell.scenario.toml", text)
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    return [error.message for error in raised.value.errors]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[[input]]\nchannel = true\nlevel = 1\nat_ms = 5\n", "channel must be a whole number, not true"),
        ('[[expect]]\nwhat = "OUT.0"\nequals = false\n', "equals must be a number, not false"),
        ("[[key]]\ntext = '1'\nat_ms = 2026-11-29\n", "at_ms must be a whole number, not 2026-11-29"),
        ("[[key]]\ntext = '1'\nat_ms = 07:32:00\n", "at_ms must be a whole number, not 07:32:00"),
        ("[[input]]\nchannel = 1\nlevel = [1, true]\nat_ms = 5\n", "level must be a whole number, not [1, true]"),
        ("[[key]]\ntext = { keys = true }\nat_ms = 5\n", "text must be text in quotes, not { keys = true }"),
        (
            '[[expect]]\nwhat = "OUT.0"\nequals = 0\nat = false\n',
            'at is "end"; for a time write at_ms = <ms>, not at = false',
        ),
        ("drives = true\n", 'drives is "enabled" (without it they start disabled, as at power-up), not true'),
    ],
)
def test_a_wrong_value_is_quoted_in_toml(tmp_path: Path, text: str, message: str) -> None:
    assert _messages(tmp_path, text)[0] == message


def test_text_and_numbers_read_as_before(tmp_path: Path) -> None:
    assert _messages(tmp_path, "[[input]]\nchannel = '3'\nlevel = 1.5\nat_ms = 5\n") == [
        "channel must be a whole number, not '3'"
    ]
