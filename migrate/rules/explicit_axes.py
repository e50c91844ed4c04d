"""S-IDLEAXES (optional): bracket-less axis keywords get the axis list they act on.

``HOME = 0,0`` or ``MOVEA = x,y : GO`` act on the AXES default in force, which
v3 and v4 set differently at power-up; writing the list out (``HOME[0,1] = 0,0``,
``GO[0,1]``) is what the v4 guide did when it ported INTRO.MNT. Redundant when
M-AXES applies, hence optional. A statement whose default is unknown stays as it
is, and so does a v4-only keyword (the v3 reader takes ``DRIVEENABLE = 0;`` for a
variable). A GO right after a move on its line gets that move's axes, as the
guide's port does; that assumes no other default axis has a move pending there.
It runs with the insertions, after every context rewrite, so the companions those
write (S-ACCEL's ``: DECEL = v`` after ``ACCEL = v``) get the same list and still pair up.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.keyworddb.model import Addressing
from mintlang.migrate.context import Context, FileView
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import MOVES, addressed_axes, axis_list
from mintlang.migrate.rules.base import Action, Rule
from mintlang.syntax import nodes as n


class ExplicitAxes(Rule):
    """Writes the default axes a bracket-less axis keyword statement acts on after the keyword."""

    id = "S-IDLEAXES"
    rule_class = RuleClass.SEMI
    phase = Phase.INSERTIONS
    optional = True
    summary = "bracket-less 'HOME = 0,0', 'GO' -> 'HOME[0,1] = 0,0', 'GO[0,1]' (the AXES default in force)"
    evidence = "spec S-IDLEAXES; v3:586, v3:596, v3:1029-1033, v3:1080-1109; v4:157, v4:170, v4:605-608"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, before, statement, _ in context.neighbours(
            *context.mentioned(lambda name: axis_keyword(context, name))
        ):
            if not isinstance(statement, n.KeywordStatement) or not _bracketless_axis_keyword(context, statement):
                continue
            axes = _started_move(context, file, before, statement) or addressed_axes(
                context, file, statement, statement.span.start
            )
            if axes:
                at = statement.keyword.spelling_span.end
                yield self.replace(file, Span(at, at), axis_list(axes))


def _bracketless_axis_keyword(context: Context, statement: n.KeywordStatement) -> bool:
    keyword = statement.keyword
    return axis_keyword(context, keyword.keyword) and keyword.selector is None and keyword.channel is None


def axis_keyword(context: Context, name: str) -> bool:
    """Whether the keyword ``name`` addresses axes (``[...]``, ``.n`` or the AXES default)."""
    entry = context.db.keywords.get(name)
    return entry is not None and entry.addressing is Addressing.AXIS


def _started_move(
    context: Context, file: FileView, previous: n.Statement | None, statement: n.KeywordStatement
) -> tuple[int, ...] | None:
    """For ``MOVEA = x,y : GO`` the axes of the move the GO starts (``previous`` is the statement
    before it on its line), as the v4 guide's port writes it (``GO[0,1]``, v4:170); S-OFFSET
    pairs ``OFFSET[0] = d : GO[0]`` the same way."""
    if statement.keyword.keyword != "GO" or statement.values is not None:
        return None
    if isinstance(previous, n.KeywordStatement) and previous.keyword.keyword in MOVES and previous.values:
        return addressed_axes(context, file, previous, previous.span.start)
    return None
