"""An expectation on an element past the end of a declared array names the index the array lacks.

A Mint array's first element is 1 (000:7807) and ``DIM tbl(3)`` has elements 1 to 3 (000:1093-1095); an
index outside them is error 2016, Invalid index (000:19038-19044), as the program reading it would get. The
array is there: "no such thing in this run" sent the writer looking for a misspelt name.
"""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from tests.runtime.invoking import write


def _check(tmp_path: Path, expectation: str) -> dict[str, object]:
    program = write(tmp_path, "table.mnt", f"REM @expect {expectation}\nDIM tbl(3) = 1, 7, 3\n")
    result = CliRunner().invoke(main, ["test", "-j", "1", "--format", "json", str(program)])
    ((check,),) = [test["checks"] for test in json.loads(result.output)["tests"]]
    return check


def test_an_index_past_the_end_is_an_invalid_index(tmp_path: Path) -> None:
    check = _check(tmp_path, "tbl(9) = 7")
    assert (check["held"], check["actual"]) == (False, "missing")
    assert check["detail"] == "R2016: Invalid index (index 9 outside 1 to 3)"


def test_index_0_is_before_the_first_element(tmp_path: Path) -> None:
    check = _check(tmp_path, "tbl(0) = 0")
    assert check["detail"] == "R2016: Invalid index (index 0 outside 1 to 3)"


def test_an_element_inside_the_array_is_read(tmp_path: Path) -> None:
    check = _check(tmp_path, "tbl(2) = 7")
    assert (check["held"], check["actual"]) == (True, "7")
