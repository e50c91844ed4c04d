"""Compiling expressions into functions.

Each expression becomes a function of no arguments that returns a binary32
value, so evaluating ``POS.0 + 2 * a`` at run time is no tree walk: operators
and the variables and literals under them are generated as one Python function
(``generated.py``), which calls a closure only for what is not arithmetic (a
keyword's read, an array element, a function). Keywords are resolved to their handlers here, once; axis-addressed
keywords written without a selector read the first of the default axes
(``AXES``), and a bracket list reads every axis and ANDs the results bitwise
(v4 guide 3.1.1).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import field

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.records import record
from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.errors import (
    INVALID_AXIS,
    INVALID_INDEX,
    MISSING_PARAMETER,
    SYNTAX_ERROR,
    MintError,
    NotSimulated,
)
from mintlang.runtime.interpreter import generated
from mintlang.runtime.interpreter.generated import Emitter, Source
from mintlang.runtime.interpreter.vm import Interpreter
from mintlang.runtime.keywords import AXIS_SET_TWICE, KeywordTable, Reader
from mintlang.runtime.numbers import bits24, f32, held
from mintlang.runtime.semantics import Semantics
from mintlang.syntax import nodes as n
from mintlang.syntax.v3_axis_lists import NUMBER_OR_VARIABLE, refused_axes

Evaluate = Callable[[], float]

READ_OF_COMMAND = 2000
READ_OF_WRITE_ONLY = 2002
NESTING = 40  # operations nested in one generated function: at most two brackets each, of Python's 200


@record(frozen=False)
class Names:
    """Storage slots of the application's variables and arrays, by 10-character identity."""

    scalars: dict[str, int] = field(default_factory=dict)
    arrays: dict[str, int] = field(default_factory=dict)
    macros: frozenset[str] = frozenset()  # a macro's name left in another macro's text is not expanded


