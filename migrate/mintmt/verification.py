"""Run a v4 application and its MintMT migration in the simulator and compare them.

The same machinery as the v3 → v4 verification (``mintlang.migrate.verification``):
both runs are recorded at every millisecond with the same stimulus, the v4 one
as Mint v4 and the migrated one as MintMT, on the same controller, and compared
channel by channel within the same tolerances. In the answer, the ``v3`` fields
hold the v4 original's side and the ``v4`` fields the MintMT side. Nothing is
disabled: what the migration flags is kept in its v4 form, which MintMT reads
(MT-1), so a flagged line runs in both.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.verification import DEFAULT_UNTIL_MS, Verification
from mintlang.migrate.verification.model import DEFAULT_WALL_S, Application
from mintlang.migrate.verification.runnable import flagged_places, without_expectations
from mintlang.migrate.verification.runs import record
from mintlang.migrate.verification.verifier import conclude, short_of
from mintlang.runtime.scenario.stimulus import Scenario


def verify(
    result: MigrationResult,
    *,
    controller: Controller | str = Controller.NEXTMOVE_PCI,
    scenario: Scenario | None = None,
    until_ms: int = DEFAULT_UNTIL_MS,
    max_wall_s: float | None = DEFAULT_WALL_S,
) -> Verification:
    """Compare the v4 application ``result`` was migrated from with the MintMT one it gives, each run on
    ``controller`` for at most ``until_ms`` simulated ms with ``scenario`` as the stimulus (its
    expectations are not checked)."""
    target = str(Controller(controller))
    stimulus = replace(scenario, expectations=()) if scenario is not None else Scenario()
    runs = []
    for dialect, texts in ((Dialect.V4, _originals(result)), (Dialect.MINTMT, _migrated(result))):
        program, configuration = (without_expectations(text, dialect) if text is not None else None for text in texts)
        application = Application(program or "", configuration)
        runs.append(record(application, dialect, target, stimulus, until_ms=until_ms, max_wall_s=max_wall_s))
    original, migrated = runs
    short = (
        _ALREADY if _in_mintmt(result) else short_of(original, migrated, flagged_places(result), names=("v4", "MintMT"))
    )
    return conclude(original, migrated, result, short, controllers=(target, target))


_ALREADY = "already MintMT: there is no Mint v4 original to run (verify the v4 files before --write)"


def _in_mintmt(result: MigrationResult) -> bool:
    """Whether a file of the application was MintMT already: run as Mint v4 it would not compile, and that
    error, the first MintMT form it meets, would be reported as the v4 original's."""
    configuration = result.configuration
    return result.already_mintmt or (configuration is not None and configuration.already_mintmt)


def _originals(result: MigrationResult) -> tuple[str, str | None]:
    configuration = result.configuration
    return result.source, configuration.source if configuration is not None else None


def _migrated(result: MigrationResult) -> tuple[str, str | None]:
    configuration = result.configuration
    return result.text, configuration.text if configuration is not None else None
