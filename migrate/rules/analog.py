"""S-ANALOG: the analog inputs are ADC channels in percent, where v3 read 10-bit counts."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from types import MappingProxyType

from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.semantic.index import Use
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import ancestors

# v3 input -> v4 ADC channel: the v4 guide's ports number them from 0 (v3:2318 vs v4:1785).
CHANNELS: Mapping[str, int] = MappingProxyType({"ANALOGUE1": 0, "ANALOGUE2": 1, "ANALOGUE3": 2})
# Percent of +-10 V (-100..100) to v3 counts of +-10 V, one part in 1024 with 0 V at 512 (v3:4368-4376,
# v3:5768), each a whole count of the 10-bit conversion, 0 to 1023 (v3:5748-5760): c = INT((p + 100) * 1024 / 200),
# one less at full scale, where that gives 1024 (a relation is 1 when true, v4:1266).
TO_COUNTS = "{int}(({adc} + 100) * 1024 / 200) - ({adc} >= 100)"


class AnalogueInputs(Rule):
    """``ANALOGUEn`` becomes ``INT((ADC.(n-1) + 100) * 1024 / 200) - (ADC.(n-1) >= 100)``, in brackets within an
    expression, and the line gets a manual item.

    v3 read one part in 1024 of the input's range, which a jumper chose per input: +-10 V or
    0..5 V (v3:5748-5760, v3:4368-4370); 0 V reads 512, so ``A1 - 512`` is zero speed at rest
    (v3:4374-4380); it spans -512 to 511, the table's 0 to 1023 (v3:5748-5750; CONFLICT: 512 at
    v3:5768). v4 ADC reads percent of its range, -100..100 (v4:6358-6363), +-10 V on MintDrive and
    chosen with ADCMODE on NextMove. The formula gives the v3 count for a +-10 V input read as
    +-10 V, the one case where both ranges are known to agree, and keeps the program's arithmetic
    (``A1 - 512`` stays centred on 0 V); INT keeps the whole count v3 read, so a comparison with a
    count holds as it did (the value is never below 0), and the full scale, 100 %, reads v3's top
    count, 1023, not 1024. Nothing in the program says which jumper was fitted, so each use also
    gets a manual item naming the assumption. Rewriting the keyword alone, as the v4 guide's own
    examples do, would silently change every number the program computes from the input.
    """

    id = "S-ANALOG"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "ANALOGUE1..3 -> INT((ADC.0..2 + 100) * 1024 / 200) - (ADC.0..2 >= 100) + manual item (+-10 V inputs)"
    evidence = (
        "spec S-ANALOG; v3:5748-5760, v3:4368-4378, v3:2318; v4:6537, v4:6335-6363, v4:1785, v4:4171, v4:12565, v4:1266"
    )

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses(*CHANNELS):
            keyword = use.keyword
            channel = CHANNELS[keyword.keyword]
            if use.use is not Use.READ:
                yield self.flag(file, use.statement.span, f"{keyword.keyword} can only be read (v4: ADC.{channel})")
                continue
            if not context.supports("ADC") or channel not in context.controller.adc:
                yield self.flag(file, keyword.span, f"{context.controller.title} has no ADC.{channel}")
                continue
            spelling = keyword.spelling
            counts = TO_COUNTS.format(int=like(spelling, "INT"), adc=f"{like(spelling, 'ADC')}.{channel}")
            yield self.replace(file, keyword.span, _as_a_value(counts, use.statement, keyword))
            yield self.flag(
                file,
                use.statement.span,
                f"ADC.{channel} is % of the input range: the v3 count formula assumes a +-10 V input "
                f"(0..5 V input: INT(ADC.{channel} * 1024 / 50)); check the wiring and simplify",
            )


def _as_a_value(counts: str, statement: n.Statement, keyword: n.KeywordRef) -> str:
    """``counts`` where the read stood: in brackets within an expression, unless it is in brackets already."""
    enclosing = next(ancestors(statement, keyword), None)
    return counts if enclosing is None or isinstance(enclosing, n.Parenthesised) else f"({counts})"