class ExpressionCompiler:
    def __init__(self, vm: Interpreter, table: KeywordTable, names: Names, semantics: Semantics) -> None:
        self.vm = vm
        self.table = table
        self.names = names
        self.semantics = semantics
        self.plain: set[str] = set()  # the names compiled as plain variables, arrays' names among them (000:1086)

    def compile(self, expression: n.Expression) -> Evaluate:
        kind = type(expression)
        if kind is n.Number or kind is n.CharConstant:
            value = self.literal(expression)  # type: ignore[arg-type]
            return lambda: value
        if kind is n.Parenthesised:
            return self.compile(expression.expression)  # type: ignore[union-attr]
        if kind is n.VariableRef:
            return self.variable(expression.name)  # type: ignore[union-attr]
        if kind is n.ElementRef:
            return self.element(expression)  # type: ignore[arg-type]
        if kind is n.Binary or kind is n.Unary:
            emitter = Emitter()
            return emitter.expression(self.source(expression, emitter))
        if kind is n.ConstantRef:
            return self.constant(expression)  # type: ignore[arg-type]
        if kind is n.KeywordRef:
            return self.keyword(expression)  # type: ignore[arg-type]
        if kind is n.Call:
            return self.call(expression)  # type: ignore[arg-type]
        raise TypeError(f"not an expression: {expression!r}")

    def literal(self, expression: n.Number | n.CharConstant) -> float:
        """A number as written, as the dialect holds it (``numbers.held``)."""
        return held(float(expression.value), self.semantics.number)

    def source(self, expression: n.Expression, emitter: Emitter, depth: int = 0) -> Source:
        """``expression`` as the text of a generated function (``generated.py``), its values named by ``emitter``.

        ``depth`` counts the operations around it in that text: each nests a bracket or two, and Python
        compiles no more than 200 (a 255-character line holds over a hundred ``+``), so an operand
        ``NESTING`` deep becomes a generated function of its own that this text calls."""
        kind = type(expression)
        if kind is n.Parenthesised:
            return self.source(expression.expression, emitter, depth)  # type: ignore[union-attr]
        if depth >= NESTING and (kind is n.Binary or kind is n.Unary or kind is n.Call):
            return Source(emitter.call(self.compile(expression)))
        if kind is n.Number or kind is n.CharConstant:
            return Source(emitter.name(self.literal(expression)), binary32=self.semantics.number is f32)  # type: ignore[arg-type]
        if kind is n.VariableRef and expression.name.identity not in self.names.macros:  # type: ignore[union-attr]
            return Source(emitter.scalar(self.vm.scalars, self.scalar_slot(expression.name)))  # type: ignore[union-attr]
        if kind is n.ConstantRef:
            return Source(emitter.name(self.constant_value(expression)))  # type: ignore[arg-type]
        if kind is n.Binary:
            left = self.source(expression.left, emitter, depth + 1)  # type: ignore[union-attr]
            right = self.source(expression.right, emitter, depth + 1)  # type: ignore[union-attr]
            return generated.binary(emitter, self.semantics.binary[expression.operator], left, right)  # type: ignore[union-attr]
        if kind is n.Unary:
            operand = self.source(expression.operand, emitter, depth + 1)  # type: ignore[union-attr]
            return generated.unary(emitter, self.semantics.unary[expression.operator], operand)  # type: ignore[union-attr]
        if kind is n.Call and expression.function in self.semantics.functions:  # type: ignore[union-attr]
            arguments = (self.source(argument, emitter, depth + 1).text for argument in expression.arguments)  # type: ignore[union-attr]
            return Source(emitter.call(self.semantics.functions[expression.function], *arguments))  # type: ignore[union-attr]
        return Source(emitter.call(self.compile(expression)))

    def complete_horizon(self, expression: n.Expression) -> bool:
        """Whether reading ``expression`` reports in ``clock.horizon`` every tick at which its value may change.

        Variables and literals change only when the program runs; a keyword only where its reader says so
        (``KeywordAccess.complete_horizon``). A PAUSE on such a condition need not be tried before then.
        """
        kind = type(expression)
        if kind is n.Number or kind is n.CharConstant or kind is n.ConstantRef or kind is n.VariableRef:
            return True
        if kind is n.KeywordRef:
            access = self.table.get(expression.keyword)  # type: ignore[union-attr]
            selector = expression.selector  # type: ignore[union-attr]
            channels = [item for item in selector.items if item is not None] if selector is not None else []
            return access is not None and access.complete_horizon and all(map(self.complete_horizon, channels))
        if kind is n.Call and expression.function not in self.semantics.functions:  # type: ignore[union-attr]
            return False
        return all(self.complete_horizon(child) for child in _operands(expression))

    def scalar_slot(self, name: n.Name) -> int:
        """Where the scalar variable ``name`` is kept in ``vm.scalars``."""
        self.plain.add(name.identity)
        slot = self.names.scalars.get(name.identity)
        if slot is None:  # an array name used as a scalar without ever being one: its own scalar slot
            slot = self.names.scalars[name.identity] = len(self.vm.scalars)
            self.vm.scalars.append(0.0)
        return slot

    def variable(self, name: n.Name) -> Evaluate:
        if name.identity in self.names.macros:

            def unexpanded() -> float:  # 000:1549-1553: a syntax error when the line runs
                raise MintError(SYNTAX_ERROR, detail=f"macro {name.text} is not expanded inside another macro")

            return unexpanded
        slot = self.scalar_slot(name)
        scalars = self.vm.scalars
        return lambda: scalars[slot]

    def element_slot(self, name: n.Name) -> list[float]:
        slot = self.names.arrays.get(name.identity)
        if slot is None:
            raise MintError(INVALID_INDEX, detail=f"{name.text} is not an array")
        return self.vm.arrays[slot]

    def element(self, expression: n.ElementRef) -> Evaluate:
        values = self.element_slot(expression.name)
        index = self.compile(expression.index)
        size = len(values)

        def read() -> float:
            position = int(index())
            if not 1 <= position <= size:
                raise MintError(INVALID_INDEX, detail=f"index {position} outside 1 to {size}")
            return values[position - 1]

        return read

    def constant(self, expression: n.ConstantRef) -> Evaluate:
        value = self.constant_value(expression)
        return lambda: value

    def constant_value(self, expression: n.ConstantRef) -> float:
        value = self.semantics.constants.get(expression.name.upper())
        if value is None:
            raise NotSimulated(expression.name, "constant")
        return value

    def read_refused(self, name: str) -> int:
        """The error of reading ``name``, which gives no value: v3 calls reading a command "Read only or
        Command" (``a = STOP``, 001:13083-13094) and keeps "Write only" for a write only keyword (``a = FLY``,
        001:13073-13080); v4 names only the latter (000:18915-18918)."""
        if self.semantics.dialect is Dialect.V3:
            keyword = database().lookup_v3(name)
            if keyword is not None and keyword.command and not keyword.write:
                return READ_OF_COMMAND
        return READ_OF_WRITE_ONLY

    def keyword(self, reference: n.KeywordRef) -> Evaluate:
        read = self.reader(reference)
        number = self.semantics.number  # a parameter kept in counts reads divided by SCALE: held as any value
        channels = self.channels(reference)
        if channels is None:
            return lambda: number(read(None))
        if isinstance(channels, tuple):
            single = channels
            if len(single) == 1:
                only = single[0]
                return lambda: number(read(int(only())))

            clock = self.vm.clock
            constant = _constants(reference)
            if constant is not None and len(set(constant)) == len(constant):
                return lambda: _and_of_reads(read, constant, clock)  # IDLE[0,1] in a PAUSE: no channel to evaluate
            return lambda: _and_of_reads(read, _distinct([int(channel()) for channel in single]), clock)
        default_axes = channels
        vm = self.vm
        return lambda: number(read(vm.default_axes[0]) if default_axes else read(None))

    def reader(self, reference: n.KeywordRef) -> Reader:
        """The keyword's reader of one channel; MintMT's indices after the axes (``CONTOURPARAMETER(0,0)``) are
        evaluated with each read and go to the keyword with the channel, and leaving them out is error 2001."""
        access = self.table.in_program(reference.keyword)
        if access is not None and access.indexed_read is not None:
            selector = reference.selector
            if selector is None or not selector.indices:
                raise MintError(MISSING_PARAMETER, detail=f"{reference.keyword} needs its index after the axes")
            indexed = access.indexed_read
            indices = tuple(self.compile(item) for item in selector.items[-selector.indices :] if item)
            return lambda channel: indexed(channel, tuple(int(index()) for index in indices))
        if access is None or access.read is None:
            handled = access is not None and (access.write is not None or access.command is not None)
            unreadable = handled and not self.table.decides(reference.keyword)
            if unreadable or self.table.refused_by_the_guide(reference.keyword, write=False):  # a = WAIT
                raise MintError(self.read_refused(reference.keyword), detail=reference.keyword)
            raise NotSimulated(reference.keyword, "read")
        return access.read

    def channels(self, reference: n.KeywordRef) -> tuple[Evaluate, ...] | bool | None:
        """The channel expressions; ``True`` for the default axes, ``None`` for no channel at all."""
        if reference.channel is not None:
            glued = float(reference.channel)
            return (lambda: glued,)
        selector = reference.selector
        if selector is not None:
            if self.semantics.dialect is Dialect.V3 and next(refused_axes(selector), None) is not None:
                raise MintError(INVALID_AXIS, detail=NUMBER_OR_VARIABLE)
            return tuple(self.compile(item) if item is not None else _missing for item in selector.axes)
        return True if reference.keyword in self.semantics.axis_keywords else None

    def call(self, call: n.Call) -> Evaluate:
        arguments = tuple(self.compile(argument) for argument in call.arguments)
        function = self.semantics.functions.get(call.function)
        if function is not None:
            if len(arguments) == 1:
                (only,) = arguments
                return lambda: function(only())
            return lambda: function(*(argument() for argument in arguments))
        access = self.table.in_program(call.function)
        if access is None or access.read is None:
            raise NotSimulated(call.function, "function")
        read = access.read
        if len(arguments) != 1:
            raise NotSimulated(call.function, f"{len(arguments)} arguments")
        (index,) = arguments
        return lambda: read(int(index()))


