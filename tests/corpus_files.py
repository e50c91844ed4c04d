"""Reading the corpus: Mint files whose REM header says what the analyser must report.

The header format is described in ``tests/corpus/README.md``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

CORPUS = Path(__file__).parent / "corpus"

_EXPECT = re.compile(r"REM expect:\s*(E\d+|[WI]\d+)\s*@\s*(\d+)", re.IGNORECASE)
_SETTING = re.compile(r"REM (controller|dialect):\s*(\S+)", re.IGNORECASE)

# What a fragment may report of the variables and labels it takes from the program around it (README.md).
FRAGMENT_ALLOWANCE = frozenset({"E3001", "E3004"})


@dataclass(frozen=True)
class CorpusCase:
    path: Path
    source: str
    configuration: str | None
    fragment: bool
    controller: str
    dialect: str
    expected: frozenset[tuple[str, int]]  # (code, 1-based line)

    @property
    def name(self) -> str:
        return str(self.path.relative_to(CORPUS))


def read_case(path: Path) -> CorpusCase:
    data = path.read_bytes()
    source = data.decode("utf-8")
    settings = {"controller": "nextmove-pci", "dialect": "v4"}
    expected: set[tuple[str, int]] = set()
    fragment = False
    for line in source.splitlines():
        stripped = line.strip()
        if not stripped.upper().startswith("REM"):
            continue
        if stripped.upper() == "REM FRAGMENT":
            fragment = True
        if found := _EXPECT.match(stripped):
            expected.add((found.group(1).upper(), int(found.group(2))))
        if found := _SETTING.match(stripped):
            settings[found.group(1).lower()] = found.group(2).lower()
    configuration_path = path.with_suffix(".cfg")
    configuration = (
        configuration_path.read_text("utf-8") if path.suffix == ".mnt" and configuration_path.exists() else None
    )
    return CorpusCase(
        path, source, configuration, fragment, settings["controller"], settings["dialect"], frozenset(expected)
    )


def cases(folder: str, pattern: str = "*.mnt") -> list[CorpusCase]:
    return [read_case(path) for path in sorted((CORPUS / folder).glob(pattern))]
