"""The golden cases: a v3 input, the reviewed v4 output and the reviewed report.

``tests/corpus/migrate/<name>/`` holds ``input.mnt`` (and/or ``input.cfg``),
``expected.mnt`` (and/or ``expected.cfg``) and ``expected-report.json``. Run the
tests with ``MINT_MIGRATE_UPDATE_GOLDEN=1`` to rewrite the expected files after a
change you have reviewed against the manuals; the inputs are refreshed from
``tests/corpus/v3/programs/`` at the same time.
"""

from __future__ import annotations

import json
import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mintlang.migrate import MigrationResult, migrate
from mintlang.migrate.report import entries, report

CORPUS = Path(__file__).parent.parent / "corpus"
GOLDEN = CORPUS / "migrate"
V3_PROGRAMS = CORPUS / "v3" / "programs"
UPDATE = os.environ.get("MINT_MIGRATE_UPDATE_GOLDEN") == "1"


@dataclass(frozen=True)
class Case:
    folder: Path

    @property
    def name(self) -> str:
        return self.folder.name

    def read(self, name: str) -> str | None:
        path = self.folder / name
        return path.read_bytes().decode("utf-8") if path.exists() else None

    def migrate(self) -> MigrationResult:
        return migrate(self.read("input.mnt") or "", config=self.read("input.cfg"))

    def report(self, result: MigrationResult) -> dict[str, Any]:
        program = "input.mnt" if (self.folder / "input.mnt").exists() else ""
        return report(entries(program, result, "input.cfg"), "nextmove-pci")


def refresh_inputs() -> None:
    """Copy every corpus program (with its configuration file) into a golden folder."""
    for source in sorted(V3_PROGRAMS.iterdir()):
        if source.suffix == ".cfg" and source.with_suffix(".mnt").exists():
            continue
        folder = GOLDEN / source.stem
        folder.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, folder / f"input{source.suffix}")
        configuration = source.with_suffix(".cfg")
        if source.suffix == ".mnt" and configuration.exists():
            shutil.copyfile(configuration, folder / "input.cfg")


def write_expected(case: Case, result: MigrationResult) -> None:
    if (case.folder / "input.mnt").exists():
        (case.folder / "expected.mnt").write_bytes(result.text.encode("utf-8"))
    if result.configuration is not None:
        (case.folder / "expected.cfg").write_bytes(result.configuration.text.encode("utf-8"))
    data = json.dumps(case.report(result), indent=2, ensure_ascii=False) + "\n"
    (case.folder / "expected-report.json").write_text(data, encoding="utf-8")


def cases() -> list[Case]:
    if UPDATE:
        refresh_inputs()
    return [Case(folder) for folder in sorted(GOLDEN.iterdir()) if folder.is_dir()]
