"""The generator run where the manual seeds are not (a checkout not beside ``../shared``) says so."""

from __future__ import annotations

from pathlib import Path

import pytest

from tools.keyworddb.__main__ import DEFAULT_SPEC, main


@pytest.mark.parametrize("arguments", [pytest.param([], id="write"), pytest.param(["--check"], id="check")])
def test_missing_seeds_are_a_usage_error_naming_the_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], arguments: list[str]
) -> None:
    seeds = tmp_path / "seeds"
    with pytest.raises(SystemExit) as stop:
        main(["--seeds", str(seeds), "--spec", str(DEFAULT_SPEC), *arguments])
    assert stop.value.code == 2
    error = capsys.readouterr().err
    assert f"cannot read {seeds}/" in error
    assert "give --seeds DIR and --spec DIR" in error
    assert "Traceback" not in error
