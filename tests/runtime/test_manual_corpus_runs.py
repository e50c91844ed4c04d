"""The manual's examples on the simulator: run-time errors where the guide shows them, and never a crash.

``tests/corpus/v4/runtime`` holds the errors only a running controller raises;
each is run with every drive enabled (as a configuration file would) and must
stop with the error number and line its header names. Every other v4 example
must run to some ending - its end, an error, a deadlock, the time limit or a
keyword the simulator says it does not model - without a Python exception.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from mintlang.codes import error_code
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import Limits
from tests.corpus_files import CorpusCase, cases

ENABLE_DRIVES = "RESETALL\n"


@pytest.mark.parametrize("case", cases("v4/runtime"), ids=lambda case: case.name)
def test_a_run_time_error_of_the_manual_is_raised_on_its_line(case: CorpusCase) -> None:
    ((code, line),) = case.expected
    result = run_source(case.source, config=ENABLE_DRIVES, controller=case.controller, limits=Limits(until_ms=1000))
    assert result.stop.reason is StopReason.ERROR, result.stop
    assert (error_code(int(result.err)), int(result.erl)) == (code, line), result.stop.message


NOT_SIMULATED = re.compile(r"^(\w+) \(.*\) is not simulated by mint-run")
BEHAVIOUR = Path(__file__).parents[2] / "runtime" / "BEHAVIOUR.md"


def _documented_as_not_simulated() -> str:
    text = BEHAVIOUR.read_text(encoding="utf-8")
    start = text.index("## Not simulated")
    end = text.find("\n## ", start + 1)
    return text[start : end if end >= 0 else len(text)]


@pytest.mark.parametrize("case", cases("v4/valid"), ids=lambda case: case.name)
def test_every_example_of_the_manual_runs_with_the_drives_enabled_and_stops_only_on_what_is_documented(
    case: CorpusCase,
) -> None:
    """The guide's examples assume a configured machine (drives enabled); a keyword the simulator stops on
    must be one runtime/BEHAVIOUR.md lists as not simulated, with the line it stood on."""
    drives = Scenario(drives=(DrivesEnabled(),))
    limits = Limits(until_ms=300, max_wall_s=5.0)
    result = run_source(case.source, controller=case.controller, scenario=drives, limits=limits)
    if result.stop.reason is StopReason.ERROR:
        assert result.stop.message, "an error ending always says why"
    missing = NOT_SIMULATED.match(result.stop.message)
    if missing is not None:
        assert result.stop.line is not None
        assert f"`{missing[1]}`" in _documented_as_not_simulated(), f"{missing[1]} is not listed as not simulated"
