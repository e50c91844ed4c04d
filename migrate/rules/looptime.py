"""S-LOOPTIME: the servo loop time moved from milliseconds to microseconds."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.keyworddb.model import Controller
from mintlang.migrate.context import Context, FileView
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.literals import integer_literal
from mintlang.semantic.index import KeywordUse, Use
from mintlang.syntax import nodes as n

MICROSECONDS = {1: 1000, 2: 2000}  # v3 LOOPTIME 1 or 2 ms (v3:9882-9912)
_V4_LOOP_TIMES = frozenset({500, 1000, 2000})  # the LOOPTIME rows of the v4 range tables (v4:6171-6175)
_SETTABLE = frozenset({Controller.MINTDRIVE, Controller.SERVONODE51})  # the controllers those tables name


class LoopTime(Rule):
    """v3 ``LOOPTIME = 1`` or ``2`` chose a 1 ms (one servo axis) or 2 ms (three axes) loop; on
    MintDrive and ServoNode 51 v4 LOOPTIME takes microseconds (500, 1000, 2000 in the range
    tables of ACCEL, DECEL and ERRORDECEL), so 1 and 2 become 1000 and 2000. Those drives
    have one axis, so v3's "one axis only" side of LOOPTIME 1 costs nothing.

    Manual items: NextMove, whose loop times v4 fixes (servo loop every 1 ms, profiler every
    2 ms, v4:345-351) and whose LOOPTIME values the user guide does not list; a computed
    value; a read (v4 gives microseconds). A value already in the v4 table (v3 allowed only
    1 and 2) was written by this rule and is left alone.
    """

    id = "S-LOOPTIME"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "LOOPTIME = 1/2 -> LOOPTIME = 1000/2000 (MintDrive, ServoNode 51); NextMove, reads -> manual"
    evidence = (
        "spec S-LOOPTIME; v3:9882-9912; v4:13773-13775, v4:6169-6175, v4:8891-8897, v4:9995-10000, v4:345-351, v4:366"
    )

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses("LOOPTIME"):
            statement = use.statement
            if use.use is Use.READ or not isinstance(statement, n.KeywordStatement) or not statement.values:
                yield self.flag(file, statement.span, "LOOPTIME reads microseconds in v4 (v3: milliseconds)")
                continue
            yield from self._write(context, file, use, statement)

    def _write(
        self, context: Context, file: FileView, use: KeywordUse, statement: n.KeywordStatement
    ) -> Iterator[Action]:
        value = statement.values[0] if len(statement.values) == 1 else None
        written = integer_literal(value)
        if written in _V4_LOOP_TIMES:
            return
        if context.controller.controller not in _SETTABLE:
            yield self.flag(
                file,
                use.keyword.span,
                f"{context.controller.title} servos every 1 ms and profiles every 2 ms (v4:345-351): "
                "remove this LOOPTIME or see the Advanced Programming Guide",
            )
        elif value is None or written not in MICROSECONDS:
            yield self.flag(file, use.keyword.span, "LOOPTIME value is not 1 or 2: v4 takes 500, 1000 or 2000 us")
        else:
            yield self.replace(file, value.span, str(MICROSECONDS[written]))
