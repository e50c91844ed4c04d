"""``mint test`` takes ``mint check``'s ``--no-config``, ``--exclude``, ``--extend-exclude`` and ``--force-exclude``,
meaning what they mean there: a program run alone, and what the folders searched leave out (globs relative to
the current folder, as ruff's)."""

from __future__ import annotations

from pathlib import Path
from xml.etree import ElementTree

import pytest
from click.testing import CliRunner

from mintlang.cli import main

EXPECTS_TWO = "REM @expect a = 2\nDIM a = 2\n"


def tree(root: Path) -> None:
    for folder, name, text in (
        ("cell", "cell.cfg", "DIM b = 3\n"),
        ("cell", "cell.mnt", "REM @expect b = 3\nPRINT b\n"),  # b is declared by its configuration file
        ("legacy", "old.mnt", EXPECTS_TWO),
        ("spare", "copy.mnt", EXPECTS_TWO),
    ):
        (root / folder).mkdir(exist_ok=True)
        (root / folder / name).write_text(text)


def ran(*arguments: str) -> tuple[int, list[str]]:
    result = CliRunner().invoke(main, ["test", "-j", "1", "--format", "junit", *arguments])
    cases = ElementTree.fromstring(result.stdout).iter("testcase")
    return result.exit_code, [f"{case.get('classname')}/{case.get('name')}" for case in cases]


@pytest.mark.parametrize(
    ("options", "expected"),
    [
        pytest.param((), ["cell/cell.mnt", "legacy/old.mnt", "spare/copy.mnt"], id="everything"),
        pytest.param(("--exclude", "legacy"), ["cell/cell.mnt", "spare/copy.mnt"], id="exclude"),
        pytest.param(("--extend-exclude", "legacy,spare"), ["cell/cell.mnt"], id="extend-exclude"),
        pytest.param(("--extend-exclude", "legacy", "legacy/old.mnt"), ["legacy/old.mnt"], id="named"),
    ],
)
def test_the_exclusions_leave_out_folders(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, options: tuple[str, ...], expected: list[str]
) -> None:
    tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    named = () if options and options[-1].endswith(".mnt") else (".",)
    code, names = ran(*options, *named)
    assert (code, sorted(names)) == (0, expected)


def test_force_exclude_leaves_out_a_path_named(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    assert ran("--force-exclude", "--exclude", "legacy", "legacy/old.mnt", "spare/copy.mnt")[1] == ["spare/copy.mnt"]


def test_no_config_runs_the_program_without_its_configuration_file(tmp_path: Path) -> None:
    tree(tmp_path)
    assert ran(str(tmp_path / "cell"))[0] == 0
    result = CliRunner().invoke(main, ["test", "-j", "1", "--no-config", str(tmp_path / "cell")])
    assert result.exit_code == 1
    assert "C3001: PROGRAM Variable undefined, use DIM: 'b' is not declared [line 2]" in result.stdout
