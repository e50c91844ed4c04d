"""Reading a conformance case: its program, header, scenario file and configuration file.

The format is described in ``tests/conformance/README.md``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from mintlang.dialect import Dialect
from mintlang.runtime.hardware import machine
from mintlang.runtime.scenario import Scenario, load_scenario

CONFORMANCE = Path(__file__).parent
# Where each choice a case may rest on is recorded: the runtime's, and MintMT's (MT-n).
CHOICE_DOCUMENTS = (
    CONFORMANCE.parents[1] / "runtime" / "BEHAVIOUR.md",
    CONFORMANCE.parents[1] / "mintlang" / "MINTMT.md",
)

_HEADER = re.compile(r"REM\s+(conformance|manual|choice|controller|dialect|until-ms):\s*(.*?)\s*$", re.IGNORECASE)
_CITATION = re.compile(r"(000|001|002|004):(\d+)(?:-(\d+))?")
CHOICE = re.compile(r"\b[A-Z][A-Z0-9]*-\d+\b")  # a specification item (NM-9) or a Mint v3 choice (V3-2)


class MalformedCase(ValueError):
    """A case whose header does not follow the README."""


@dataclass(frozen=True)
class Case:
    path: Path
    source: str
    title: str
    citations: tuple[str, ...]
    choices: tuple[str, ...]
    controller: str | None  # None: the dialect's default controller
    dialect: Dialect
    until_ms: int | None
    configuration: str | None
    scenario: Scenario  # from the TOML file beside the program; the program's own REM lines are read by the run

    @property
    def name(self) -> str:
        return str(self.path.relative_to(CONFORMANCE).with_suffix(""))


def read_case(path: Path) -> Case:
    source = path.read_text(encoding="utf-8")
    header: dict[str, str] = {}
    for line in source.splitlines():
        found = _HEADER.match(line.strip())
        if found:
            key = found[1].lower()
            if key in header:
                raise MalformedCase(f"{path.name}: REM {key}: is given twice")
            header[key] = found[2]
    if not header.get("conformance"):
        raise MalformedCase(f"{path.name}: no 'REM conformance:' line says what the case shows")
    citations = _citations(path, header.get("manual", ""))
    choices = tuple(choice.strip() for choice in header.get("choice", "").split(",") if choice.strip())
    for choice in choices:
        if not CHOICE.fullmatch(choice):
            raise MalformedCase(f"{path.name}: {choice!r} is not a specification item id such as NM-9")
    controller = header.get("controller")
    dialect = Dialect(header.get("dialect", Dialect.V4.value))
    toml = path.with_suffix(".toml")
    scenario = load_scenario(toml, machine(controller, dialect), dialect) if toml.exists() else Scenario()
    configuration = path.with_suffix(".cfg")
    return Case(
        path,
        source,
        header["conformance"],
        citations,
        choices,
        controller,
        dialect,
        int(header["until-ms"]) if "until-ms" in header else None,
        configuration.read_text(encoding="utf-8") if configuration.exists() else None,
        scenario,
    )


def _citations(path: Path, text: str) -> tuple[str, ...]:
    cited = tuple(part.strip() for part in text.split(",") if part.strip())
    if not cited:
        raise MalformedCase(f"{path.name}: no 'REM manual:' line cites the manual lines the expectations rest on")
    for citation in cited:
        found = _CITATION.fullmatch(citation)
        if found is None or (found[3] is not None and int(found[3]) < int(found[2])):
            raise MalformedCase(f"{path.name}: {citation!r} is not a citation such as 000:1700 or 000:1700-1731")
    return cited


def all_cases() -> list[Path]:
    return sorted(CONFORMANCE.rglob("*.mnt"))


def reindented(source: str) -> str:
    """Every line with an indentation no other line has (tabs and spaces), its text otherwise unchanged."""
    lines = source.splitlines(keepends=True)
    return "".join("\t" * (number // 8) + " " * (number % 8) + line for number, line in enumerate(lines, start=1))
