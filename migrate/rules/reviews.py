"""Manual reviews the spec lists without a rewrite: arrays in the configuration file
(X-ARRAY-CFG), output formats a host may parse (X-PRINT), and values whose units
changed (X-UNITS). Each flags only the statements its spec row names.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import islice

from mintlang.keyworddb.model import Controller
from mintlang.migrate.context import MACRO, MARKER, Context, FileView, name_tag, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import unparsed_write
from mintlang.migrate.rules.base import Action, Rule
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_DELETED = "v4 deletes array data when the configuration runs: {} it in the program"
_GAINS = frozenset({"GAIN", "KPROP", "KVEL", "KVELFF", "KINT", "KDERIV", "KACCEL"})
# written in the same tuning block as the gains: they continue the block without an item of their own
_TUNING = _GAINS | {"KINTLIMIT", "KINTRANGE", "KINTMODE", "DACLIMITMAX", "CURRENTLIMIT", "CURRLIMIT"}
# The tags of a line that may write one of those or TORQUE: as a keyword, a user name (a v4
# keyword to the v3 reader), or the first word of a statement's text (unparsed, or a macro's name).
_WRITTEN = (*map(statement_tag, {*_TUNING, "TORQUE"}), *map(name_tag, {*_TUNING, "TORQUE"}), n.SyntaxError_, MACRO)


class ConfigurationArrays(Rule):
    """v4 deletes array data whenever the configuration file runs (and RELEASE does too), so an
    array dimensioned or filled there does not keep its values as it did in v3."""

    id = "X-ARRAY-CFG"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "array DIMed or filled in the configuration file -> manual (move it to the program)"
    evidence = "spec X-ARRAY-CFG; v3:1675-1738; v4:15749-15750, v4:5543"

    def apply(self, context: Context) -> Iterator[Action]:
        file = context.files.get(Unit.CONFIGURATION)
        if file is None:
            return
        for current, _, statement in context.statements(n.Dim, n.Assignment):
            if current is not file:
                continue
            if isinstance(statement, n.Dim) and statement.size is not None:
                yield self.flag(file, statement.span, _DELETED.format("DIM"))
            elif isinstance(statement, n.Assignment) and isinstance(statement.target, n.ElementRef):
                yield self.flag(file, statement.span, _DELETED.format("fill"))


class OutputFormat(Rule):
    """Text a host program or an operator reads: PRINT/INPUT USING layouts, BINARY, the query
    mark v3 INPUT printed after its prompt (``Enter a number ?``, v3:2764-2775; v4 shows none,
    v4:12213-12218), and strings in the format of the v3 ``ERROR: Program: ...`` message
    (v3:4978-5008) that a host parses; v4 reports errors as ``R0003: ...``. Other strings that
    merely mention an error are not flagged."""

    id = "X-PRINT"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "PRINT/INPUT USING, INPUT prompt, BINARY, printed 'ERROR' text -> manual (v4 number and message formats)"
    evidence = (
        "spec X-PRINT, §12; v3:2764-2775, v3:4978-5008, v3:6209-6239; "
        "v4:729, v4:764-767, v4:4584-4589, v4:12213-12218, v4:15299-15366"
    )

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(n.Print, n.Input, statement_tag("BINARY")):
            for statement in n.flatten_statements(line.syntax.statements):
                reason = _format_reason(statement)
                if reason is not None:
                    yield self.flag(file, line.span(statement.span), reason)


def _format_reason(statement: n.Statement) -> str | None:
    if isinstance(statement, n.Input):  # with USING too: USING lays out what is typed, the prompt is the same
        return "v3 INPUT printed ' ?' after its prompt (not after POFF), v4 does not; check what reads this output"
    if isinstance(statement, n.Print) and statement.using:
        return "USING layout: v4 prints numbers with up to 4 decimals; check what reads this output"
    if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "BINARY":
        return "BINARY output: v4 prints with PRINT BIN, without the 8-digit padding"
    if isinstance(statement, n.Print) and any(
        isinstance(item.value, n.StringLiteral) and item.value.value.upper().startswith("ERROR:")
        for item in statement.items
    ):
        return "v4 error messages read 'R0003: ...': a host parsing v3 'ERROR:' text must change"
    return None


class ChangedUnits(Rule):
    """Servo gains are 0..255 in 1/256 steps in v3 and floats up to 10000 on a 1 kHz NextMove loop
    in v4 (re-tune); on MintDrive TORQUE 100 is nominal current, where v3 100 was peak."""

    id = "X-UNITS"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "servo gain writes, TORQUE writes on MintDrive -> manual (units changed: re-tune)"
    evidence = "spec X-UNITS; v3:12131; v4:13015, v4:345-351, v4:16847-16848"

    def apply(self, context: Context) -> Iterator[Action]:
        """One item for each run of gain writes on consecutive lines: a tuning block is re-tuned as a whole."""
        mintdrive = context.controller.controller is Controller.MINTDRIVE
        block_end: dict[Unit, int] = {}  # the last line of the tuning block each file is in
        for file, line in context.placed(*_WRITTEN):
            for statement in n.flatten_statements(line.syntax.statements):
                span = line.span(statement.span)
                name = _written_name(statement) or unparsed_write(file.slice(span))
                if name in _TUNING:
                    previous = block_end.get(file.unit)
                    block_end[file.unit] = line.number
                    block = previous is not None and _continues(file, span.start, line.number - previous - 1)
                    if name in _GAINS and not block:
                        yield self.flag(file, span, "servo gains changed units and loop rate in v4: re-tune")
                elif name == "TORQUE" and mintdrive and not _all_zero(statement):
                    yield self.flag(file, span, "MintDrive TORQUE 100 is nominal current (v3 100 was peak)")


def _continues(file: FileView, offset: int, between: int) -> bool:
    """Whether the ``between`` lines above the line of ``offset`` are markers only (none: the same
    line or the next): another rule's items (X-NUM's on a gain's value) do not split a tuning block."""
    return between <= 0 or all(line.startswith(MARKER) for line in islice(file.lines_above(offset), between))


def _written_name(statement: n.Statement) -> str | None:
    """The keyword a statement writes, v4-only keywords (read as names by v3) included."""
    if isinstance(statement, n.KeywordStatement) and statement.values is not None:
        return statement.keyword.keyword
    if isinstance(statement, n.Assignment) and isinstance(statement.target, n.VariableRef):
        return statement.target.name.identity
    return None


def _all_zero(statement: n.Statement) -> bool:
    values = statement.values if isinstance(statement, n.KeywordStatement) else None
    return bool(values) and all(isinstance(value, n.Number) and value.value == 0 for value in values or ())
