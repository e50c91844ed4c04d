"""M-BIT (optional): ``IN0``..``IN7`` and ``OUT0``..``OUT7`` in the dot form ``IN.0``, ``OUT.0``.

Both forms are valid v4 (v4:11951, v4:14896); the v4 guide writes the dot form
in its own port of the v3 examples (v3:598 vs v4:172). A style choice, so optional.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule, keyword_refs

_BIT = re.compile(r"(IN|OUT)([0-7])")
_BITS = tuple(f"{port}{bit}" for port in ("IN", "OUT") for bit in range(8))


class DotBits(Rule):
    """Rewrites the glued bit keyword to the port keyword with a dot channel."""

    id = "M-BIT"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    optional = True
    summary = "IN0..IN7, OUT0..OUT7 -> IN.0..IN.7, OUT.0..OUT.7"
    evidence = "spec M-BIT; v3:598; v4:172, v4:11951, v4:14896, v4:4079-4084, v4:4128-4133"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line, _, keyword in keyword_refs(context, *_BITS):
            found = _BIT.fullmatch(keyword.keyword)
            if found is not None:
                yield self.replace(file, line.span(keyword.spelling_span), f"{found[1]}.{found[2]}")
