"""Finding and reading the settings file: the nearest above a file, ``mint.toml`` before ``pyproject.toml``, the
line of each key for messages, a file read again once it changes."""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.cli.settings import check_tool_tables
from mintlang.settings import SettingsError, settings_for
from mintlang.settings.files import find_settings, key_places


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_key_places_follow_tables_dotted_and_quoted_keys() -> None:
    """Each key's line, its column and its value's column: a message places an unknown key at the key and a bad
    value at the value; a table, at its name."""
    text = (
        "# settings\n"  # 1
        'controller = "mintdrive"\n'  # 2
        "[ tool . mint ]\n"  # 3
        'select = ["E",\n'  # 4
        '  "W"]\n'  # 5
        "run.until-ms = 5\n"  # 6
        "[tool.mint.per-file-ignores]\n"  # 7
        '"legacy/*.mnt" = ["W103"]\n'  # 8
        "'raw.mnt' = []\n"  # 9
        "[[tool.other]]\n"  # 10
        "x = 1\n"  # 11
    )
    places = {key: (place.line, place.column, place.value_column) for key, place in key_places(text).items()}
    assert places[("controller",)] == (2, 1, 14)
    assert places[("tool",)] == (3, 3, 3)
    assert places[("tool", "mint")] == (3, 10, 10)
    assert places[("tool", "mint", "select")] == (4, 1, 10)
    assert places[("tool", "mint", "run")] == (6, 1, 1)
    assert places[("tool", "mint", "run", "until-ms")] == (6, 5, 16)
    assert places[("tool", "mint", "per-file-ignores", "legacy/*.mnt")] == (8, 1, 18)
    assert places[("tool", "mint", "per-file-ignores", "raw.mnt")] == (9, 1, 13)
    assert places[("tool", "other", "x")] == (11, 1, 5)
    assert ("W",) not in places  # an array's continuation is no key


def test_the_nearest_folder_with_settings_wins(tmp_path: Path) -> None:
    outer = write(tmp_path / "mint.toml", "")
    write(tmp_path / "a" / "pyproject.toml", '[project]\nname = "a"\n')  # no [tool.mint]: passed over
    inner = write(tmp_path / "a" / "b" / "pyproject.toml", "[tool.mint]\n")
    assert find_settings(tmp_path / "a" / "x.mnt").path == outer
    assert find_settings(tmp_path / "a" / "b" / "c" / "x.mnt").path == inner
    beside = write(tmp_path / "a" / "b" / "mint.toml", "")
    assert find_settings(tmp_path / "a" / "b" / "x.mnt").path == beside


def test_a_folder_is_searched_from_itself(tmp_path: Path) -> None:
    settings = write(tmp_path / "line" / "mint.toml", "")
    assert find_settings(tmp_path / "line").path == settings


def test_a_changed_file_is_read_again(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", 'controller = "mintdrive"\n')
    program = tmp_path / "a.mnt"
    assert settings_for(program).controller.value == "mintdrive"
    settings.write_text('controller = "nextmove-bx"\n', encoding="utf-8")
    assert settings_for(program).controller.value == "nextmove-bx"


def test_a_file_that_is_not_utf8_is_an_error_naming_it(tmp_path: Path) -> None:
    settings = tmp_path / "mint.toml"
    settings.write_bytes(b'controller = "caf\xe9"\n')
    with pytest.raises(SettingsError) as raised:
        settings_for(tmp_path / "a.mnt")
    assert str(raised.value) == f"{settings.absolute()}: not UTF-8 text, as TOML must be"


def test_tool_mint_that_is_no_table_is_an_error(tmp_path: Path) -> None:
    settings = write(tmp_path / "pyproject.toml", '[tool]\nmint = "yes"\n')
    with pytest.raises(SettingsError) as raised:
        settings_for(tmp_path / "a.mnt")
    assert str(raised.value) == f"{settings.absolute()}:2:8: tool.mint: must be a table"


def test_config_is_relative_to_the_settings_file_and_origins_name_the_line(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", '\nconfig = "shared/line.cfg"\n')
    applied = settings_for(tmp_path / "cells" / "a.mnt")
    assert applied.config.value == tmp_path.absolute() / "shared" / "line.cfg"
    assert applied.config.origin == f"{settings.absolute()}:2"


@pytest.mark.parametrize(
    ("text", "place", "key"),
    [
        ('per-file-ignores = { "a.mnt" = ["Q1"] }\n', "1:20", 'per-file-ignores."a.mnt"'),  # at the table's value
        ("\nrun = { untl-ms = 3 }\n", "2:1", "run.untl-ms"),  # an unknown key: at the table's key
    ],
)
def test_a_key_of_an_inline_table_is_placed_at_its_table(tmp_path: Path, text: str, place: str, key: str) -> None:
    """The scan finds no line for a key written inside ``{ }``: the error is placed where its table is."""
    settings = write(tmp_path / "mint.toml", text)
    with pytest.raises(SettingsError) as raised:
        check_tool_tables(settings_for(tmp_path / "a.mnt").project)
    assert str(raised.value).startswith(f"{settings.absolute()}:{place}: {key}: ")


def test_a_value_in_an_inline_table_names_its_tables_line_as_its_origin(tmp_path: Path) -> None:
    """--show-settings says where each value came from: inside braces, the line the table is written on."""
    settings = write(tmp_path / "mint.toml", 'controller = "mintdrive"\nper-file-ignores = { "*.mnt" = ["W103"] }\n')
    [(glob, given)] = settings_for(tmp_path / "a.mnt").per_file_ignores
    assert (glob, given.origin) == ("*.mnt", f"{settings.absolute()}:2")
