"""``mint-migrate --verify``: run the v3 original and its v4 migration in the simulator and compare them.

A migration is only as good as the machine's behaviour after it. Both
applications run in ``mintlang.runtime`` with the same stimulus (a scenario, and
the programs' own ``REM @sim`` lines, which the migration keeps), the v3 one on
a v3 controller and the v4 one on its counterpart, and their terminal output,
outputs, relay and axes are compared at every millisecond within the
tolerances ``tolerance`` states::

    from mintlang.migrate import migrate
    from mintlang.migrate.verification import verify
    result = migrate(v3_source, config=v3_config)
    found = verify(result, scenario=scenario, until_ms=5000)
    found.verdict, found.divergence, found.not_verified

The answer is a ``Verification``: equivalent, a timing difference X-GO-TIMING
expected, differences only in the values M-TRIG says differ (``explained``), the
first divergence (time, the line each run was at, what differs), or incomplete
when the comparison cannot cover the run (the v3 original does not compile, the
migration compiles only once a flagged line is done, a run meets what the
simulator does not model). Everything the migration left for a person,
application notes included, is listed as not verified, and the flagged lines v4
finds in error are made comments for the v4 run (``runnable``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from mintlang.migrate.verification.model import (
        DEFAULT_UNTIL_MS,
        Divergence,
        Place,
        Stopped,
        Verdict,
        Verification,
    )
    from mintlang.migrate.verification.verifier import COUNTERPART, V3_CONTROLLERS, V3_DEFAULT, verify

__all__ = [
    "COUNTERPART",
    "DEFAULT_UNTIL_MS",
    "V3_CONTROLLERS",
    "V3_DEFAULT",
    "Divergence",
    "Place",
    "Stopped",
    "Verdict",
    "Verification",
    "verify",
]

# Imported when first used: ``mint-migrate --help`` shows DEFAULT_UNTIL_MS without loading the simulator.
import_when_used(
    __name__,
    {
        **dict.fromkeys(
            ["DEFAULT_UNTIL_MS", "Divergence", "Place", "Stopped", "Verdict", "Verification"],
            "mintlang.migrate.verification.model",
        ),
        **dict.fromkeys(
            ["COUNTERPART", "V3_CONTROLLERS", "V3_DEFAULT", "verify"], "mintlang.migrate.verification.verifier"
        ),
    },
)
