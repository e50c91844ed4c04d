"""Rewrites of keyword writes whose values, companions or target keyword changed in v4."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import ClassVar

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.axes import axis_values, default_axes, selector_axes
from mintlang.migrate.rules.base import Action, Rule, same_text, selector_text, values_text
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.statements import Refusal, StatementRule
from mintlang.migrate.rules.terminal import DPR_HOST_TERMINAL, has_serial_port
from mintlang.semantic.v3_declarations import COMMS
from mintlang.syntax import nodes as n


def _writes(statement: n.Statement | None, keyword: str) -> n.KeywordStatement | None:
    if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == keyword:
        return statement
    return None


class AccelAlsoDecel(Rule):
    """In v3 writing ACCEL (ACCELTIME) also set DECEL unless AXISCON bit 0 was set; in v4 the two
    are independent. So every ACCEL write gets ``: DECEL<axes> = <same values>`` after it
    (unless a DECEL of the same axes already follows it on the line). A DECEL write is left as
    it is: without the bit v3 used it until the next ACCEL write overwrote it (v3:7203,
    v3:6027), which the DECEL written beside that ACCEL does in v4. AXISCON is set per axis
    (``AXISCON.1 = 1`` turns DECEL on for axis 1, v3:6041), so an ACCEL write is left to the user
    only where it may reach an axis whose bit 0 may be set (a value with it set, or one computed,
    on axes named or unknown); ``ACCEL.0`` beside ``AXISCON.1 = 1`` is rewritten as without it.

    The copy must compute what the ACCEL write computed. A value that reads what the controller
    or the host changes between two statements (a key, an input, a position, TIME, COMMS: any
    keyword but the pair, v3:9136-9160) would give DECEL another value, so DECEL reads back what
    the write set, axis by axis: ``ACCEL[0,1] = POS.0, 5 : DECEL[0,1] = ACCEL.0,ACCEL.1``
    (v4:6150-6153). Values that read ACCEL (or ACCELTIME), as ``ACCEL = ACCEL * 2`` does, would
    read the new value after the write, so their DECEL goes before it,
    ``DECEL = ACCEL * 2 : ACCEL = ACCEL * 2``; values that read both ACCEL and DECEL fit neither
    order and are flagged."""

    id = "S-ACCEL"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "ACCEL[axes] = v -> ACCEL[axes] = v : DECEL[axes] = v (ACCELTIME likewise with DECELTIME)"
    evidence = "spec S-ACCEL; v3:5662, v3:5728, v3:7203; v4:6178, v4:8900, v4:244"
    pairs: ClassVar[dict[str, str]] = {"ACCEL": "DECEL", "ACCELTIME": "DECELTIME"}

    def apply(self, context: Context) -> Iterator[Action]:
        decel_on = _decel_may_be_on(context)
        for file, before, statement, after in context.neighbours(*map(statement_tag, self.pairs)):
            accel = _accel(statement)
            if accel is None:
                continue
            decel = self.pairs[accel.keyword.keyword]
            if _may_reach(context, file, accel, decel_on):
                yield self.flag(file, accel.span, f"AXISCON is used: decide whether {decel} must follow this write")
                continue
            if _changes_between_reads(accel, self.pairs):
                if self._companion(file, accel, after):
                    continue
                read_back = _read_back(context, file, accel, decel)
                if read_back is None:
                    yield self.flag(
                        file,
                        accel.span,
                        "the value may change between two reads and the axes are not known: "
                        f"write {decel} from a variable holding the value",
                    )
                else:
                    yield self.replace(file, Span(accel.span.end, accel.span.end), f" : {read_back}")
                continue
            if _reads(accel, self.pairs) and _reads(accel, self.pairs.values()):
                yield self.flag(
                    file,
                    accel.span,
                    f"the value reads {accel.keyword.keyword} and {decel}: v4 needs "
                    f"{decel} written too; compute the value into a variable first",
                )
                continue
            if _reads(accel, self.pairs):  # after the write it would read the new value
                if not self._companion(file, accel, before):
                    yield self.replace(
                        file, Span(accel.span.start, accel.span.start), f"{_decel_write(file, accel, decel)} : "
                    )
                continue
            if self._companion(file, accel, after):
                continue
            yield self.replace(file, Span(accel.span.end, accel.span.end), f" : {_decel_write(file, accel, decel)}")

    def _companion(self, file: FileView, accel: n.KeywordStatement, beside: n.Statement | None) -> bool:
        """Whether ``beside``, the statement right after (or before) ``accel`` on its line, writes the same axes' DECEL.

        DECELTIME is no v3 keyword, so the v3 reader takes the rule's own ``DECELTIME = 10`` for
        a variable and ``DECELTIME = 10,20`` for a syntax error: the statement also counts when
        its text is the write this rule makes (spacing and case aside), or the rule would add
        one more on every pass."""
        if beside is None:
            return False
        decel = self.pairs[accel.keyword.keyword]
        written = _writes(beside, decel)
        if written is not None and _same_axes(file, accel, written):
            return True
        return same_text(file.slice(beside.span), _decel_write(file, accel, decel))


def _decel_may_be_on(context: Context) -> frozenset[int] | None:
    """The axes on which a write of AXISCON may set bit 0, which turns DECEL on (v3:6027): one whose
    values are not all constants with the bit clear (``AXISCON.0 = AXISCON.0 | 01``, v3:7212); None
    when such a write's axes are not known (a variable axis, or default axes AXES leaves unknown)."""
    axes: set[int] = set()
    for file, _, statement in context.statements(statement_tag("AXISCON")):
        write = _writes(statement, "AXISCON")
        if write is None or write.values is None:
            continue
        pairs = axis_values(context, file, write)
        if not pairs and any(_may_set_bit_0(value) for value in write.values if value is not None):
            return None
        axes.update(axis for axis, value in pairs if _may_set_bit_0(value))
    return frozenset(axes)


