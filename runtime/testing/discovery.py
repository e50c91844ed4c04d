"""Which files are tests: programs with ``REM @expect`` lines or a scenario file beside them."""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from mintlang.pairing import is_program, listed_as, names_in

SCENARIO_SUFFIX = ".scenario.toml"
_EXPECTATION = re.compile(r"(?:\bREM|')\s*@expect\b", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class TestCase:
    """One program to run, with the scenario file beside it if it has one."""

    program: Path
    scenario: Path | None

    @property
    def name(self) -> str:
        return str(self.program)


@dataclass(frozen=True, slots=True)
class Unreadable:
    """A path given or found that could not be read: reported, and the run goes on."""

    path: Path
    reason: str


def discover(paths: Iterable[Path]) -> tuple[list[TestCase], list[Unreadable]]:
    """The tests under ``paths`` (files or folders, searched recursively), in path order, each once."""
    cases: dict[Path, TestCase] = {}
    problems: list[Unreadable] = []
    for program in _programs(paths, problems):
        found = _case(program, problems)
        if found is not None:
            cases.setdefault(program.resolve(), found)
    return sorted(cases.values(), key=lambda case: str(case.program)), problems


def _programs(paths: Iterable[Path], problems: list[Unreadable]) -> Iterator[Path]:
    for path in paths:
        if path.is_dir():
            for found in sorted(found for found in path.rglob("*") if is_program(found.name)):
                if found.is_file():
                    yield found
                else:  # a broken link, a FIFO, a folder named like a program: said, not silently skipped
                    problems.append(Unreadable(found, _not_a_file(found)))
        elif path.exists():
            yield path
        else:
            problems.append(Unreadable(path, "no such file or folder"))


def _not_a_file(path: Path) -> str:
    if path.is_symlink() and not path.exists():
        return "a link to nothing"
    return "not a regular file"


def _case(program: Path, problems: list[Unreadable]) -> TestCase | None:
    scenario_name = listed_as(program.stem + SCENARIO_SUFFIX, names_in(program.parent))
    scenario = program.parent / scenario_name if scenario_name is not None else None
    if scenario is not None:
        return TestCase(program, scenario)
    try:
        text = program.read_text(encoding="utf-8", errors="replace")
    except OSError as error:
        problems.append(Unreadable(program, error.strerror or str(error)))
        return None
    return TestCase(program, None) if _EXPECTATION.search(text) else None
