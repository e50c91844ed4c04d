"""The differences M-TRIG explains, told from a divergence by a what-if run.

M-TRIG keeps v3's thousandths, ``(SIN(x) * 1000)``, but not v3's table values
(``mintlang.migrate.expected``): ``PRINT`` of it shows 707 in v3 and 707.1067 in
v4, and whatever is computed from it differs as much. To tell that from a fault
of the migration, the migrated application runs once more with v3's SIN, COS and
TAN in place of v4's (each v3's table value over 1000, so the rewritten
expression gives what v3 gave). What that run no longer differs in (a channel:
the terminal, the outputs, an axis) differed by the trigonometry alone and is
explained; what it still differs in diverges, and the first difference told there
is that run's, since v4's own run is off by the trigonometry in it too.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import replace
from types import MappingProxyType

from mintlang.migrate.expected import TRIGONOMETRY
from mintlang.migrate.model import MigrationResult
from mintlang.migrate.verification.model import Divergence
from mintlang.runtime.dialects.v3 import trig
from mintlang.runtime.numbers import f32

WHAT_IF = "the migration run again with v3's SIN, COS and TAN values (M-TRIG)"


def _as_v3(table: Callable[[float], float]) -> Callable[[float], float]:
    """v3's function of an angle (folded into 0..360, the only angles v3 takes) over 1000, as v4 holds it."""

    def function(degrees: float) -> float:
        return f32(table(degrees % 360) / 1000)

    return function


FUNCTIONS: Mapping[str, Callable[..., float]] = MappingProxyType(
    {"SIN": _as_v3(trig.sine), "COS": _as_v3(trig.cosine), "TAN": _as_v3(trig.tangent)}
)


def applies(result: MigrationResult) -> bool:
    """Whether M-TRIG rewrote a line of the application (its program or its configuration file)."""
    parts = (result, result.configuration)
    return any(change.rule == TRIGONOMETRY for part in parts if part is not None for change in part.changes)


def split(found: list[Divergence], still: list[Divergence]) -> tuple[list[Divergence], list[Divergence]]:
    """``found`` (v4's own run against v3) as (divergences, explained differences), given what the what-if run
    ``still`` differs in: a channel it no longer differs in is explained; one it does is that run's difference,
    or v4's own where the two agree. A channel only the what-if run differs in is no difference of the
    migration: v4's own run agrees with v3 there."""
    channels = {divergence.what for divergence in still}
    explained = [replace(d, explained_by=TRIGONOMETRY) for d in found if d.what not in channels]
    differing = {divergence.what for divergence in found}
    diverging = [d if d in found else replace(d, what_if=WHAT_IF) for d in still if d.what in differing]
    return diverging, explained