def _may_set_bit_0(value: n.Expression) -> bool:
    return not isinstance(value, n.Number) or bool(int(value.value) & 1)


def _may_reach(context: Context, file: FileView, accel: n.KeywordStatement, decel_on: frozenset[int] | None) -> bool:
    """Whether ``accel`` may write an axis whose AXISCON bit 0 may be set: the axes it names, or the
    default axes where it names none; any axis when either is unknown."""
    if decel_on is not None and not decel_on:
        return False
    axes = selector_axes(accel.keyword)
    if axes is None and accel.keyword.selector is None:
        axes = default_axes(context, file, accel.span.start)
    return decel_on is None or axes is None or not decel_on.isdisjoint(axes)


def _reads(accel: n.KeywordStatement, keywords: Iterable[str]) -> bool:
    """Whether the values of ``accel`` read one of ``keywords``."""
    wanted = frozenset(keywords)
    return any(
        isinstance(node, n.KeywordRef) and node.keyword in wanted
        for value in accel.values or ()
        for node in n.walk_expression(value)
    )


def _changes_between_reads(accel: n.KeywordStatement, pairs: dict[str, str]) -> bool:
    """Whether the values of ``accel`` read a keyword other than the ACCEL/DECEL pairs, or the
    COMMS array, either of which may give another value when read again a statement later."""
    own = frozenset(pairs) | frozenset(pairs.values())
    return any(
        (isinstance(node, n.KeywordRef) and node.keyword not in own)
        or (isinstance(node, n.ElementRef) and node.name.text.upper() == COMMS)
        for value in accel.values or ()
        for node in n.walk_expression(value)
    )


def _read_back(context: Context, file: FileView, accel: n.KeywordStatement, decel: str) -> str | None:
    """``decel`` written with the axes of ``accel`` and, for each value it set, a read of that
    axis' new ACCEL; None when the places of several values are not known."""
    source = like(accel.keyword.spelling, accel.keyword.keyword)
    selector = selector_text(file, accel.keyword)
    target = like(accel.keyword.spelling, decel)
    pairs = axis_values(context, file, accel)
    if pairs:
        places = selector_axes(accel.keyword) or default_axes(context, file, accel.span.start) or ()
        read = dict(pairs)
        reads = [f"{source}.{axis}" if axis in read else "" for axis in places]
        while not reads[-1]:
            reads.pop()
        return f"{target}{selector} = {','.join(reads)}"
    if len(accel.values or ()) != 1:
        return None
    if accel.keyword.selector is None:  # the first default axis, or all of them alike with ``;`` (v3:1052-1109)
        return f"{target} = {source}{';' if accel.fill else ''}"
    if len(accel.keyword.selector.items) == 1:  # one computed axis: ACCEL[ax] = v
        return f"{target}{selector} = {source}{selector}"
    return None


