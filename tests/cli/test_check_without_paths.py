"""``mint check`` with no paths checks the current folder, as ruff does and as ``mint test`` already does."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, write


@pytest.mark.parametrize(
    ("program", "exit_code"),
    [
        pytest.param("DIM a\nPRINT a\n", 0, id="a clean program passes"),
        pytest.param("PRINT 1 +\n", 1, id="an error in a program below is found"),
    ],
)
def test_no_paths_checks_the_current_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, program: str, exit_code: int
) -> None:
    write(tmp_path / "cells" / "press.mnt", program)
    monkeypatch.chdir(tmp_path)
    result = mint_check()
    assert result.exit_code == exit_code, result.output
    assert "Missing argument" not in result.output
