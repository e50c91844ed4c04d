"""``mint-migrate`` searches a folder as ``mint check`` does: what the settings exclude (``build`` by default,
``extend-exclude``) is not migrated, and a path named is migrated unless ``force-exclude`` is set. The options
of the same names say it on the command line, their globs relative to the current folder as ruff's; a tool's
own table cannot, its globs would have no folder to be relative to."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"


def migrated(root: Path, *arguments: Path | str) -> list[str]:
    """The files the JSON report lists, relative to ``root``, sorted."""
    result = CliRunner().invoke(command, ["--format", "json", *(str(argument) for argument in arguments)])
    assert result.exit_code in (0, 1), result.output
    return sorted(
        Path(file["path"]).absolute().relative_to(root).as_posix() for file in json.loads(result.stdout)["files"]
    )


@pytest.mark.parametrize(
    ("settings", "named", "expected"),
    [
        pytest.param("", (".",), ["main.mnt"], id="a folder: build and legacy left out"),
        pytest.param("", ("main.mnt", "build/copy.mnt"), ["build/copy.mnt", "main.mnt"], id="named: migrated"),
        pytest.param("force-exclude = true\n", ("main.mnt", "build/copy.mnt"), ["main.mnt"], id="force-exclude"),
        pytest.param("force-exclude = true\n", ("build/copy.mnt",), [], id="nothing left: no failure"),
    ],
)
def test_what_the_settings_exclude_is_not_migrated(
    tmp_path: Path, settings: str, named: tuple[str, ...], expected: list[str]
) -> None:
    for name in ("main.mnt", "build/copy.mnt", "legacy/old.mnt"):
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).write_text(V3)
    (tmp_path / "mint.toml").write_text(f'extend-exclude = ["legacy"]\n{settings}')
    assert migrated(tmp_path, *(tmp_path / name for name in named)) == expected


def tree(root: Path, settings: str = "") -> None:
    for name in ("main.mnt", "build/copy.mnt", "legacy/old.mnt"):
        (root / name).parent.mkdir(exist_ok=True)
        (root / name).write_text(V3)
    (root / "mint.toml").write_text(settings)


@pytest.mark.parametrize(
    ("options", "expected"),
    [
        pytest.param(("--exclude", "legacy"), ["build/copy.mnt", "main.mnt"], id="exclude replaces the default"),
        pytest.param(("--extend-exclude", "legacy"), ["main.mnt"], id="extend-exclude adds to it"),
        pytest.param(("--exclude", "legacy,build"), ["main.mnt"], id="comma-separated"),
        pytest.param(("--force-exclude", "--exclude", "legacy", "legacy/old.mnt"), [], id="force-exclude, named"),
        pytest.param(("legacy/old.mnt",), ["legacy/old.mnt"], id="named without force-exclude"),
    ],
)
def test_the_options_exclude_over_the_settings(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, options: tuple[str, ...], expected: list[str]
) -> None:
    tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    named = () if options[-1].endswith(".mnt") else (".",)
    assert migrated(tmp_path, *options, *named) == expected


def test_a_tools_table_cannot_exclude(tmp_path: Path) -> None:
    tree(tmp_path, '[migrate]\nexclude = ["legacy"]\n')
    result = CliRunner().invoke(command, [str(tmp_path)])
    assert result.exit_code == 2
    message = "migrate.exclude: a setting of every tool: write it beside select, not in a tool's table"
    assert result.stderr == f"mint-migrate: {tmp_path / 'mint.toml'}:2:1: {message}\n"
