"""``mint-migrate`` searches a folder as ``mint check`` does: what the settings exclude (``build`` by default,
``extend-exclude``) is not migrated, and a path named is migrated unless ``force-exclude`` is set."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"


def migrated(root: Path, *arguments: Path) -> list[str]:
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
