"""An entry of ``select``, ``extend-select``, ``ignore`` or ``per-file-ignores`` that selects nothing is refused
(README, Selecting codes), the blank one too: ``select = [""]`` was read as no entry, so the file selected no
code at all and every check passed, where ``--select ""`` on the command line is refused. ``select = []``,
written so, still selects nothing, as in ruff."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, write

PROGRAM = "PRINT b\n"  # error 3001: b is not declared


@pytest.mark.parametrize(
    ("text", "line", "key"),
    [
        ('select = [""]\n', "1:10", "select"),
        ('extend-select = ["W103", " "]\n', "1:17", "extend-select"),
        ('controller = "mintdrive"\nignore = [""]\n', "2:10", "ignore"),
        ('[per-file-ignores]\n"*.mnt" = [""]\n', "2:11", 'per-file-ignores."*.mnt"'),
    ],
)
def test_a_blank_entry_stops_the_check_at_its_line(tmp_path: Path, text: str, line: str, key: str) -> None:
    settings = write(tmp_path / "mint.toml", text)
    result = mint_check(write(tmp_path / "a.mnt", PROGRAM))
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr.startswith(f"mint check: {settings.absolute()}:{line}: {key}: a blank entry selects no code")


def test_an_empty_list_selects_nothing(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", "select = []\n")
    result = mint_check(write(tmp_path / "a.mnt", PROGRAM))
    assert (result.exit_code, result.stderr) == (0, "")