def _and_of_reads(read: Reader, channels: Iterable[int], clock: Clock) -> float:
    """Several axes read at once, ANDed bitwise (v4 guide 3.1.1).

    For flags (every value 0 or 1) that AND to 0, the result can only change once every axis
    reading 0 has changed, so it stays valid until the latest of their horizons: a PAUSE on
    ``IDLE[0,1,2,3]`` sleeps until the last axis can stop, not the first.
    """
    outer = clock.horizon
    result = 0xFFFFFF
    soonest, latest_zero, flags = NEVER, -1, True
    for channel in channels:
        clock.horizon = NEVER
        number = read(channel)
        value = 1 if number == 1.0 else 0 if number == 0.0 else bits24(number)
        horizon = clock.horizon
        soonest = min(soonest, horizon)
        if value == 0:
            latest_zero = max(latest_zero, horizon)
        elif value != 1:
            flags = False
        result &= value
    valid = latest_zero if flags and result == 0 else soonest
    clock.horizon = min(outer, valid)
    return float(result)


def _distinct(channels: list[int]) -> list[int]:
    """The axes of a bracket list read, each named once: the same one twice is error 2018 (000:19053-19055)."""
    if len(set(channels)) != len(channels):
        raise MintError(AXIS_SET_TWICE, detail="an axis is named twice")
    return channels


def _constants(reference: n.KeywordRef) -> tuple[int, ...] | None:
    """The axes of a selector written with literal numbers only, such as ``[0,1]``."""
    selector = reference.selector
    if selector is None or not all(type(item) is n.Number for item in selector.axes):
        return None
    return tuple(int(item.value) for item in selector.axes)  # type: ignore[union-attr]


def _operands(expression: n.Expression) -> tuple[n.Expression, ...]:
    """The expressions an operator, a parenthesis, an array element or a function call is made of."""
    kind = type(expression)
    if kind is n.Binary:
        return (expression.left, expression.right)  # type: ignore[union-attr]
    if kind is n.Unary:
        return (expression.operand,)  # type: ignore[union-attr]
    if kind is n.Parenthesised:
        return (expression.expression,)  # type: ignore[union-attr]
    if kind is n.ElementRef:
        return (expression.index,)  # type: ignore[union-attr]
    return tuple(expression.arguments)  # type: ignore[union-attr]


def _missing() -> float:
    raise MintError(2001, detail="an axis place is empty")
