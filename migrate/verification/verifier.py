"""The comparison of a v3 application with its migration (the package's docstring says how it goes)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from functools import cache, partial
from types import MappingProxyType

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.migrate.model import ManualItem, MigrationResult
from mintlang.migrate.verification import compare, explained, runnable
from mintlang.migrate.verification.model import (
    DEFAULT_UNTIL_MS,
    DEFAULT_WALL_S,
    Divergence,
    Place,
    Verdict,
    Verification,
)
from mintlang.migrate.verification.runs import Recording, record
from mintlang.runtime.dialects.v3.controllers import DEFAULT as V3_DEFAULT
from mintlang.runtime.dialects.v3.controllers import PROFILES as V3_CONTROLLERS
from mintlang.runtime.scenario.stimulus import Scenario

# Every v3 controller the simulator offers is simulated on the NextMove PCI machine (its 1 ms servo
# tick, 2 ms profiler and plants: runtime/dialects/v3/controllers.py, V3-1), cut down to its axes and
# I/O; the NextMove PCI has those axes (0..2), inputs (0..7) and outputs (0..7) under the same
# numbers, and it is what the migration targets by default. MintDrive (one axis) fits none of them.
COUNTERPART = MappingProxyType(dict.fromkeys(V3_CONTROLLERS, Controller.NEXTMOVE_PCI))

_TIMING_RULE = "X-GO-TIMING"
# run as v3, a v4 application would be compared with itself, or stop on its first v4 form
_ALREADY_V4 = "already Mint v4: there is no Mint v3 original to run (verify the v3 files before --write)"


def verify(
    result: MigrationResult,
    *,
    v3_controller: str = V3_DEFAULT,
    controller: Controller | str | None = None,
    scenario: Scenario | None = None,
    until_ms: int = DEFAULT_UNTIL_MS,
    max_wall_s: float | None = DEFAULT_WALL_S,
) -> Verification:
    """Compare the v3 application ``result`` was migrated from with the v4 one it gives, each run for at
    most ``until_ms`` simulated ms. ``controller`` is the v4 controller ``result`` was migrated for (by
    default the counterpart of ``v3_controller``); ``scenario`` is the stimulus of both runs (its
    expectations are not checked). Raises ``ScenarioFileError`` when a program's ``REM @sim`` line cannot
    be read, ``ValueError`` for a controller of the wrong generation."""
    target = str(Controller(controller)) if controller is not None else str(COUNTERPART[v3_controller])
    stimulus = replace(scenario, expectations=()) if scenario is not None else Scenario()
    v3 = runnable.original(result)
    v4, disabled = runnable.migrated(result, target)
    left = record(v3, Dialect.V3, v3_controller, stimulus, until_ms=until_ms, max_wall_s=max_wall_s)
    run_v4 = partial(record, v4, Dialect.V4, target, stimulus, until_ms=until_ms, max_wall_s=max_wall_s)
    right = run_v4()
    short = _ALREADY_V4 if result.already_v4 else short_of(left, right, runnable.flagged_places(result))
    what_if = partial(run_v4, functions=explained.FUNCTIONS) if explained.applies(result) else None
    return conclude(left, right, result, short, controllers=(v3_controller, target), disabled=disabled, what_if=what_if)


def conclude(
    original: Recording,
    migrated: Recording,
    result: MigrationResult,
    short: str | None,
    *,
    controllers: tuple[str, str],
    disabled: tuple[Place, ...] = (),
    what_if: Callable[[], Recording] | None = None,
) -> Verification:
    """The verdict on two recorded runs of ``result``'s original and migrated application, ``short`` saying
    why the comparison cannot cover the whole run (if it cannot); ``controllers`` ran the original and the
    migration. ``what_if`` records the migration with v3's trigonometry, to tell the differences M-TRIG
    explains (``explained``) from divergences when there are any."""
    comparable = not (original.refused or (migrated.refused and short))  # else one of them never ran
    origins = cache(partial(runnable.origins, result))
    found = compare.differences(original, migrated, origins) if comparable else []
    expected: list[Divergence] = []
    if found and what_if is not None:
        found, expected = explained.split(found, compare.differences(original, what_if(), origins))
    flagged = _flagged(result)
    return Verification(
        verdict=_verdict(found, expected, flagged, short),
        compared_ms=max(compare.horizon(original, migrated), 0) if comparable else 0,
        divergence=found[0] if found else expected[0] if expected else None,
        differences=tuple(compare.in_order([*found, *expected])),
        v3_controller=controllers[0],
        v4_controller=controllers[1],
        v3_stop=compare.stopped(original),
        v4_stop=compare.stopped(migrated),
        not_verified=flagged,
        disabled=disabled,
        short=short,
    )


def short_of(
    original: Recording, migrated: Recording, flagged: set[Place], *, names: tuple[str, str] = ("v3", "v4")
) -> str | None:
    """Why the comparison cannot cover the whole run: the original does not compile, the migration does not
    until a person deals with a line left for them, both stopped on an error at once, or the simulation
    stopped where the program would not. A migration that does not compile on a line nobody flagged is no
    such reason: it diverges. ``names`` are the two dialects, as the reasons name them."""
    source, target = names
    if original.refused:
        return f"the {source} original does not compile: {compare.stopped(original).message}"
    migrated_stop = compare.stopped(migrated)
    if migrated.refused and migrated_stop.line in flagged:
        return (
            f"the {target} program does not compile until {migrated_stop.line}, left for a person, is done: "
            f"{migrated_stop.message}"
        )
    original_stop = compare.stopped(original)
    if original_stop.reason == migrated_stop.reason == "error" and original_stop.time_ms == migrated_stop.time_ms == 0:
        # both failed at once (a drive left disabled, a missing RESET): agreeing on that verifies nothing
        return f"both runs stopped on an error at 0 ms ({original_stop.message}; {migrated_stop.message})"
    return original.short or migrated.short


def _flagged(result: MigrationResult) -> tuple[tuple[str, ManualItem], ...]:
    """The statements left for a person, configuration file first: the lines marked, and the statements an
    application note asks to fill in (a v3 default, a dedicated input), whose effect is not verified either."""
    parts = [("configuration", result.configuration), ("program", result)]
    return tuple((unit, item) for unit, part in parts if part is not None for item in part.manual)


def _verdict(
    found: list[Divergence], expected: list[Divergence], flagged: tuple[tuple[str, ManualItem], ...], short: str | None
) -> Verdict:
    """``found`` the differences no rule explains, ``expected`` those one does."""
    if not found:
        return Verdict.INCOMPLETE if short else Verdict.EXPLAINED if expected else Verdict.EQUIVALENT
    timing_flagged = any(item.rule == _TIMING_RULE for _, item in flagged)
    if timing_flagged and all(divergence.timing_only for divergence in found):
        return Verdict.TIMING
    return Verdict.DIVERGES
