"""The analog outputs: v3 wrote and read DAC counts, v4 writes and reads percent.

v3 ``DAC[axes]`` and ``AUXDAC`` take -2047..2047 counts for -10..+10 V
(v3:7110-7135, v3:5943); v4 ``DAC.channel`` and ``AUXDAC.channel`` take -100..100
percent of the same +-10 V (v4:8737-8752, v4:6680-6686) and, being channel
keywords, dot syntax only, one channel per write (v4:548-561). v3 ``DEMAND[axis]``
read percent; v4 replaced it by DAC (v4:9149).
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import islice

from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.axes import default_axes, selector_axes
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import ancestors

_FAMILY = frozenset({"DAC", "AUXDAC", "DEMAND"})
_TO_PERCENT = " * 100 / 2047"
_TO_COUNTS = " * 2047 / 100"
_STEPPER_CONSTANTS = frozenset({"_STEPPER", "_MICRO", "_CFSTEPPER"})
_STEPPER_VALUES = frozenset({2.0, 3.0})  # v3 _stepper and _micro (v3:4624-4649); v4 2 = _cfSTEPPER


def _scaled(file: FileView, value: n.Expression, factor: str) -> str:
    text = file.slice(value.span)
    simple = isinstance(value, n.Number | n.VariableRef | n.KeywordRef | n.Parenthesised | n.Call)
    return f"{text}{factor}" if simple else f"({text}){factor}"


def _is_factor(node: n.Expression | None, multiply: float, divide: float) -> bool:
    """``x * multiply / divide``: a value this rule already wrote."""
    return (
        isinstance(node, n.Binary)
        and node.operator == "/"
        and isinstance(node.right, n.Number)
        and node.right.value == divide
        and isinstance(node.left, n.Binary)
        and node.left.operator == "*"
        and isinstance(node.left.right, n.Number)
        and node.left.right.value == multiply
    )


class DacUnits(Rule):
    """DAC counts become percent, with one dot-syntax write per channel:

    * ``DAC[0,1] = a, b`` -> ``DAC.0 = a * 100 / 2047 : DAC.1 = b * 100 / 2047`` (a ``;``
      fill and the AXES default are expanded; axis n drives DAC channel n);
    * ``AUXDAC = v`` -> ``AUXDAC.0 = v * 100 / 2047`` (MintDrive, ServoNode 51);
    * reading ``DAC[n]`` -> ``(DAC.n * 2047 / 100)``, ``AUXDAC`` -> ``(AUXDAC.0 * 2047 / 100)``,
      the v3 counts.

    ``DEMAND[n]`` (percent of the amplifier's peak in v3) is a manual item: written as a
    plain ``DAC.n`` it would read, to this rule on a second run, as a v3 DAC in counts.

    A value already of the form ``x * 100 / 2047`` is taken as converted (what this rule
    writes; a second migration must not scale again). Refused: computed axes, a write
    whose values read the analog outputs (a controller without the keyword is left to
    X-PLATFORM). v4 writes
    DAC only on an axis configured off where v3 also allowed a stepper axis
    (v3:7118-7128, v4:8753-8755): in an application that configures a stepper, each
    DAC write also gets a manual item.
    """

    id = "S-DAC"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "DAC[axes] = v -> DAC.n = v * 100 / 2047 per axis; AUXDAC likewise (.0); reads -> counts; DEMAND manual"
    evidence = "spec S-DAC; v3:7110-7135, v3:5943, v3:7260-7285; v4:8737-8755, v4:6680-6686, v4:9149, v4:548-561"

    def apply(self, context: Context) -> Iterator[Action]:
        stepper = _configures_stepper(context)
        for file, _, statement in context.statements(*_FAMILY):
            if (
                isinstance(statement, n.KeywordStatement)
                and statement.keyword.keyword in ("DAC", "AUXDAC")
                and statement.values is not None
            ):
                yield from self._write(context, file, statement, stepper)
                continue
            for node in _family_reads(statement):
                if not _is_factor(_grandparent(statement, node), 2047, 100):
                    yield from self._read(context, file, statement, node)

    def _write(
        self, context: Context, file: FileView, statement: n.KeywordStatement, stepper: bool
    ) -> Iterator[Action]:
        keyword = statement.keyword
        values = statement.values or ()
        if any(value is not None and any(True for _ in _family_reads_of(value)) for value in values):
            yield self.flag(file, statement.span, f"{keyword.keyword} value reads an analog output: convert by hand")
            return
        if not context.supports(keyword.keyword):
            return  # X-PLATFORM reports a keyword the controller does not have
        if keyword.keyword == "AUXDAC":
            axes: tuple[int, ...] | None = selector_axes(keyword) or (0,)
        else:
            axes = selector_axes(keyword)
            if axes is None and keyword.selector is None:
                axes = default_axes(context, file, statement.span.start)
        if axes is None:
            yield self.flag(
                file, statement.span, f"{keyword.keyword}: the axes are not constant; DAC.n = v * 100 / 2047"
            )
            return
        present = [value for value in values if value is not None]
        if (
            keyword.selector is not None
            and keyword.selector.dot
            and len(present) == 1
            and _is_factor(present[0], 100, 2047)
        ):
            return  # already converted
        listed = list(values)
        if statement.fill and listed:
            listed += [listed[-1]] * (len(axes) - len(listed))
        word = like(keyword.spelling, keyword.keyword)
        writes = [
            f"{word}.{axis} = {_scaled(file, value, _TO_PERCENT)}"
            for axis, value in zip(axes, listed, strict=False)
            if value is not None
        ]
        yield self.replace(file, statement.span, " : ".join(writes))
        if stepper and keyword.keyword == "DAC":
            reason = "v4 writes DAC only on an axis with CONFIG = _cfOFF (v3 also allowed a stepper axis)"
            yield self.flag(file, statement.span, reason)

    def _read(self, context: Context, file: FileView, statement: n.Statement, node: n.KeywordRef) -> Iterator[Action]:
        word = node.keyword
        if word == "DEMAND":
            yield self.flag(file, statement.span, "DEMAND: read DAC.n (v4 % of +-10 V, as DEMAND was %)")
            return
        target = "AUXDAC" if word == "AUXDAC" else "DAC"
        axes = selector_axes(node) if word != "AUXDAC" or node.selector is not None else (0,)
        if axes is None and node.selector is None and word != "AUXDAC":
            axes = default_axes(context, file, node.span.start)
        if not context.supports(target):
            return  # X-PLATFORM reports a keyword the controller does not have
        if axes is None or len(axes) != 1:
            yield self.flag(file, statement.span, f"{word}: read one constant channel as {target}.n (v4 % of 10 V)")
            return
        channel = f"{like(node.spelling, target)}.{axes[0]}"
        yield self.replace(file, node.span, f"({channel}{_TO_COUNTS})")


def _grandparent(statement: n.Statement, node: n.Expression) -> n.Expression | None:
    """The parent's parent of ``node``: ``x * 2047 / 100`` around a read this rule already converted."""
    return next(islice(ancestors(statement, node), 1, None), None)


def _family_reads_of(root: n.Expression) -> Iterator[n.KeywordRef]:
    for node in n.walk_expression(root):
        if isinstance(node, n.KeywordRef) and node.keyword in _FAMILY:
            yield node


def _family_reads(statement: n.Statement) -> Iterator[n.KeywordRef]:
    for root in n.expressions_of(statement):
        yield from _family_reads_of(root)


def _configures_stepper(context: Context) -> bool:
    for _, _, statement in context.statements(statement_tag("CONFIG")):
        if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "CONFIG":
            for value in statement.values or ():
                if (isinstance(value, n.Number) and value.value in _STEPPER_VALUES) or (
                    isinstance(value, n.ConstantRef) and value.name in _STEPPER_CONSTANTS
                ):
                    return True
    return False
