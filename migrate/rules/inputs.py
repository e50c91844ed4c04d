"""The digital inputs read or masked as one byte: v3 had 8 user inputs, v4 has up to 24.

v3 ``IN`` read inputs 0..7 as an 8-bit number and ``IMASK`` (default 255, range
0..255) enabled the handlers #IN0..#IN7 (v3:8884-8947). In v4 both cover every
input of the controller: IMASK defaults to all ones over the controller's inputs
and IN returns them all (v4:11877-11978). The rewrites below keep the v3 values
of bits 0..7 and leave the bits above as v4 starts them.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.keyworddb.model import Controller
from mintlang.migrate.context import LABEL, Context, FileView
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.literals import integer_literal
from mintlang.migrate.rules.spelling import like
from mintlang.semantic.events import EventKind, event_of
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import parent_of

# IMASK's default (= all inputs enabled) per controller: the attribute table at v4:11896-11900.
# ServoNode 51 is not in that table; with 6 inputs it has no input above 7 to keep enabled.
IMASK_ALL_ONES = {
    Controller.NEXTMOVE_PCI: 1048575,
    Controller.NEXTMOVE_PC: 16777215,
    Controller.NEXTMOVE_BX: 65535,
    Controller.MINTDRIVE: 262143,
}


_INPUT_BITS = {f"IN{bit}": bit for bit in range(8)}  # v3's one-input keywords IN0..IN7 (v3:8975-8992)


def imask_all_ones(context: Context) -> int:
    """IMASK with every input of the target enabled, its default (v4:11896-11900; ServoNode 51, not in
    that table, by its inputs)."""
    inputs = context.controller.digital_inputs.high + 1
    return IMASK_ALL_ONES.get(context.controller.controller, (1 << inputs) - 1)


def inputs_holding_back_handlers(context: Context) -> int:
    """The inputs v4 serves before a handler's input that have no handler, as a bit pattern: enabled in IMASK,
    such an input holds back every event of a lower priority (v4:5055-5057, #IN0 first: v4:5062-5064), where
    v3's IMASK only masked handlers off (v3:8894-8902)."""
    handled = _handler_inputs(context)
    return ((1 << handled.bit_length()) - 1) & ~handled


def _byte(node: n.Expression | None) -> bool:
    """An integer literal 0..255: a value v3 IMASK or IN could hold."""
    return isinstance(node, n.Number) and node.value == int(node.value) and 0 <= node.value <= 255


def _plain(node: n.Expression | None, keyword: str) -> bool:
    """``keyword`` without axes or channel (``IN``, not ``IN3`` or ``IN.3``)."""
    return isinstance(node, n.KeywordRef) and node.keyword == keyword and node.selector is None and node.channel is None


def _keyword_refs(statement: n.Statement, keyword: str) -> Iterator[n.KeywordRef]:
    for root in n.expressions_of(statement):
        for node in n.walk_expression(root):
            if _plain(node, keyword):
                assert isinstance(node, n.KeywordRef)
                yield node


class InputMask(Rule):
    """v3 IMASK held 8 bits (default 255); v4 IMASK holds one bit per input of the controller
    and defaults to all ones, so an 8-bit literal written as in v3 would also disable the
    handlers of inputs 8 and up. Bit set = handler enabled in both (v3:8894-8902,
    v4:11915-11916). The rewrites:

    * ``IMASK = k`` (k a literal 0..255) -> ``IMASK = k | <all ones above bit 7>``, with k's bits of
      inputs that would hold back a handler cleared (``inputs_holding_back_handlers``);
    * ``IMASK = IMASK AND k`` -> ``IMASK = IMASK AND (k | <all ones above bit 7>)``;
    * ``IMASK = IMASK OR e`` is kept (it only sets bits), but for the bits of inputs that would
      hold back a handler, cleared from a literal e;
    * a read of IMASK anywhere else -> ``(IMASK & 255)``, the v3 value.

    The ones above bit 7 come from the v4 range table of the target controller; any other
    write (a computed value, a literal above 255) is a manual item.
    """

    id = "S-IMASK"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "IMASK = k -> IMASK = k | <v4 bits 8 and up>; IMASK AND k likewise; IMASK read -> (IMASK & 255)"
    evidence = "spec S-IMASK; v3:8884-8902; v4:11877-11925 (default per controller v4:11896-11900)"

    def apply(self, context: Context) -> Iterator[Action]:
        if context.controller.controller not in IMASK_ALL_ONES:
            return  # ServoNode 51: no input above 7, v3 values mean the same
        high = imask_all_ones(context) & ~255
        holding = inputs_holding_back_handlers(context)
        for file, _, statement in context.statements("IMASK"):  # written or read
            if (
                isinstance(statement, n.KeywordStatement)
                and statement.keyword.keyword == "IMASK"
                and statement.values is not None
            ):
                yield from self._write(file, statement, high, holding)
                continue
            for read in _keyword_refs(statement, "IMASK"):
                if not _masked(parent_of(statement, read), read):
                    yield self.replace(file, read.span, f"({file.slice(read.span)} & 255)")

    def _write(self, file: FileView, statement: n.KeywordStatement, high: int, holding: int) -> Iterator[Action]:
        values = statement.values or ()
        value = values[0] if len(values) == 1 and statement.keyword.selector is None else None
        if _byte(value):
            assert isinstance(value, n.Number)
            written = file.slice(value.span)
            if int(value.value) & holding:  # brackets: v4's | binds before & (v4:1427-1428)
                written = f"({written} & 0x{255 & ~holding:X})"
            yield self.replace(file, value.span, f"{written} | 0x{high:X}")
            return
        if _widened(value, high):
            return
        if isinstance(value, n.Binary) and value.operator in ("AND", "OR"):
            own, other = (value.left, value.right) if _plain(value.left, "IMASK") else (value.right, value.left)
            if _plain(own, "IMASK") and value.operator == "OR":
                if isinstance(other, n.Number) and _byte(other) and int(other.value) & holding:
                    yield self.replace(file, other.span, f"({file.slice(other.span)} & 0x{255 & ~holding:X})")
                return
            if _plain(own, "IMASK") and (_widened(other, high) or _keeps(other, high)):
                return
            if _plain(own, "IMASK") and _byte(other):
                yield self.replace(file, other.span, f"({file.slice(other.span)} | 0x{high:X})")
                return
        reason = f"v4 IMASK has a bit per input (default 0x{high | 255:X}): keep the bits of inputs 8 and up set"
        yield self.flag(file, statement.span, reason)


class InputByte(Rule):
    """v3 ``IN`` read inputs 0..7 as a byte; v4 ``IN`` returns every input, so a plain read
    becomes ``(IN & 255)``, as the v4 guide itself rewrote ``JOG = IN`` (v3:2336 vs v4:1802).
    ``IN & k`` / ``IN AND k`` with a literal k of 0..255 already masks and is kept; ``INx``
    and ``IN.x`` read one input and are unchanged (M-BIT).

    Beside #INn handlers the inputs are read with INSTATE. v3 IN, INx and IN.x read the inputs'
    state (v3:4288-4317); S-INEDGE makes each handler's input edge triggered, and v4 IN reads
    such an input's latched edge and clears it (v4:11976-11978, v4:11985-11988), where INSTATE
    reads the state of every input and clears no latch (v4:12487-12536). So ``IN`` becomes
    ``(INSTATE & 255)``, ``IN & k`` ``INSTATE & k``, and a read of a handler's input, or of
    ``IN.x`` whose input is not known, ``INSTATE.n``.
    """

    id = "S-IN"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "IN read as a byte -> (IN & 255) (IN & k with k <= 255 kept); beside #INn handlers IN -> INSTATE"
    evidence = "spec S-IN; v3:8927-8947, v3:2336, v3:4288-4317; v4:11951-11996, v4:1802, v4:12487-12536"

    def apply(self, context: Context) -> Iterator[Action]:
        edged = _handler_inputs(context)
        wide = context.controller.digital_inputs.high > 7  # else IN reads the same byte
        if not (edged or wide):
            return
        for file, _, statement in context.statements("IN", *_INPUT_BITS):
            for root in n.expressions_of(statement):
                for read in n.walk_expression(root):
                    if isinstance(read, n.KeywordRef) and (read.keyword == "IN" or read.keyword in _INPUT_BITS):
                        yield from self._read(file, statement, read, edged, wide=wide)

    def _read(
        self, file: FileView, statement: n.Statement, read: n.KeywordRef, edged: int, *, wide: bool
    ) -> Iterator[Action]:
        state = like(read.spelling, "INSTATE")
        bit = _INPUT_BITS.get(read.keyword, read.channel)
        if bit is not None:  # INx
            if edged >> bit & 1:
                yield self.replace(file, read.span, f"{state}.{bit}")
            return
        if read.selector is not None:  # IN.x
            channel = read.selector.items[0] if len(read.selector.items) == 1 else None
            number = integer_literal(channel) if channel is not None else None
            if edged and (number is None or edged >> number & 1):
                yield self.replace(file, read.spelling_span, state)
            return
        masked = _masked(parent_of(statement, read), read)
        if edged:
            yield self.replace(file, read.span, state if masked else f"({state} & 255)")
        elif wide and not masked:
            yield self.replace(file, read.span, f"({file.slice(read.span)} & 255)")


def _masked(parent: n.Expression | None, read: n.KeywordRef) -> bool:
    """Whether ``read`` is already ANDed with a literal of 0..255 (``IN & 15``, ``(IMASK & 255)``)."""
    if isinstance(parent, n.Binary) and parent.operator == "AND":
        return _byte(parent.right if parent.left is read else parent.left)
    return False


def _widened(value: n.Expression | None, high: int) -> bool:
    """``k | <high>`` (possibly bracketed) with k of 0..255: a value this rule already wrote."""
    while isinstance(value, n.Parenthesised):
        value = value.expression
    return (
        isinstance(value, n.Binary)
        and value.operator == "OR"
        and _byte(value.left)
        and isinstance(value.right, n.Number)
        and value.right.value == high
    )


def _keeps(value: n.Expression | None, high: int) -> bool:
    """A literal ANDed into IMASK that keeps the bits above 7 set (S-INEDGE's ``IMASK = IMASK & 0xFFFF8``)."""
    return isinstance(value, n.Number) and value.value == int(value.value) and int(value.value) & high == high


def _handler_inputs(context: Context) -> int:
    """The inputs of the program's #INn handlers as a bit pattern: those S-INEDGE makes edge triggered."""
    inputs = 0
    for file, line in context.placed(LABEL):
        label = line.syntax.label
        event = event_of(label.text) if label is not None and file.unit is Unit.PROGRAM else None
        if event is not None and event.kind is EventKind.IN and event.number is not None:
            inputs |= 1 << event.number
    return inputs
