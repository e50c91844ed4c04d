"""``mint test`` refuses a report or tracefile it cannot write before it runs a test, not after.

A suite can run for minutes; a typo in ``--output-file`` or ``--lcov`` (a folder that does not exist)
was found only once every test had run, and their results were lost. ``mint-run`` checks every output
before the run (README.md, "mint-run": "Every output is checked before the run"); ``mint test``'s exit
status for such a problem is 2, a usage problem (README.md, "mint test").
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.runtime.invoking import write


def _mint_test(folder: Path, *options: str) -> Result:
    program = write(folder, "passes.mnt", "REM @expect a = 2\nDIM a\na = 1 + 1\n")
    return CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", *options, str(program)])


def test_a_tracefile_in_a_missing_folder_is_refused_before_any_test_runs(tmp_path: Path) -> None:
    tracefile = tmp_path / "missing" / "cov.info"
    result = _mint_test(tmp_path, "--coverage", "--lcov", str(tracefile))
    assert result.exit_code == 2
    assert result.output == f"mint test: cannot write {tracefile}: {tracefile.parent}: no such directory\n"


def test_a_report_in_a_missing_folder_is_refused_before_any_test_runs(tmp_path: Path) -> None:
    report = tmp_path / "missing" / "report.xml"
    result = _mint_test(tmp_path, "--format", "junit", "--output-file", str(report))
    assert result.exit_code == 2
    assert result.output == f"mint test: cannot write {report}: {report.parent}: no such directory\n"
