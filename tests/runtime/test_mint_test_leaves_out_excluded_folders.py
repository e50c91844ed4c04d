"""``mint test`` searches a folder as ``mint check`` does: a program or a scenario file in a folder the settings
exclude (``build`` by default, ``extend-exclude``) is no test, and a scenario file there is not reported as one
that runs nothing."""

from __future__ import annotations

from pathlib import Path

from mintlang.runtime.testing.discovery import discover

PASSING = "REM @expect a = 2\nDIM a\na = 1 + 1\n"
ORPHAN = '[[expect]]\nwhat = "a"\nequals = 0\n'  # beside no program of its name: it would run nothing


def test_an_excluded_folder_holds_no_tests(tmp_path: Path) -> None:
    for folder in ("", "build", "legacy"):
        (tmp_path / folder).mkdir(exist_ok=True)
        (tmp_path / folder / "a.mnt").write_text(PASSING)
        (tmp_path / folder / "lost.scenario.toml").write_text(ORPHAN)
    (tmp_path / "mint.toml").write_text('extend-exclude = ["legacy"]\n')
    cases, problems = discover([tmp_path])
    assert [case.program for case in cases] == [tmp_path / "a.mnt"]
    assert [problem.message for problem in problems] == [
        f"{tmp_path / 'lost.scenario.toml'}: no program lost.mnt beside it, so it runs nothing"
    ]
