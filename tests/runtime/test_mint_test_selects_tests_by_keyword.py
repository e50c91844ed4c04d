"""``mint test -k``: a keyword expression selects tests by their path, as pytest's ``-k`` selects by name."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from mintlang.runtime.testing.selection import KeywordError, selector

PASSING = "REM @expect a = 2\nDIM a\na = 1 + 1\n"
PATHS = ("lines/Conveyor_jam.mnt", "lines/slow/conveyor_start.mnt", "press/press_v3.mnt", "and/or.mnt")


def _selected(expression: str) -> list[str]:
    selects = selector(expression)
    return [path for path in PATHS if selects(path)]


@pytest.mark.parametrize(
    ("expression", "selected"),
    [
        ("conveyor", ["lines/Conveyor_jam.mnt", "lines/slow/conveyor_start.mnt"]),
        ("CONVEYOR", ["lines/Conveyor_jam.mnt", "lines/slow/conveyor_start.mnt"]),  # any case, either side
        ("not conveyor", ["press/press_v3.mnt", "and/or.mnt"]),
        ("conveyor and not slow", ["lines/Conveyor_jam.mnt"]),
        ("jam or press", ["lines/Conveyor_jam.mnt", "press/press_v3.mnt"]),
        ("lines/slow", ["lines/slow/conveyor_start.mnt"]),  # a folder and a file, as the report shows the path
        ("_v3.mnt", ["press/press_v3.mnt"]),
        ("press or jam and slow", ["press/press_v3.mnt"]),  # and binds tighter: press or (jam and slow)
        ("(press or jam) and slow", []),
        ("not jam and lines", ["lines/slow/conveyor_start.mnt"]),  # not binds tighter: (not jam) and lines
        ("not (jam and lines)", ["lines/slow/conveyor_start.mnt", "press/press_v3.mnt", "and/or.mnt"]),
        ("not not press", ["press/press_v3.mnt"]),
        ("AND", ["and/or.mnt"]),  # the keywords are lower case: AND is a name, and "or" in a longer name no keyword
        ("order or android", []),
        ("", list(PATHS)),  # a blank expression selects every test, as pytest's empty -k
        (" \t", list(PATHS)),
    ],
)
def test_an_expression_selects_the_paths_that_contain_its_names(expression: str, selected: list[str]) -> None:
    assert _selected(expression) == selected


@pytest.mark.parametrize(
    ("expression", "message"),
    [
        ("jam and", "at column 8: the expression ends where a name, 'not' or '(' should follow"),
        ("not", "at column 4: the expression ends where a name, 'not' or '(' should follow"),
        ("jam press", "at column 5: expected 'and' or 'or', not 'press'"),
        ("(jam or press", "at column 14: the expression ends where ')' should follow"),
        ("jam)", "at column 4: ')' closes no '('"),
        ("jam or (press and not)", "at column 22: expected a name, 'not' or '(', not ')'"),
        ("jam && press", "at column 5: '&' is written 'and'"),
        ("jam || press", "at column 5: '|' is written 'or'"),
        ("!jam", "at column 1: '!' is written 'not'"),
        ("jam#1", "at column 4: a name is letters, digits and _ : + - . [ ] \\ /, not '#'"),
    ],
)
def test_an_expression_that_cannot_be_read_says_where_and_what_would_do(expression: str, message: str) -> None:
    with pytest.raises(KeywordError) as error:
        selector(expression)
    assert str(error.value) == message


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Three tests, named relative to the current folder (a temporary folder's own name holds the test's)."""
    for name in ("lines/conveyor_jam.mnt", "lines/slow/conveyor_start.mnt", "press/press.mnt"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(PASSING, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def _mint_test(*arguments: str) -> Result:
    return CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", *arguments])


def test_k_runs_the_selected_tests_and_counts_those_left_out(project: Path) -> None:
    result = _mint_test("-k", "conveyor and not slow")
    lines = result.output.splitlines()
    assert result.exit_code == 0
    assert lines[0] == f"PASSED {Path('lines', 'conveyor_jam.mnt')}"
    assert lines[1].startswith("1 passed, 2 deselected in ")
    assert len(lines) == 2


def test_k_selects_what_collect_only_lists(project: Path) -> None:
    result = _mint_test("--collect-only", "-k", "PRESS or slow")
    assert result.exit_code == 0
    selected = [Path("lines", "slow", "conveyor_start.mnt"), Path("press", "press.mnt")]
    assert result.output.splitlines() == [str(path) for path in selected]


def test_k_selecting_no_test_says_so_and_exits_5_as_no_test_found_does(project: Path) -> None:
    result = CliRunner().invoke(main, ["test", "-j", "1", "-k", "[jam]"])  # brackets shown as written
    assert result.exit_code == 5
    assert result.stderr == "mint test: -k '[jam]' selected none of the 3 tests found\n"


def test_k_selecting_no_test_beside_an_unreadable_path_exits_2_as_no_test_found_does(project: Path) -> None:
    result = CliRunner().invoke(main, ["test", "-j", "1", "-k", "pump", ".", "missing"])
    assert result.exit_code == 2
    assert "selected none of the 3 tests found" in result.stderr


def test_k_that_cannot_be_read_is_a_usage_error_at_its_column_before_any_test_runs(project: Path) -> None:
    result = CliRunner().invoke(main, ["test", "-j", "1", "-k", "jam and"])
    assert result.exit_code == 2
    assert "-k 'jam and': at column 8: the expression ends where a name, 'not' or '(' should follow" in result.stderr
    assert "PASSED" not in result.output
