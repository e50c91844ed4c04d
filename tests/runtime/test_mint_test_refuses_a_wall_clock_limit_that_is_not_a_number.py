"""``mint test --max-wall-s nan`` is refused, as ``mint-run``'s is.

``--max-wall-s`` is the wall-clock limit of each run (README.md, "mint test" and "mint-run": 60 s
unless raised, ``inf`` for none). NaN passed the option's range, every comparison with it being false,
and as a limit no elapsed time exceeds it: a test stuck in its main loop ran for ever instead of
failing at the limit. ``mint-run`` already refused it; ``mint test`` took it.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from tests.runtime.invoking import write


def test_a_wall_clock_limit_that_is_not_a_number_is_a_usage_error(tmp_path: Path) -> None:
    program = write(tmp_path, "short.mnt", "REM @expect a = 1\nDIM a\na = 1\n")
    result = CliRunner().invoke(main, ["test", "-j", "1", "--max-wall-s", "nan", str(program)])
    assert result.exit_code == 2
    assert "Invalid value for '--max-wall-s': give a number of seconds, or inf for no limit" in result.output
