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
from mintlang.migrate.verification import DEFAULT_UNTIL_MS, Verification, compare
from mintlang.migrate.verification.model import DEFAULT_WALL_S, Application, Place
from mintlang.migrate.verification.runnable import flagged_places, without_expectations
from mintlang.migrate.verification.runs import Recording, record
from mintlang.migrate.verification.verifier import conclude
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
    short = _short(original, migrated, flagged_places(result))
    return conclude(original, migrated, result, short, controllers=(target, target))


def _originals(result: MigrationResult) -> tuple[str, str | None]:
    configuration = result.configuration
    return result.source, configuration.source if configuration is not None else None


def _migrated(result: MigrationResult) -> tuple[str, str | None]:
    configuration = result.configuration
    return result.text, configuration.text if configuration is not None else None


def _short(original: Recording, migrated: Recording, flagged: set[Place]) -> str | None:
    """Why the comparison cannot cover the whole run: the original does not compile, the migration does
    not until a person deals with a line left for them, both stopped on an error at once, or the simulation
    stopped where the program would not. A migration that does not compile on a line nobody flagged is no
    such reason: it diverges."""
    if original.refused:
        return f"the v4 original does not compile: {compare.stopped(original).message}"
    stop = compare.stopped(migrated)
    if migrated.refused and stop.line in flagged:
        return f"the MintMT program does not compile until {stop.line}, left for a person, is done: {stop.message}"
    original_stop = compare.stopped(original)
    if original_stop.reason == stop.reason == "error" and original_stop.time_ms == stop.time_ms == 0:
        # both failed at once (a drive left disabled): agreeing on that verifies nothing, as for v3 -> v4
        return f"both runs stopped on an error at 0 ms ({original_stop.message}; {stop.message})"
    return original.short or migrated.short
