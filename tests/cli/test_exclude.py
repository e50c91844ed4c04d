"""Which files ``mint check`` looks at, with ruff's ``exclude``, ``extend-exclude`` and ``force-exclude``.

A folder searched leaves out what ``exclude`` (by default tools' folders: ``.git``, ``build``, ...) and
every ``extend-exclude`` match: a glob is matched against the path relative to the settings file's folder
(the current folder for the command line's) or against a file's or a folder's name, and an excluded folder
is not entered. A path named is checked all the same, unless ``force-exclude`` is set (pre-commit names
every staged file). Each program below holds an unused variable (W103), so each file checked has a finding.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main
from tests.cli.invoking import mint_check, records, write

SPARE = "DIM spare\n"  # W103 in every file checked

TREE = (
    "main.mnt",
    "src/cell.mnt",
    "src/legacy.mnt",
    "legacy/old.mnt",
    "legacy/v2/new.mnt",
    "cells/legacy/press.mnt",
    "build/copy.mnt",
)


def tree(root: Path, names: tuple[str, ...] = TREE) -> Path:
    for name in names:
        write(root / name, SPARE)
    return root


def checked(root: Path, *arguments: str | Path) -> list[str]:
    """The files with a finding, relative to ``root``, sorted: the files checked."""
    return sorted({Path(record["path"]).absolute().relative_to(root).as_posix() for record in records(*arguments)})


# ------------------------------------------------------------------ the default exclude


@pytest.mark.parametrize(
    "folder",
    [".git", ".hg", ".svn", ".venv", "venv", "node_modules", "build", "dist", "__pycache__", ".mypy_cache", ".tox"],
)
def test_the_default_exclude_leaves_out_tools_folders(tmp_path: Path, folder: str) -> None:
    tree(tmp_path, ("main.mnt", f"{folder}/copy.mnt", f"src/{folder}/deeper/copy.mnt"))
    assert checked(tmp_path, tmp_path) == ["main.mnt"]


def test_a_folder_named_like_a_default_is_left_out_only_as_a_folder(tmp_path: Path) -> None:
    """``build`` is a name: a file ``build.mnt`` or a folder ``builds`` is not it."""
    tree(tmp_path, ("build.mnt", "builds/a.mnt", "build/a.mnt"))
    assert checked(tmp_path, tmp_path) == ["build.mnt", "builds/a.mnt"]


# ------------------------------------------------------------------ the settings file


@pytest.mark.parametrize(
    ("glob", "expected"),
    [
        pytest.param(
            "legacy",
            ["build/copy.mnt", "main.mnt", "src/cell.mnt", "src/legacy.mnt"],
            id="a name: each folder of that name, not entered; not legacy.mnt",
        ),
        pytest.param(
            "legacy/old.mnt",
            [
                "build/copy.mnt",
                "cells/legacy/press.mnt",
                "legacy/v2/new.mnt",
                "main.mnt",
                "src/cell.mnt",
                "src/legacy.mnt",
            ],
            id="a path relative to the settings file's folder: that file",
        ),
        pytest.param(
            "LEGACY/OLD.MNT",
            [
                "build/copy.mnt",
                "cells/legacy/press.mnt",
                "legacy/v2/new.mnt",
                "main.mnt",
                "src/cell.mnt",
                "src/legacy.mnt",
            ],
            id="without regard to case, as Mint's file names",
        ),
        pytest.param(
            "legacy*",
            ["build/copy.mnt", "main.mnt", "src/cell.mnt"],
            id="a wildcard name: the folders and legacy.mnt",
        ),
        pytest.param(
            "./src/*",
            ["build/copy.mnt", "cells/legacy/press.mnt", "legacy/old.mnt", "legacy/v2/new.mnt", "main.mnt"],
            id="./ is the settings file's folder",
        ),
        pytest.param(
            "**/v2",
            [
                "build/copy.mnt",
                "cells/legacy/press.mnt",
                "legacy/old.mnt",
                "main.mnt",
                "src/cell.mnt",
                "src/legacy.mnt",
            ],
            id="**/ is any folders, or none",
        ),
        pytest.param(
            "cells/legacy",
            ["build/copy.mnt", "legacy/old.mnt", "legacy/v2/new.mnt", "main.mnt", "src/cell.mnt", "src/legacy.mnt"],
            id="a folder by its path: that one only",
        ),
    ],
)
def test_exclude_replaces_the_default_with_its_globs(tmp_path: Path, glob: str, expected: list[str]) -> None:
    write(tree(tmp_path) / "mint.toml", f'exclude = ["{glob}"]\n')
    assert checked(tmp_path, tmp_path) == expected


def test_extend_exclude_adds_to_the_default(tmp_path: Path) -> None:
    write(tree(tmp_path) / "mint.toml", 'extend-exclude = ["legacy"]\n')
    assert checked(tmp_path, tmp_path) == ["main.mnt", "src/cell.mnt", "src/legacy.mnt"]


def test_extend_exclude_adds_to_the_files_exclude(tmp_path: Path) -> None:
    write(tree(tmp_path) / "mint.toml", 'exclude = ["src"]\nextend-exclude = ["legacy"]\n')
    assert checked(tmp_path, tmp_path) == ["build/copy.mnt", "main.mnt"]


def test_an_empty_exclude_leaves_out_nothing(tmp_path: Path) -> None:
    write(tree(tmp_path, ("main.mnt", "build/copy.mnt", ".git/copy.mnt")) / "mint.toml", "exclude = []\n")
    assert checked(tmp_path, tmp_path) == [".git/copy.mnt", "build/copy.mnt", "main.mnt"]


def test_globs_are_relative_to_the_settings_files_folder_not_the_folder_searched(tmp_path: Path) -> None:
    write(tree(tmp_path) / "mint.toml", 'extend-exclude = ["cells/legacy"]\n')
    assert checked(tmp_path, tmp_path / "cells", tmp_path / "src") == ["src/cell.mnt", "src/legacy.mnt"]


def test_a_folders_entries_are_judged_by_the_nearest_settings_file(tmp_path: Path) -> None:
    """The nearest settings file applies whole, to what a walk finds as to what it checks."""
    tree(tmp_path, ("old/a.mnt", "line/old/b.mnt", "line/c.mnt"))
    write(tmp_path / "mint.toml", 'extend-exclude = ["old"]\n')
    write(tmp_path / "line" / "mint.toml", 'controller = "mintdrive"\n')
    assert checked(tmp_path, tmp_path) == ["line/c.mnt", "line/old/b.mnt"]


# ------------------------------------------------------------------ the command line


def test_exclude_on_the_command_line_replaces_the_files_and_the_default(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write(tree(tmp_path) / "mint.toml", 'exclude = ["src"]\n')
    monkeypatch.chdir(tmp_path)  # the command line's globs are relative to the current folder
    assert checked(tmp_path, "--exclude", "legacy/v2,cells", ".") == [
        "build/copy.mnt",
        "legacy/old.mnt",
        "main.mnt",
        "src/cell.mnt",
        "src/legacy.mnt",
    ]


def test_extend_exclude_on_the_command_line_adds_to_the_files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    write(tree(tmp_path) / "mint.toml", 'extend-exclude = ["src"]\n')
    monkeypatch.chdir(tmp_path)
    assert checked(tmp_path, "--extend-exclude", "cells", "--extend-exclude", "legacy/old.mnt", ".") == [
        "legacy/v2/new.mnt",
        "main.mnt",
    ]


# ------------------------------------------------------------------ paths named


@pytest.mark.parametrize(
    ("settings", "options", "expected"),
    [
        pytest.param("", (), ["build/copy.mnt", "legacy/old.mnt", "main.mnt"], id="named: checked"),
        pytest.param("", ("--force-exclude",), ["main.mnt"], id="--force-exclude"),
        pytest.param("force-exclude = true\n", (), ["main.mnt"], id="force-exclude in the file"),
        pytest.param(
            "force-exclude = true\n",
            ("--no-force-exclude",),
            ["build/copy.mnt", "legacy/old.mnt", "main.mnt"],
            id="--no-force-exclude wins",
        ),
    ],
)
def test_a_path_named_is_checked_unless_force_exclude(
    tmp_path: Path, settings: str, options: tuple[str, ...], expected: list[str]
) -> None:
    """``build/copy.mnt`` is excluded by its folder (a default), ``legacy/old.mnt`` by its own path."""
    write(tree(tmp_path) / "mint.toml", f'extend-exclude = ["legacy/old.mnt"]\n{settings}')
    named = [tmp_path / "build" / "copy.mnt", tmp_path / "legacy" / "old.mnt", tmp_path / "main.mnt"]
    assert checked(tmp_path, *options, *named) == expected


def test_a_folder_named_is_searched_unless_force_exclude(tmp_path: Path) -> None:
    write(tree(tmp_path) / "mint.toml", "")  # the project's top: the folders above tmp_path are not looked at
    assert checked(tmp_path, tmp_path / "build") == ["build/copy.mnt"]
    assert checked(tmp_path, "--force-exclude", tmp_path / "build", tmp_path / "src") == [
        "src/cell.mnt",
        "src/legacy.mnt",
    ]


def test_force_exclude_looks_no_higher_than_the_settings_files_folder(tmp_path: Path) -> None:
    """The project may itself sit in a folder named ``build``: only what is below its settings file counts."""
    project = tree(tmp_path / "build" / "line", ("main.mnt",))
    write(project / "mint.toml", "force-exclude = true\n")
    assert checked(project, project / "main.mnt") == ["main.mnt"]


def test_nothing_left_to_check_by_force_exclude_is_no_failure(tmp_path: Path) -> None:
    """pre-commit hands over only excluded files: the commit goes on, as with ruff."""
    write(tree(tmp_path) / "mint.toml", "force-exclude = true\n")
    result = mint_check(tmp_path / "build" / "copy.mnt")
    assert result.exit_code == 0
    assert result.stdout == ""
    assert (
        result.stderr == f"mint check: nothing to check: force-exclude leaves out {tmp_path / 'build' / 'copy.mnt'}\n"
    )


def test_standard_input_named_as_an_excluded_file_is_left_out_with_force_exclude(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An editor pipes its buffer with --stdin-filename: under force-exclude an excluded name is not checked,
    as ruff does; without it the buffer is checked as a file named directly is."""
    write(tmp_path / "mint.toml", "")
    monkeypatch.chdir(tmp_path)
    named = ("-", "--stdin-filename", "build/copy.mnt")
    runner = CliRunner()
    left_out = runner.invoke(main, ["check", "--force-exclude", *named], input=SPARE)
    assert (left_out.exit_code, left_out.stdout) == (0, "")
    assert left_out.stderr == "mint check: nothing to check: force-exclude leaves out build/copy.mnt\n"
    checked_anyway = runner.invoke(main, ["check", *named], input=SPARE)
    assert checked_anyway.exit_code == 0
    assert "W103" in checked_anyway.stdout


def test_nothing_found_that_nothing_excluded_is_still_a_failure(tmp_path: Path) -> None:
    tree(tmp_path, ("build/copy.mnt",))
    result = mint_check(tmp_path)
    assert result.exit_code == 2
    assert result.stderr == f"mint check: no .mnt files found in {tmp_path}\n"


# ------------------------------------------------------------------ bad values


@pytest.mark.parametrize(
    ("text", "column", "message"),
    [
        ('exclude = "legacy"\n', 11, 'exclude: must be a list of globs, such as ["legacy", "vendor/*.mnt"]'),
        (
            'extend-exclude = ["legacy", 3]\n',
            18,
            'extend-exclude: must be a list of globs, such as ["legacy", "vendor/*.mnt"]',
        ),
        ('force-exclude = "yes"\n', 17, "force-exclude: must be true or false"),
    ],
)
def test_a_bad_value_is_one_line_naming_the_key(tmp_path: Path, text: str, column: int, message: str) -> None:
    """Placed at the value, its line and column."""
    settings = write(tmp_path / "mint.toml", text)
    result = mint_check(write(tmp_path / "a.mnt", SPARE))
    assert result.exit_code == 2
    assert result.stderr == f"mint check: {settings.absolute()}:1:{column}: {message}\n"
