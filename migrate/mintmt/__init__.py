"""``mint-migrate --to mintmt``: a Mint v4 application rewritten in MintMT's syntax (``mintlang.migrate.mintmt``).

The two MintMT notes show how a v4 program is written in MintMT: ``'`` comments,
round-bracket addressing, ``End Loop``/``Then``/``End If``, ``Event Comms1`` blocks
(``mintlang/MINTMT.md``). One module per kind of rewrite finds them on the tokens of
the project's lexer; what the notes do not show is kept as v4 writes it (MintMT
reads it, MT-1) and flagged for a person with the migrator's ``REM MIGRATE:`` line::

    from mintlang.migrate.mintmt import to_mintmt
    from mintlang.migrate.mintmt.verification import verify  # loads the simulator
    result = to_mintmt(v4_source, config=v4_config)
    result.text, result.changes, result.manual, result.already_mintmt
    verify(result, scenario=scenario, until_ms=5000).verdict  # the v4 and MintMT runs compared
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from mintlang.migrate.mintmt.api import CHECKS, REWRITES, to_mintmt

__all__ = ["CHECKS", "REWRITES", "to_mintmt"]

# Imported when first used: a migration from Mint v3 (mint-migrate's default) does not load the rewrites.
import_when_used(__name__, dict.fromkeys(__all__, "mintlang.migrate.mintmt.api"))
