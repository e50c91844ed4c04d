"""M-RELATION: ``a > = b`` becomes ``a >= b``.

The v3 guide writes a relation with a blank inside and runs it (``PAUSE DEMAND > = 50``,
v3:3096); the v4 guide prints its relations in one piece only (v4:1262-1264), and a v4
compiler reads ``> =`` as two operators. Written in one piece, both versions read it alike.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.syntax.tokens import TokenKind

_RELATIONS = frozenset({TokenKind.MOREEQUAL, TokenKind.LESSEQUAL, TokenKind.NOTEQUAL})


class SpacedRelations(Rule):
    """Closes up ``> =``, ``< =`` and ``< >``."""

    id = "M-RELATION"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    summary = "'a > = b' -> 'a >= b' (also '< =', '< >')"
    evidence = "v3:3096; v4:1262-1264"

    def apply(self, context: Context) -> Iterator[Action]:
        for file in context.files.values():
            for offset, line in file.document.physical:
                for kind, start, end in zip(line.kinds, line.starts, line.ends, strict=True):
                    if kind in _RELATIONS and end - start > 2:
                        yield self.replace(
                            file, Span(offset + start, offset + end), line.text[start] + line.text[end - 1]
                        )