def _decel_write(file: FileView, accel: n.KeywordStatement, decel: str) -> str:
    """``decel`` written with the axes and values of ``accel``, in its spelling's case."""
    return f"{like(accel.keyword.spelling, decel)}{selector_text(file, accel.keyword)} = {values_text(file, accel)}"


def _accel(statement: n.Statement | None) -> n.KeywordStatement | None:
    return _writes(statement, "ACCEL") or _writes(statement, "ACCELTIME")


def _same_axes(file: FileView, first: n.KeywordStatement, second: n.KeywordStatement) -> bool:
    return selector_text(file, first.keyword) == selector_text(file, second.keyword)


class IdleWindow(StatementRule):
    """Writing ``IDLE`` set v3's idle following-error window; v4 IDLE is read-only and the
    window is IDLEPOS. Writing ``VEL`` (idle velocity in counts per servo cycle) has a unit
    change as well (IDLEVEL), so it is flagged."""

    id = "S-WRITE"
    rule_class = RuleClass.SEMI
    summary = "IDLE[axes] = v -> IDLEPOS[axes] = v; VEL[axes] = v -> manual (IDLEVEL, other units)"
    evidence = "spec S-WRITE; v3:8762-8780, v3:12480-12488; v4:11738, v4:11747-11748, v4:3046-3050"
    keywords = frozenset({"IDLE", "VEL"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None:
            return None
        if statement.keyword.keyword == "VEL":
            return Refusal("VEL written: v4 IDLEVEL takes the idle velocity in other units (v4:3046)")
        keyword = statement.keyword
        rest = file.slice(Span(keyword.spelling_span.end, statement.span.end))
        return self.unsupported(context, "IDLEPOS") or like(keyword.spelling, "IDLEPOS") + rest


class CurrentLimit(StatementRule):
    """``CURRLIMIT`` is DACLIMITMAX on NextMove (one write per DAC channel: channel keywords
    take dot syntax only) and CURRENTLIMIT on MintDrive; both are percentages as in v3."""

    id = "S-CURR"
    rule_class = RuleClass.SEMI
    summary = "CURRLIMIT[axes] = v -> DACLIMITMAX.n = v per axis (NextMove) / CURRENTLIMIT = v (MintDrive)"
    evidence = "spec S-CURR; v4:8712, v4:444-445, v4:9015-9016"
    keywords = frozenset({"CURRLIMIT"})

    def caveat(self, context: Context, statement: n.KeywordStatement) -> str | None:
        if any(isinstance(value, n.Number) and value.value < 1 for value in statement.values or ()):
            return "CURRLIMIT below v3's 1..100: the v4 limit 0 holds the output at 0 V"  # v3:7073, v4:8815
        return None

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None:
            return Refusal("CURRLIMIT read: DACLIMITMAX (NextMove) or CURRENTLIMIT (MintDrive) in v4")
        if context.supports("DACLIMITMAX"):
            return per_channel(context, file, statement, "DACLIMITMAX")
        if context.supports("CURRENTLIMIT"):
            keyword = like(statement.keyword.spelling, "CURRENTLIMIT")
            return f"{keyword}{selector_text(file, statement.keyword)} = {values_text(file, statement)}"
        return Refusal(f"{context.controller.title} has no current limit keyword")


def per_channel(context: Context, file: FileView, statement: n.KeywordStatement, keyword: str) -> str | Refusal:
    """A multi-axis write as one dot-syntax write per channel (channel keywords address one)."""
    axes = selector_axes(statement.keyword)
    if axes is None and statement.keyword.selector is None and statement.keyword.channel is None:
        axes = default_axes(context, file, statement.span.start)
    if axes is None or statement.values is None:
        return Refusal(f"{keyword} takes one channel per write and the axes here are not constant")
    values = list(statement.values)
    if statement.fill and values:
        values += [values[-1]] * (len(axes) - len(values))
    writes = [
        f"{like(statement.keyword.spelling, keyword)}.{axis} = {file.slice(value.span)}"
        for axis, value in zip(axes, values, strict=False)
        if value is not None
    ]
    return " : ".join(writes) if writes else Refusal(f"{keyword}: no value to write")


class Ramp(StatementRule):
    """``RAMP`` (S-ramp 0..10) became ``SRAMP`` (0..100): the value is multiplied by 10."""

    id = "S-RAMP"
    rule_class = RuleClass.SEMI
    summary = "RAMP[axes] = v -> SRAMP[axes] = v * 10"
    evidence = "spec S-RAMP; v3:11212; v4:15444, v4:2837-2839"
    keywords = frozenset({"RAMP"})

    def caveat(self, context: Context, statement: n.KeywordStatement) -> str | None:
        if all(isinstance(value, n.Number) and value.value == 0 for value in statement.values or ()):
            return None  # no smoothing in either version
        return "SRAMP shapes the ramps differently from v3 RAMP: check the motion"  # spec S-RAMP

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None or any(value is None for value in statement.values):
            return Refusal("RAMP read or written with skipped places: SRAMP ranges 0..100 where RAMP ranged 0..10")
        values = ", ".join(_times_ten(file, value) for value in statement.values if value is not None)
        selector = selector_text(file, statement.keyword)
        fill = ";" if statement.fill else ""
        return self.unsupported(context, "SRAMP") or (
            f"{like(statement.keyword.spelling, 'SRAMP')}{selector} = {values}{fill}"
        )


def _times_ten(file: FileView, value: n.Expression) -> str:
    if isinstance(value, n.Number):
        return f"{value.value * 10:g}"
    text = file.slice(value.span)
    return f"{text} * 10" if isinstance(value, n.VariableRef | n.KeywordRef | n.Parenthesised) else f"({text}) * 10"


class IntegerScale(Rule):
    """v3 SCALE takes integers and truncates a fraction; NextMove v4 accepts fractional SCALE.
    A value that is not an integer literal (or already INT(...)) is wrapped in ``INT()``."""

    id = "M-SCALE"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "SCALE[...] = e (not an integer literal) -> SCALE[...] = INT(e)"
    evidence = "spec M-SCALE; v3:4759-4760, v3:11610; v4:15783"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, _, statement in context.statements(statement_tag("SCALE")):
            scale = _writes(statement, "SCALE")
            for value in scale.values or () if scale is not None else ():
                if value is None or _integral(value):
                    continue
                yield self.replace(file, value.span, f"INT({file.slice(value.span)})")


def _integral(value: n.Expression) -> bool:
    if isinstance(value, n.Number):
        return value.value == int(value.value)
    return isinstance(value, n.Call) and value.function == "INT"


_TERMINALS = {1: "_tmLCD1", 2: "_tmRS232", 3: "_tmRS232 + _tmLCD1"}
_TERM_CONSTANTS = {"_LCD": 1, "_SERIAL": 2, "_BOTH": 3}


class Terminal(StatementRule):
    """``TERM = v`` becomes ``TERMINAL = <bits>``: v3 values 1 LCD, 2 serial, 3 both became
    the bit constants _tmLCD1 (8) and _tmRS232 (1); +4 (VT52 mode) has no v4 equivalent.
    The v3 LCD was the keypad/display on the controller's own bus; v4's _tmLCD1 is a CAN
    keypadNode, which reaches no display until KEYPADNODE gives its node (v4:2073-2078), so
    a TERMINAL naming it gets a manual item (X-KEYPAD). So does _tmRS232 on a controller without a
    serial port (the NextMove PC cards, whose host terminal is the dual port RAM, v4:16693-16697):
    v4 ignores a channel the controller lacks (v4:2028-2029)."""

    id = "S-TERM"
    rule_class = RuleClass.SEMI
    summary = "TERM = 1/2/3 (_lcd/_serial/_both) -> TERMINAL = _tmLCD1 / _tmRS232 / _tmRS232 + _tmLCD1"
    evidence = "spec S-TERM; v3:12016-12020; v4:16653, v4:16683-16704, v4:2077"
    keywords = frozenset({"TERM"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        code = _term_code(statement)
        if code not in _TERMINALS:
            return Refusal("TERM value is not 1, 2 or 3 (VT52 mode and computed values have no v4 equivalent)")
        return f"{like(statement.keyword.spelling, 'TERMINAL')} = {_TERMINALS[code]}"

    def caveat(self, context: Context, statement: n.KeywordStatement) -> str | None:
        code = _term_code(statement)
        caveats = []
        if code in (1, 3):  # _lcd, _both
            caveats.append(
                "the v3 LCD is a CAN keypadNode in v4: give its node with KEYPADNODE._tmLCD1 = <node> (v4:2073-2078)"
            )
        if code in (2, 3) and not has_serial_port(context):  # the PC cards
            caveats.append(
                f"{context.controller.title} has no RS232 port and v4 ignores a channel the controller lacks "
                f"(v4:2028-2029): {DPR_HOST_TERMINAL}"
            )
        return "; ".join(caveats) or None


def _term_code(statement: n.KeywordStatement) -> int | None:
    """The v3 TERM value written, when it is a constant."""
    value = statement.values[0] if statement.values and len(statement.values) == 1 else None
    if isinstance(value, n.Number):
        return int(value.value) if value.value == int(value.value) else None
    if isinstance(value, n.ConstantRef):
        return _TERM_CONSTANTS.get(value.name)
    return None


class OffsetNeedsGo(Rule):
    """On NextMove a v4 OFFSET is a buffered move that starts with GO; v3 OFFSET needed none.
    ``: GO<axes>`` is added after each OFFSET write (MintDrive keeps the v3 form)."""

    id = "S-OFFSET"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "OFFSET[axes] = v -> OFFSET[axes] = v : GO[axes] (NextMove)"
    evidence = "spec S-OFFSET; v3:10402-10404; v4:14780-14784, v4:14822, v4:3506-3510"

    def apply(self, context: Context) -> Iterator[Action]:
        if not context.controller.controller.startswith("nextmove"):
            return
        for file, _, statement, after in context.neighbours(statement_tag("OFFSET")):
            offset = _writes(statement, "OFFSET")
            if offset is None or offset.values is None:
                continue
            go = _writes(after, "GO")
            selector = selector_text(file, offset.keyword)
            if go is not None and selector_text(file, go.keyword) == selector:
                continue
            yield self.replace(
                file, Span(offset.span.end, offset.span.end), f" : {like(offset.keyword.spelling, 'GO')}{selector}"
            )


_CONFIG_VALUES = {3: "_cfSTEPPER"}
_CONFIG_CONSTANTS = {"_MICRO": "_cfSTEPPER"}


class ConfigValues(StatementRule):
    """CONFIG values: v3 3/_micro (microstepper) is a stepper in v4 (3 is now _cfPWM); 4
    (_inverter) has no v4 equivalent. v4 CONFIG needs the drive disabled, and v3 files
    RESET (which in v4 enables the drive) before CONFIG: a CONFIG that follows a RESET in
    the same file is wrapped in ``DRIVEENABLE<axes> = 0;`` ... ``DRIVEENABLE<axes> = 1;``,
    which gives back the enabled state RESET left, as v3's CONFIG did not touch it."""

    id = "S-CONFIG"
    rule_class = RuleClass.SEMI
    summary = (
        "CONFIG = _micro/3 -> _cfSTEPPER; _inverter/4 -> manual; after RESET: DRIVEENABLE 0 / CONFIG / DRIVEENABLE 1"
    )
    evidence = "spec S-CONFIG; v3:4624-4649, v3:827-828; v4:8431-8443, v4:8481-8482, v4:15624-15629"
    keywords = frozenset({"CONFIG"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None:
            return None
        text = file.slice(statement.span)
        base = statement.span.start
        for value in reversed([v for v in statement.values if v is not None]):
            new = None
            if (isinstance(value, n.Number) and value.value in (4,)) or (
                isinstance(value, n.ConstantRef) and value.name == "_INVERTER"
            ):
                return Refusal("CONFIG = _inverter: Mint v4 has no inverter configuration")
            if isinstance(value, n.Number) and value.value in _CONFIG_VALUES:
                new = _CONFIG_VALUES[int(value.value)]
            elif isinstance(value, n.ConstantRef):
                new = _CONFIG_CONSTANTS.get(value.name)
            if new is not None:
                text = text[: value.span.start - base] + new + text[value.span.end - base :]
        if self._after_reset(context, file, statement):
            selector = selector_text(file, statement.keyword)
            disable = like(statement.keyword.spelling, "DRIVEENABLE") + selector
            fill = "" if selector.startswith(".") else ";"
            text = f"{disable} = 0{fill} : {text} : {disable} = 1{fill}"
        return None if text == file.slice(statement.span) else text

    @staticmethod
    def _after_reset(context: Context, file: FileView, statement: n.KeywordStatement) -> bool:
        before = file.text[file.line_start(statement.span.start) : statement.span.start]
        if "DRIVEENABLE" in before.upper():
            return False
        return any(
            use.keyword.keyword == "RESET" and use.statement.span.start < statement.span.start
            for current, use in context.keyword_uses("RESET")
            if current is file
        )


class Echo(StatementRule):
    """v3 ECHO had two bits (echo, error messages) and PON/POFF switched the prompt; v4 ECHO
    has the prompt as bit 2 ("ECHO replaces POFF and PON"). ``ECHO = v`` keeps the current
    prompt bit (``ECHO = v | (ECHO & 4)``), ``POFF`` clears it and ``PON`` sets it. A value
    that already reads ECHO is left alone. (v3 POFF also hid the INPUT prompt; v4 does not
    say that ECHO does.)"""

    id = "S-ECHO"
    rule_class = RuleClass.SEMI
    summary = "ECHO = v -> ECHO = v | (ECHO & 4); POFF -> ECHO = ECHO & 3; PON -> ECHO = ECHO | 4"
    evidence = "spec S-ECHO; v3:7504-7523, v3:10791-10847; v4:9539-9557, v4:15075, v4:15084"
    keywords = frozenset({"ECHO", "PON", "POFF"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        word = like(statement.keyword.spelling, "ECHO")
        if statement.keyword.keyword == "PON":
            return f"{word} = {word} | 4"
        if statement.keyword.keyword == "POFF":
            return f"{word} = {word} & 3"
        values = statement.values
        if values is None or len(values) != 1 or values[0] is None:
            return Refusal("ECHO takes one value")
        if any(isinstance(node, n.KeywordRef) and node.keyword == "ECHO" for node in n.walk_expression(values[0])):
            return None
        value = file.slice(values[0].span)
        if not isinstance(values[0], n.Number | n.VariableRef | n.Parenthesised):
            value = f"({value})"
        return f"{word} = {value} | ({word} & 4)"


class ErrorInput(StatementRule):
    """v3 ``ERRORIN`` chose the error input's active level (0 low, 1 high, 2 disabled); v4
    ERRORINPUT chooses the input channel (-1 none). ``ERRORIN = 2`` is ``ERRORINPUT = -1;``
    on every default axis; levels 0 and 1 need the input's number: manual item."""

    id = "S-ERRORIN"
    rule_class = RuleClass.SEMI
    summary = "ERRORIN = 2 -> ERRORINPUT = -1; (0/1 -> manual: ERRORINPUT = <input> + INPUTACTIVELEVEL)"
    evidence = "spec S-ERRORIN; v3:7861-7876; v4:10018, v4:10048-10064"
    keywords = frozenset({"ERRORIN"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        values = statement.values or ()
        if len(values) == 1 and isinstance(values[0], n.Number) and values[0].value == 2:
            return self.unsupported(context, "ERRORINPUT") or f"{like(statement.keyword.spelling, 'ERRORINPUT')} = -1;"
        return Refusal("ERRORINPUT takes the error input's number (-1 none); set its level with INPUTACTIVELEVEL")
