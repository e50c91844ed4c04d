"""Axis and channel numbers, checked against the keyword and the controller.

Brackets list axes (3.1.1), a dot names one (3.1.2): an empty place is 2001, more
axes than the controller has or more values than addressed axes is 2017, an axis listed twice
is 2018, and only constants or simple variables may stand in them (an
expression is a syntax error, 2003). A circle moves the two axes of its
brackets with three values, ``CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle>``
(000:8152, 000:8215): a third axis or a fourth value is 2017, a missing axis
2001; a vector move on one axis is 2001 too (000:16958, 17031). Channel keywords take
the dot only (``ADC[1]`` is invalid), and a keyword whose formats show no
axis or channel takes neither (``TIME.5``): both are 2003. Constant numbers out of the controller's range give
the motion library's errors: 2 axis, 4 channel, 7 input, 8 output, 26 CAN
node, 31 CAN bus, 35/36 terminal (Dot Parameters table, chapter 12.2).
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Callable, Generator, Iterator, Mapping, Sequence
from operator import attrgetter

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts, KeywordUse, LineScope, Use
from mintlang.controllers import ChannelRange, ControllerProfile, io_banks
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import CIRCLE_AXES, CIRCLES, VECTORS, Addressing, Keyword, KeywordKind
from mintlang.semantic.constants import constant_integer
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from mintlang.terminals import SERIAL_PORT_KEYWORDS, serial_port_error

_CAPTURE_CHANNELS = ChannelRange(0, 5)  # the same on every controller
_CAN_BUSES = ChannelRange(1, 2)
_CAN_NODES = ChannelRange(0, 63)  # chapter 12, error 26
_CIRCLE_VALUES = 3  # centre, centre and angle on two axes
_VECTOR_AXES = 2  # the fewest a vector move interpolates

# Which range a channel keyword's number is checked against, and the error it gives.
_Channels = Callable[[ControllerProfile], ChannelRange | None]
_CHANNEL_FAMILIES: tuple[tuple[frozenset[str], _Channels, int], ...] = (
    (frozenset({"IN", "INSTATE"}), lambda p: p.digital_inputs, 7),
    (frozenset({"OUT", "OUTX"}), lambda p: p.digital_outputs, 8),  # OUTX(channel): MintMT's OUT.channel (004:148)
    (frozenset({"ADC", "ADCMODE"}), lambda p: p.adc, 4),
    (frozenset({"AUXDAC"}), lambda p: p.auxiliary_dac, 4),
    (frozenset({"DAC", "DACLIMITMAX"}), lambda p: p.dac, 4),
    (
        frozenset({"AUXENCODER", "AUXENCODERSCALE", "AUXENCODERVEL", "AUXENCODERWRAP", "FASTAUXENCODER"}),
        lambda p: p.auxiliary_encoders,
        4,
    ),
    (
        frozenset({"ENCODER", "ENCODERPRESCALE", "ENCODERSCALE", "ENCODERVEL", "ENCODERWRAP", "FASTENCODER"}),
        lambda p: p.encoders,
        4,
    ),
)


def _channel_family(keyword: str) -> tuple[_Channels, int] | None:
    if keyword.startswith("CAPTURE"):
        return (lambda _: _CAPTURE_CHANNELS), 4
    for names, channels, code in _CHANNEL_FAMILIES:
        if keyword in names:
            return channels, code
    return None


_NOUNS = {7: "input", 8: "output"}  # the error a family's number gives tells what it numbers


def addressed(keyword: str, controller: ControllerProfile) -> tuple[str, ChannelRange] | None:
    """What the number after ``keyword.`` is on ``controller`` ("axis", "input", "channel") and its valid range;
    the editor offers these numbers after the dot. None for keywords numbered otherwise (CAN, terminals)."""
    found = database().keywords.get(keyword)
    if found is not None and found.addressing is Addressing.AXIS:
        return "axis", controller.axes
    family = _channel_family(keyword)
    valid = family[0](controller) if family is not None else None
    return (_NOUNS.get(family[1], "channel"), valid) if family is not None and valid is not None else None


def each_line(scope: LineScope) -> Iterator[Finding]:
    for use in scope.facts.keyword_uses:
        yield from _keyword(use, scope)
    for statement in scope.facts.statements:
        if isinstance(statement, n.Axes):
            yield from _axes_statement(scope.unit, statement, scope)
        elif type(statement) is n.FunctionStatement:
            yield from _function_axis(statement.call, scope)


# A straight run of lines: statements that neither jump, branch, loop nor may be arrived at from elsewhere.
_RUN_ON = frozenset({n.Assignment, n.KeywordStatement, n.Pause, n.Dim, n.Define, n.Print, n.Input, n.Axes})
_AXES = frozenset({n.Axes})
_ORIGIN = attrgetter("origin")  # where a placed line starts: the order of a file's lines


def check(facts: Facts) -> Iterator[Finding]:
    """Writes to the default axes with more values than the AXES list set before them: 2017 when the line runs.

    AXES sets the default axes at run time (000:590-606, 627-639), so its list is known only up to whatever could
    change it unseen or be arrived at without it: a label (a GOTO or GOSUB may land there), a jump, a
    block word, IF .. THEN, a statement that could not be read. More values than the controller's axes
    the line rule reports; the values that fit it but not the list are reported here.
    """
    model = facts.model
    walked: dict[Unit, int] = {}  # per file, the index of the line after the last run followed
    for unit, axes_line, _ in facts.lines.with_kinds(_AXES):  # only the runs from an AXES line are read
        lines = model.document(unit).placed
        start = bisect_left(lines, axes_line.origin, key=_ORIGIN)
        if start >= walked.get(unit, 0):
            walked[unit] = yield from _run(unit, lines, start, model)


def _run(unit: Unit, lines: Sequence[n.PlacedLine], start: int, model: SemanticModel) -> Generator[Finding, None, int]:
    """The findings of the straight run from the AXES line ``lines[start]``; returns where the run ends."""
    keywords = database().keywords_of(model.program.dialect)
    controller = model.controller
    listed: tuple[int, int] | None = None  # how many axes the AXES in force lists, and its line
    for index in range(start, len(lines)):
        line = lines[index]
        if line.syntax.label is not None:
            listed = None
        for statement in line.syntax.statements:
            kind = type(statement)
            if kind is n.Axes:
                listed = _listed(statement, line.number, controller)  # type: ignore[arg-type]
            elif kind not in _RUN_ON:
                listed = None
            elif listed is not None and kind is n.KeywordStatement:
                found = _beyond_the_list(statement, keywords, controller, listed)  # type: ignore[arg-type]
                if found is not None:
                    yield Finding(unit, mint_error(2017, line.span(found[0]), found[1]))
        if listed is None:
            return index + 1
    return len(lines)


def _listed(statement: n.Axes, number: int, controller: ControllerProfile) -> tuple[int, int] | None:
    """How many axes ``AXES[...]`` lists, and its line; None where it fails itself (2001, 2017, 2018)."""
    axes = statement.selector.axes if statement.selector is not None else ()
    if not axes or None in axes or len(axes) > controller.axis_count:
        return None
    constants = [constant_integer(item) for item in axes]
    known = [axis for axis in constants if axis is not None]
    return (len(axes), number) if len(set(known)) == len(known) else None


def _beyond_the_list(
    statement: n.KeywordStatement,
    keywords: Mapping[str, Keyword],
    controller: ControllerProfile,
    listed: tuple[int, int],
) -> tuple[Span, str] | None:
    """Where a write to the default axes has more values than the AXES list in force, and what to say."""
    ref = statement.keyword
    keyword = keywords.get(ref.keyword)
    if (
        keyword is None
        or keyword.addressing is not Addressing.AXIS
        or keyword.name in CIRCLES
        or not keyword.available_on(controller.controller)
        or ref.selector is not None
        or ref.channel is not None
        or statement.values is None
        or len(statement.values) > controller.axis_count  # the line rule's finding
    ):
        return None
    count, number = listed
    span = _past(statement, count)
    if span is None:
        return None
    axes = f"ax{'is' if count == 1 else 'es'}"
    return span, f"{len(statement.values)} values for {count} {axes} (the AXES list of line {number})"


def _keyword(use: KeywordUse, scope: LineScope) -> Iterator[Finding]:
    keyword = database().keywords_of(scope.dialect).get(use.keyword.keyword)
    if keyword is None or not keyword.available_on(scope.controller.controller):
        return  # not a keyword of this controller: 17 (keyword usage) says so, its channels are moot
    if keyword.one_value_a_write:  # OUT.1 = 1,0: a channel keyword takes one value, with or without its channel
        yield from one_value(use, keyword.name)
    if use.keyword.selector is None and use.keyword.channel is None:
        if missing := _unaddressed(keyword):
            yield Finding(use.unit, mint_error(2001, use.keyword.span, f"{missing} is missing: {_layout(keyword)}"))
            return
        # Nothing addressed: the default axes, whatever AXES made them, are at most the controller's
        # (000:572, 605-606, #2017 at 19047); a circle's three values go to two of them.
        if keyword.addressing is Addressing.AXIS and keyword.name not in CIRCLES:
            yield from values_for_axes(use, scope.controller.axis_count)
        if keyword.name in VECTORS:
            yield from _one_position(use, keyword.name)
            yield from vector_gap(use, keyword.name)
        elif keyword.name in CIRCLES:
            yield from circle_values(use, keyword.name)
        return
    found = misaddressed(use.keyword, keyword, scope.dialect)
    if found is not None:
        yield Finding(use.unit, mint_error(2003, *found))
    if keyword.name.startswith("REMOTE"):
        yield from _can_address(use)
    elif keyword.name in SERIAL_PORT_KEYWORDS:
        yield from _terminal(use, scope)
    elif keyword.addressing is Addressing.AXIS:
        yield from _axes(use, scope, keyword.name)
        yield from _indices(use, keyword, scope)
    elif keyword.addressing is Addressing.CHANNEL or _channel_family(keyword.name):
        yield from _channel(use, scope)


_ADDRESSED_KINDS = frozenset({KeywordKind.PARAMETER, KeywordKind.COMMAND})


def misaddressed(ref: n.KeywordRef, keyword: Keyword, dialect: Dialect) -> tuple[Span, str] | None:
    """Where and why ``ref`` addresses ``keyword`` as none of its formats do, a syntax error (2003) the compiler
    stops the program on, and the debugger an expression typed at it (``TIME.2`` evaluates nothing).

    A dot names one axis or channel (000:678-679); several axes are listed in brackets (000:563-566), and a
    channel keyword addresses one channel a call (000:548-549). A second number after the dot (``POS.1.5``), or
    a dot after a channel glued to its keyword (``OUT1.2``), is an addressing no format shows, as ``TIME.5`` is:
    an axis or channel number on a keyword whose formats take none. The guide names no error for that; it
    writes such a keyword only as its formats show it (``v = TIME``, 000:16737-16738), and an addressing its
    formats do not show is invalid as ``ADC[1]`` is (000:702-708). Only the CAN keywords chain two numbers, a
    bus and a node (``REMOTEIN.2.65``, 000:18607)."""
    if (ref.selector is None and ref.channel is None) or keyword.name.startswith("REMOTE"):
        return None
    if (
        keyword.name in SERIAL_PORT_KEYWORDS
        or keyword.addressing is Addressing.CHANNEL
        or _channel_family(keyword.name)
    ):
        return _one_number_after_the_dot(ref, "channel", brackets=dialect is Dialect.MINTMT)
    if keyword.addressing is Addressing.AXIS:
        return _one_number_after_the_dot(ref, "axis")
    if dialect.modern and keyword.documented and keyword.formats and keyword.kind in _ADDRESSED_KINDS:
        span = ref.selector.span if ref.selector is not None else ref.spelling_span
        shown = " or ".join(f"'{layout}'" for layout in keyword.formats)
        return span, f"{keyword.name} takes no axis or channel number: {shown}"
    return None


def _one_number_after_the_dot(ref: n.KeywordRef, addressed: str, *, brackets: bool = False) -> tuple[Span, str] | None:
    """``brackets``: MintMT's round brackets name a channel keyword's channel as v4's dot does (``OUTX(0)``,
    004:148), so they hold one number too."""
    selector = ref.selector
    if selector is None or not (selector.dot or brackets) or not selector.items:
        return None
    if ref.channel is not None:
        return (
            selector.span,
            f"{ref.spelling} already names channel {ref.channel}: no {'dot' if selector.dot else 'brackets'} after it",
        )
    where = "after its dot" if selector.dot else "between its brackets"
    if len(selector.axes) > 1 and (first := selector.items[0]) is not None:
        detail = f"{ref.keyword} takes one {addressed} number {where}"
        if addressed == "axis":
            detail += " (several axes are listed in brackets)"
        return Span(first.span.end, selector.span.end), detail
    return None


def _function_axis(call: n.Call, scope: LineScope) -> Iterator[Finding]:
    """A function loaded on an axis names it first, ``CAMTABLE ( axis, position array, ...)`` (000:7907-7910):
    an axis the controller lacks is error 2 there as after a dot."""
    keyword = database().keywords_of(scope.dialect).get(call.function)
    if (
        keyword is not None
        and keyword.addressing is Addressing.AXIS
        and call.arguments
        and keyword.available_on(scope.controller.controller)
    ):
        yield from _axis_number(scope.unit, call.arguments[0], scope)


def _axes(use: KeywordUse, scope: LineScope, name: str) -> Iterator[Finding]:
    selector = use.keyword.selector
    if selector is None:
        return
    if selector.dot:  # one axis, as POS.1 or POS.(a+1) (000:677-681)
        for item in selector.items[:1]:
            yield from _axis_number(use.unit, item, scope)
    else:
        yield from _axis_list(use.unit, selector, scope, use.keyword.spelling)
    listed = 1 if selector.dot else len(selector.axes)
    if name in CIRCLES:
        yield from _circle(use, selector, name, listed)
        return
    if name in VECTORS and 0 < listed < _VECTOR_AXES:  # an empty place is the axis list's own 2001
        detail = f"{name} interpolates two axes or more, {listed} listed"
        yield Finding(use.unit, mint_error(2001, selector.span, detail))
    elif name in VECTORS:
        yield from _one_position(use, name)
        yield from vector_gap(use, name)
    yield from values_for_axes(use, listed)


def _one_position(use: KeywordUse, name: str) -> Iterator[Finding]:
    """A vector move written one position: the axes past the values are left out (000:578-580), which leaves
    one, and a vector interpolates two or more (000:16958, 17031)."""
    position = lone_position(use)
    if position is not None:
        detail = f"{name} interpolates two axes or more: one position given"
        yield Finding(use.unit, mint_error(2001, position.span, detail))


def vector_gap(use: KeywordUse, name: str) -> Iterator[Finding]:
    """A vector move with a place left empty (``VECTORR[0,1] = ,100``) is Missing parameter, 2001: a vector
    interpolates every axis it is given a position for, from one start to one end (000:16958, 17031), and the
    v3 guide gives this very line as its example of a missing parameter (001:13100-13109)."""
    values = _written(use)
    if values is not None and None in values:
        detail = f"{name} needs a position on each axis it moves: a place is left empty"
        yield Finding(use.unit, mint_error(2001, use.statement.span, detail))


def one_value(use: KeywordUse, name: str) -> Iterator[Finding]:
    """2017 at the second value written to a keyword whose write takes one (``OUT.1 = 1, 0``)."""
    yield from _too_many_values(use, 1, lambda count: f"{count} values; {name} takes one")


def lone_position(use: KeywordUse) -> n.Expression | None:
    """The value of a write given one value and no place left empty (``VECTORA[0,1] = 5``), if it is one; a
    semicolon after it gives it to every axis (``VECTORA[0,1] = 5;``, 000:654-659), which makes it no lone one."""
    values = _written(use)
    fills = isinstance(use.statement, n.KeywordStatement) and use.statement.fill
    return values[0] if values is not None and len(values) == 1 and not fills else None


def _written(use: KeywordUse) -> tuple[n.Expression | None, ...] | None:
    """The values a write gives its keyword (None in the places left empty); None for a read or a command."""
    statement = use.statement
    return statement.values if use.use is Use.WRITE and isinstance(statement, n.KeywordStatement) else None


def _indices(use: KeywordUse, keyword: Keyword, scope: LineScope) -> Iterator[Finding]:
    """MintMT's items after the axes (``MOVEOUT(axis, bank)``, ``CONTOURPARAMETER(axes, index)``, 004:232, 295):
    one left out is 2001, as in ``MOVEOUT(0) = 7``, which would otherwise read as a bank-less write to axis 0;
    an output move names one axis (its format's ``axis``), so a second one is 2017, an output channel
    the controller lacks (``MOVEOUTX(0, 99)``) is 8 and a bank it lacks (``MOVEOUT(0, 3)``) 3, as the run says
    when the line loads it (MT-22): its banks are ``io_banks``', the run's."""
    selector = use.keyword.selector
    if not keyword.indices or selector is None:
        return
    layout = _layout(keyword)
    if selector.indices < len(keyword.indices):
        missing = " and ".join(keyword.indices[selector.indices :])
        yield Finding(use.unit, mint_error(2001, selector.span, f"the {missing} after the axes is missing: {layout}"))
    elif layout.upper().startswith(f"{keyword.name}(AXIS,") and len(selector.axes) > 1:
        detail = f"{len(selector.axes)} axes listed: {layout} is loaded on one axis"
        yield Finding(use.unit, mint_error(2017, selector.span, detail))
    if keyword.indices[-1] == "channel" and selector.indices == len(keyword.indices):
        item = selector.items[-1]
        number = constant_integer(item, scope.dialect)
        outputs = scope.controller.digital_outputs
        if item is not None and number is not None and (outputs is None or number not in outputs):
            available = _held(outputs)
            detail = f"{keyword.name} channel {number} does not exist on {scope.controller.title} ({available})"
            yield Finding(use.unit, mint_error(8, item.span, detail))
    if keyword.indices[-1] == "bank" and selector.indices == len(keyword.indices):
        item = selector.items[-1]
        number = constant_integer(item, scope.dialect)
        banks = ChannelRange(0, io_banks(scope.controller).count - 1)  # one a card
        if item is not None and number is not None and number not in banks:
            available = _held(banks, "bank", "banks")
            detail = f"{keyword.name} bank {number} does not exist on {scope.controller.title} ({available})"
            yield Finding(use.unit, mint_error(3, item.span, detail))


def _layout(keyword: Keyword) -> str:
    """The keyword as its first format addresses it: ``MOVEOUT(axis, bank)``."""
    return keyword.formats[0].split("=")[0].strip() if keyword.formats else keyword.name


def _unaddressed(keyword: Keyword) -> str:
    """What a MintMT keyword written bare leaves out, which no default stands for ("" when nothing): the
    indices after its axes (``MOVEOUT = 7``, MT-22) or, where every format names it, its one channel
    (``OUTX = 1``: OUTX is one output, 004:148, never v4's bank ``OUT``)."""
    if keyword.indices:
        return f"the {' and '.join(keyword.indices)} after the axes"
    if keyword.formats and all(f"{keyword.name}(channel)" in layout for layout in keyword.formats):
        return "the channel"
    return ""


def values_for_axes(use: KeywordUse, axes: int) -> Iterator[Finding]:
    """More values written than there are axes to take them: 2017 at the first one too many."""
    detail = f"ax{'is' if axes == 1 else 'es'}"
    yield from _too_many_values(use, axes, lambda count: f"{count} values for {axes} {detail}")


def _circle(use: KeywordUse, selector: n.Selector, name: str, listed: int) -> Iterator[Finding]:
    """Two axes addressed and three values."""
    detail = f"{_circle_shape(name)} moves two axes, {listed} listed"
    if listed > CIRCLE_AXES:
        yield Finding(use.unit, mint_error(2017, selector.span, detail))
    elif listed < CIRCLE_AXES:
        yield Finding(use.unit, mint_error(2001, selector.span, detail))
    yield from circle_values(use, name)


def circle_values(use: KeywordUse, name: str) -> Iterator[Finding]:
    """A circle written takes its three values, each given: both centre coordinates and the angle are in its
    format and in every example of the guide (000:8152, 8215), and ``mint-run`` refuses one without them."""
    shape = _circle_shape(name)
    yield from _too_many_values(use, _CIRCLE_VALUES, lambda count: f"{count} values; {shape} takes three")
    values = _written(use)
    if values is not None and (len(values) < _CIRCLE_VALUES or None in values):
        detail = f"{shape}: a centre on each axis and an angle are needed"
        yield Finding(use.unit, mint_error(2001, use.statement.span, detail))


def _circle_shape(name: str) -> str:
    return f"{name}[axis0,axis1] = <centre0>,<centre1>,<angle>"


def _too_many_values(use: KeywordUse, most: int, detail: Callable[[int], str]) -> Iterator[Finding]:
    """2017 at the first value past ``most`` in a write."""
    statement = use.statement
    if use.use is Use.WRITE and isinstance(statement, n.KeywordStatement):
        span = _past(statement, most)
        if span is not None and statement.values is not None:
            yield Finding(use.unit, mint_error(2017, span, detail(len(statement.values))))


def _past(statement: n.KeywordStatement, most: int) -> Span | None:
    """Where a write has more than ``most`` values: its first value written past them (in ``SPEED[0,1] = ,,,20``
    the 20), or the statement where those are all left out; None if the values fit."""
    values = statement.values
    if values is None or len(values) <= most:
        return None
    return next((value.span for value in values[most:] if value is not None), statement.span)


def _axis_list(unit: Unit, selector: n.Selector, scope: LineScope, keyword: str | None) -> Iterator[Finding]:
    """The axes listed in brackets after ``keyword`` as written (None: AXES, whose list has no dot form)."""
    axes = selector.axes
    too_many = len(axes) > scope.controller.axis_count
    if too_many:
        detail = f"{len(axes)} axes listed, {scope.controller.title} has {scope.controller.axis_count}"
        yield Finding(unit, mint_error(2017, selector.span, detail))
    seen: set[int] = set()
    for place, item in enumerate(axes):
        if item is None:
            yield Finding(unit, mint_error(2001, selector.span, _missing_axis(place, len(axes))))
            continue
        if not isinstance(item, n.Number | n.VariableRef | n.ConstantRef):
            written = scope.syntax.text[item.span.start : item.span.end]
            advice = f"give {written} to a variable first"  # 000:584-589
            if keyword is not None and len(axes) == 1:  # one axis: the dot takes an expression (000:694-700)
                advice = f"write {keyword}.({written}), or {advice}"
            detail = f"an axis number in brackets must be a number or a simple variable: {advice}"
            yield Finding(unit, mint_error(2003, item.span, detail))
            continue
        axis = constant_integer(item, scope.dialect)
        if axis is not None and axis in seen:
            yield Finding(unit, mint_error(2018, item.span, f"axis {axis} is listed twice"))
        elif axis is not None:
            seen.add(axis)
            if not too_many:  # 2017 already says the list does not fit
                yield from _axis_number(unit, item, scope)


def _held(numbers: ChannelRange | None, noun: str = "channel", nouns: str = "channels") -> str:
    """What a controller has of an axis or channel, read as a whole: "axis 0 only" where the Dot Parameters
    table gives ``x = 0`` (000:5612-5621), "axes 0 to 7" for a span, "none" where it has none."""
    if numbers is None:
        return "none"
    if numbers.low == numbers.high:
        return f"{noun} {numbers} only"
    return f"{nouns} {numbers}"


def _missing_axis(place: int, count: int) -> str:
    """Where the empty place of an axis list is, as the author fills it (000:18909-18914)."""
    if count == 1:  # GO[] has no comma
        return "no axis number between the brackets"
    if place == count - 1:
        return "an axis number is missing after the last comma"
    if place == 0:
        return "an axis number is missing before the first comma"
    return "an axis number is missing between the commas"


def _axis_number(unit: Unit, item: n.Expression | None, scope: LineScope) -> Iterator[Finding]:
    axis = constant_integer(item, scope.dialect)
    if item is not None and axis is not None and axis not in scope.controller.axes:
        detail = (
            f"axis {axis} does not exist on {scope.controller.title} ({_held(scope.controller.axes, 'axis', 'axes')})"
        )
        yield Finding(unit, mint_error(2, item.span, detail))


def _channel(use: KeywordUse, scope: LineScope) -> Iterator[Finding]:
    ref = use.keyword
    selector = ref.selector
    if selector is not None and not selector.dot and scope.dialect is not Dialect.MINTMT:  # MintMT: OUTX(0)
        detail = f"{ref.keyword} addresses a channel: write {ref.keyword}.{_first_text(selector)}, not brackets"
        yield Finding(use.unit, mint_error(2003, selector.span, detail))
        return
    family = _channel_family(ref.keyword)
    if family is None:
        return
    channels, code = family
    span: Span
    if ref.channel is not None:
        number, span = ref.channel, ref.spelling_span
    elif selector is not None and selector.items:
        item = selector.items[0]
        number = constant_integer(item, scope.dialect)
        span = item.span if item is not None else selector.span
    else:
        return
    valid = channels(scope.controller)
    if number is not None and (valid is None or number not in valid):
        available = _held(valid)
        detail = f"{ref.keyword} channel {number} does not exist on {scope.controller.title} ({available})"
        yield Finding(use.unit, mint_error(code, span, detail))


def _first_text(selector: n.Selector) -> str:
    first = selector.items[0] if selector.items else None
    return first.text if isinstance(first, n.Number) else "channel"


def _can_address(use: KeywordUse) -> Iterator[Finding]:
    selector = use.keyword.selector
    if selector is None or not selector.dot or len(selector.items) < 2:
        return
    bus_item, node_item = selector.items[0], selector.items[1]
    bus, node = constant_integer(bus_item), constant_integer(node_item)
    if bus is not None and bus_item is not None and bus not in _CAN_BUSES:
        yield Finding(use.unit, mint_error(31, bus_item.span, f"CAN bus {bus} does not exist (buses {_CAN_BUSES})"))
    if node is not None and node_item is not None and node not in _CAN_NODES:
        yield Finding(use.unit, mint_error(26, node_item.span, f"CAN node {node} is out of range ({_CAN_NODES})"))


def _terminal(use: KeywordUse, scope: LineScope) -> Iterator[Finding]:
    """COMMSMODE and SERIALBAUD take a serial terminal: _tmRS232 or _tmRS485."""
    selector = use.keyword.selector
    if selector is None or not selector.dot or not selector.items:
        return
    item = selector.items[0]
    value = constant_integer(item, scope.dialect)
    if value is None or item is None:
        return
    found = serial_port_error(use.keyword.keyword, value)
    if found is not None:
        yield Finding(use.unit, mint_error(found[0], item.span, found[1]))


def _axes_statement(unit: Unit, statement: n.Axes, scope: LineScope) -> Iterator[Finding]:
    if statement.selector is None:
        yield from axes_alone(unit, statement)
        return
    yield from _axis_list(unit, statement.selector, scope, None)


def axes_alone(unit: Unit, statement: n.Axes) -> Iterator[Finding]:
    """``AXES`` without its list, which reports the axes at the command line and fails in a program (v3's
    run time error too, 001:1027): 2005, as the run stops on it."""
    if statement.selector is None:
        detail = "AXES without an axis list only reports the axes at the command line; in a program it fails"
        yield Finding(unit, mint_error(2005, statement.span, detail))
