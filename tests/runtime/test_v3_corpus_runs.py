"""Every Mint v3 program of the v3 guide runs on the simulator to an ending, and those that cannot run say why.

Each program of ``tests/corpus/v3/programs`` (with its configuration file, and the
configuration files that have no program) runs as Mint v3 with every drive
enabled. It must end without a Python exception: at its end, at the time limit,
blocked waiting for a key or an input nobody gives (a deadlock), or on an error.
An error ending must be explained in runtime/BEHAVIOUR.md: the keyword it stops
on in the list of what v3 does not simulate, and the program in the table of the
guide's programs that do not run, with the same reason.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario.stimulus import DrivesEnabled, Scenario
from mintlang.runtime.simulation import Limits
from tests.corpus_files import CORPUS

PROGRAMS = CORPUS / "v3" / "programs"
BEHAVIOUR = Path(__file__).parents[2] / "runtime" / "BEHAVIOUR.md"
NOT_SIMULATED = re.compile(r"^(.+?) \(.*\) is not simulated by mint-run")
V3_ERROR = re.compile(r"^ERROR: \w+: (.+?) at line \d+")


def _runs() -> list[tuple[str, str, str | None]]:
    """(name, program, configuration) of every program, and of every configuration file without one."""
    runs = []
    for path in sorted(PROGRAMS.glob("*.mnt")):
        configuration = path.with_suffix(".cfg")
        text = configuration.read_text("utf-8") if configuration.exists() else None
        runs.append((path.name, path.read_text("utf-8"), text))
    for path in sorted(PROGRAMS.glob("*.cfg")):
        if not path.with_suffix(".mnt").exists():
            runs.append((path.name, "", path.read_text("utf-8")))
    return runs


def _section(title: str) -> str:
    text = BEHAVIOUR.read_text(encoding="utf-8")
    start = text.index(title)
    end = text.find("\n#", start + 1)
    return text[start : end if end >= 0 else len(text)]


def _reason(result: RunResult) -> str:
    """What stopped a run that ended on an error: the keyword not simulated, or the v3 error's message."""
    message = result.stop.message
    for pattern in (NOT_SIMULATED, V3_ERROR):
        found = pattern.match(message)
        if found is not None:
            return found[1]
    return message


@pytest.mark.parametrize(("name", "program", "configuration"), _runs(), ids=[run[0] for run in _runs()])
def test_every_v3_program_of_the_guide_runs_to_an_ending(name: str, program: str, configuration: str | None) -> None:
    drives = Scenario(drives=(DrivesEnabled(),))
    result = run_source(
        program, config=configuration, dialect="v3", scenario=drives, limits=Limits(until_ms=300, max_wall_s=5.0)
    )
    assert result.stop.reason is not StopReason.WALL_LIMIT
    if result.stop.reason is not StopReason.ERROR:
        return
    assert result.stop.line is not None, "an error ending names its line"
    reason = _reason(result)
    row = next((line for line in _section("### The guide's programs").splitlines() if f"`{name}`" in line), None)
    assert row is not None, f"{name} stops on {reason!r}: list it among the guide's programs that do not run"
    assert reason in row, f"{name} stops on {reason!r}, not on what BEHAVIOUR.md says: {row}"
    if NOT_SIMULATED.match(result.stop.message):
        assert f"`{reason}`" in _section("### Not simulated in v3"), f"{reason} is not listed as not simulated"
