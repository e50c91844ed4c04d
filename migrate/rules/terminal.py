"""Terminal and serial-port keywords: BINARY output, the BAUD rate, and PAUSE waiting for a key."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.statements import Refusal, StatementRule
from mintlang.syntax import nodes as n

DPR_HOST_TERMINAL = "its host terminal is the dual port RAM, _tmDPR (v4:16693-16697)"


def has_serial_port(context: Context) -> bool:
    """Whether the target has a serial port: not the NextMove PC cards, which have no SERIALBAUD
    (v4:15817-15822) and talk to their host through the dual port RAM (``DPR_HOST_TERMINAL``)."""
    return context.supports("SERIALBAUD")


class BinaryOutput(Rule):
    """v3 ``BINARY`` has PRINT's syntax but prints numbers in binary (v3:6209-6239); v4 has no
    BINARY and prints binary with PRINT's BIN modifier (v4:764-767, v4:15354-15366). The
    keyword becomes PRINT and ``BIN`` goes before each item that is not a string; the items,
    separators and a ``#n`` terminal stay as written.

    The digits are the same but v3 padded to 8 digits with leading zeros, printed "up to 8
    bits" and stripped the fraction (v3:6219, v3:6233); v4 documents neither padding nor stripping
    (``PRINT BIN 0x1A`` shows ``11010``) and shows a 24-bit value in full (``PRINT BIN
    ~01100101``, v4:1338-1342: a negative prints 24 digits), so each rewritten statement also
    gets a manual item about the layout. ``BINARY ... USING`` is refused.
    """

    id = "S-BINARY"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "BINARY args -> PRINT args with BIN before each number (manual item: no 8-digit zero padding)"
    evidence = "spec S-BINARY; v3:6209-6239; v4:764-767, v4:15354-15366"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, _, statement in context.statements(statement_tag("BINARY")):
            if not isinstance(statement, n.KeywordStatement) or statement.keyword.keyword != "BINARY":
                continue
            if statement.using or statement.values is not None or statement.keyword.selector is not None:
                yield self.flag(file, statement.span, "use PRINT with BIN before each number (no USING in v4 BIN)")
                continue
            yield self.replace(file, statement.keyword.spelling_span, like(statement.keyword.spelling, "PRINT"))
            for item in statement.arguments:
                if not isinstance(item, n.StringLiteral):
                    yield self.replace(
                        file, Span(item.span.start, item.span.start), like(statement.keyword.spelling, "BIN ")
                    )
            yield self.flag(
                file,
                statement.span,
                "v4 PRINT BIN has no 8-digit zero padding (v3 00001100, v4 1100) and prints a negative in 24 bits;"
                " v3 printed 8 bits at most and dropped fractions",
            )


class PauseForKey(Rule):
    """v3's ``PAUSE`` with no condition waits until a key is pressed at the terminal (v3:2211); v4's PAUSE
    needs one (no expression is error 2005, v4:15013). ``PAUSE INKEY`` waits for any key in both (v3:2217-2223,
    v4:1680-1693), and the simulator runs v3's bare PAUSE as it, the key read (``runtime/BEHAVIOUR.md``)."""

    id = "M-PAUSEKEY"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "PAUSE (no condition: wait for a key) -> PAUSE INKEY"
    evidence = "v3:2211-2223; v4:15013, v4:1680-1693"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(n.Pause):  # as parsed: most PAUSEs have a condition, none needs a copy
            for statement in n.flatten_statements(line.syntax.statements):
                if type(statement) is not n.Pause or statement.condition is not None:
                    continue
                start, end = line.span(statement.span)
                written = file.text[start : start + len("PAUSE")]  # INKEY in the same case: pause inkey
                yield self.replace(file, Span(end, end), " " + like(written, "INKEY"))


class Baud(StatementRule):
    """v3 ``BAUD = v`` set the serial port's rate, any value of 300..19200 (v3:6092-6124); v4
    sets it with ``SERIALBAUD.<terminal>`` from a short list of rates (v4:15817-15866). 9600
    is the only rate the v4 table marks for the RS232 port of every controller, so only
    ``BAUD = 9600`` is rewritten (to the RS232 port, as the v4 example does); any other
    rate, and a computed one, is a manual item. v4 keeps the rate in EEPROM. The NextMove PC cards
    have no serial port: the item says to remove the BAUD."""

    id = "S-BAUD"
    rule_class = RuleClass.SEMI
    summary = "BAUD = 9600 -> SERIALBAUD._tmRS232 = 9600 (any other rate -> manual)"
    evidence = "spec S-BAUD; v3:6092-6124; v4:15817-15866 (rates v4:15856-15863)"
    keywords = frozenset({"BAUD"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        values = statement.values or ()
        value = values[0] if len(values) == 1 else None
        if not has_serial_port(context):
            missing = f"{context.controller.title} has no serial port (SERIALBAUD is not on it)"
            return Refusal(f"{missing}: remove the BAUD; {DPR_HOST_TERMINAL}")
        if not (isinstance(value, n.Number) and value.value == 9600):
            return Refusal("use SERIALBAUD._tmRS232 = <rate> with a rate the v4:15856-15863 table lists")
        return f"{like(statement.keyword.spelling, 'SERIALBAUD')}._tmRS232 = {file.slice(value.span)}"
