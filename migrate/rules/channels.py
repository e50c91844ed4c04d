"""Channel keywords: v4 addresses encoders by channel, in dot syntax only, one channel at a time."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from types import MappingProxyType

from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.axes import default_axes, selector_axes
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.writes import per_channel
from mintlang.semantic.index import Use
from mintlang.syntax import nodes as n

# v3 keyword -> v4 channel keyword (axis n reads encoder channel n by default, v4:17243-17250).
CHANNEL_KEYWORDS: Mapping[str, str] = MappingProxyType(
    {"ENCODER": "ENCODER", "ENCWRAP": "ENCODERWRAP", "FASTENC": "FASTENCODER", "PRESCALE": "ENCODERPRESCALE"}
)
_PRESCALES = frozenset({1, 2, 4, 8, 16, 32, 64, 128})


class Channels(Rule):
    """``ENCODER[1]`` becomes ``ENCODER.1``, ``ENCWRAP[0,1] = a,b`` becomes
    ``ENCODERWRAP.0 = a : ENCODERWRAP.1 = b`` (FASTENC and PRESCALE likewise): v4 channel
    keywords take dot syntax only and cannot address several channels. A read without
    axes reads the first default axis, as in v3 (``ENCODER`` after ``AXES[1,2]`` is
    ``ENCODER.1``). A read of several axes or of axes not constant, or a PRESCALE that
    is not a power of two up to 128, is flagged."""

    id = "S-CHAN"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "ENCODER/ENCWRAP/FASTENC/PRESCALE[axes] -> ENCODER/ENCODERWRAP/FASTENCODER/ENCODERPRESCALE.n"
    evidence = "spec S-CHAN; v3:7640, v3:10941; v4:548-561, v4:9597, v4:9799, v4:10365, v4:9668, v4:9680"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses(*CHANNEL_KEYWORDS):
            keyword = use.keyword
            new = CHANNEL_KEYWORDS[keyword.keyword]
            if not context.supports(new):
                yield self.flag(file, keyword.span, f"{new} is not available on {context.controller.title}")
                continue
            if use.use is Use.READ:
                axes = selector_axes(keyword)
                if axes is None and keyword.selector is None:  # the first default axis (v3:1063-1071)
                    default = default_axes(context, file, use.statement.span.start)
                    axes = default[:1] if default else None
                if axes is None or len(axes) != 1:
                    yield self.flag(file, keyword.span, f"{new} reads one channel: write {new}.<channel>")
                elif new != keyword.keyword or not (keyword.selector and keyword.selector.dot):
                    yield self.replace(file, keyword.span, f"{like(keyword.spelling, new)}.{axes[0]}")
                continue
            statement = use.statement
            if not isinstance(statement, n.KeywordStatement) or statement.values is None:
                yield self.flag(file, keyword.span, f"{keyword.keyword} used as a command: no v4 equivalent")
                continue
            if new == keyword.keyword and keyword.selector is not None and keyword.selector.dot:
                continue  # already one channel in dot syntax
            if keyword.keyword == "PRESCALE" and not all(
                isinstance(value, n.Number) and value.value in _PRESCALES for value in statement.values
            ):
                yield self.flag(file, statement.span, "ENCODERPRESCALE takes a power of two from 1 to 128 only")
                continue
            result = per_channel(context, file, statement, new)
            if isinstance(result, str):
                yield self.replace(file, statement.span, result)
            else:
                yield self.flag(file, statement.span, result)
