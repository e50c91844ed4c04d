"""Loops whose passes run as one generated Python function over local copies of their variables.

In a tight loop the interpreter spends most of its time around the statements:
a Python call each, the program counter, the slice's budget. A loop whose body
only does arithmetic on scalar variables (assignments, one-line ``IF .. THEN``,
``EXIT``) and whose closer is ``NEXT``, ``ENDW``, ``UNTIL`` or ``ENDL`` is
therefore compiled a second time, whole, into a Python ``while`` loop over
locals. Its binary32 rounding is a store into a ``memoryview`` of binary32 and a
load: the same C conversion ``struct`` makes in ``numbers.f32``, in about a third
of the time; a result too large for binary32 becomes an infinity there, which is
error 3.

It runs only where the interpreter runs the program alone (``Interpreter.run_ahead``)
and it changes nothing a run shows:

- it starts at the loop's first statement, with the loop on top of the running
  frame's stack, and runs whole passes while the statements left in the budget
  hold the longest pass, counting statements as the interpreter does; the rest
  of the budget, and anything else, is the interpreter's;
- a statement that fails (or meets what the simulator does not model) is left
  unrun: the variables and the program counter are as the statements before it
  left them, and the interpreter runs it again, to fail there itself (pure
  statements change nothing when they fail);
- it leaves in ``Interpreter.ran`` the last statement it ran (the closer of its
  last pass, or the EXIT or closer that left the loop): a program that ends
  there names it;
- when any of its operations has been replaced (coverage, the debugger, a
  benchmark's counter wrap them), it steps aside.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import field

from mintlang.records import record
from mintlang.runtime import numbers
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter import generated
from mintlang.runtime.interpreter.expressions import ExpressionCompiler
from mintlang.runtime.interpreter.generated import Emitter, Source
from mintlang.runtime.interpreter.statements import layout_size
from mintlang.runtime.interpreter.vm import Interpreter, Loop, Operation
from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.syntax import nodes as n

_LOOPS = frozenset({BlockKind.FOR, BlockKind.WHILE, BlockKind.REPEAT, BlockKind.LOOP})
_EXACT = 2.0**24  # every integer up to this is a binary32
Passes = Callable[[int, Loop], int]  # (budget, the loop's stack entry) -> statements run
_INDENT = "    "


class _Unsupported(Exception):
    """The loop holds a statement the generated loop does not write: the interpreter alone runs it."""


@record
class CompiledLoop:
    """The generated passes of the loop opened at ``opener``, and the operations they stand for."""

    vm: Interpreter
    opener: int
    operations: list[Operation]  # of the loop's first statement to its closer, as compiled
    upwards: Passes
    downwards: Passes  # a FOR loop's, for a negative step
    counting: tuple[Passes, Passes] | None = None  # a FOR loop's upwards and downwards while exactly counting

    def __call__(self, budget: int) -> int:
        """Run whole passes within ``budget`` statements; how many ran (0: the interpreter runs the next one)."""
        vm = self.vm
        loops = vm.loops
        if not loops or loops[-1].opener != self.opener:
            return 0
        frames = vm.frames
        if frames and len(loops) <= frames[-1].loops:
            return 0  # a caller's loop: the running subroutine jumped into its body
        entry = self.opener + 1
        if vm.operations[entry : entry + len(self.operations)] != self.operations:
            return 0
        loop = loops[-1]
        step = loop.step
        if self.counting is not None and _counts_exactly(vm.scalars[loop.slot], step, loop.end):
            return self.counting[step < 0](budget, loop)
        return (self.upwards if step >= 0 else self.downwards)(budget, loop)


def _counts_exactly(value: float, step: float, end: float) -> bool:
    """Whether every value a FOR variable takes from ``value`` on (it moves by ``step`` towards ``end``, and
    one step past it) is an integer of at most 2**24, which binary32 holds exactly: no sum needs rounding."""
    return value % 1 == 0 and step % 1 == 0 and max(abs(value), abs(end)) + abs(step) <= _EXACT


def attach(
    vm: Interpreter,
    statements: Sequence[n.Statement],
    blocks: Sequence[Block],
    positions: Mapping[Place, int],
    expressions: ExpressionCompiler,
) -> None:
    """Compile every loop of one file that generated passes can run into ``vm.compiled_loops`` (one place per
    operation), ``statements`` being the statement of each operation."""
    for block in blocks:
        if block.kind not in _LOOPS or block.closer is None:
            continue
        opener, closer = positions[block.opener], positions[block.closer]
        if not all(vm.pure[opener : closer + 1]):
            continue
        try:
            upwards, downwards = _Writer(vm, statements, expressions, opener, closer).passes()
        except (_Unsupported, MintError, NotSimulated):
            continue
        counting = _counting(vm, statements, expressions, opener, closer)
        operations = vm.operations[opener + 1 : closer + 1]
        vm.compiled_loops[opener + 1] = CompiledLoop(vm, opener, operations, upwards, downwards, counting)


def _counting(
    vm: Interpreter, statements: Sequence[n.Statement], expressions: ExpressionCompiler, opener: int, closer: int
) -> tuple[Passes, Passes] | None:
    """A binary32 FOR loop's passes that add the step without rounding, for when it counts exactly (the body
    leaves the variable to NEXT)."""
    if type(statements[opener]) is not n.For or expressions.semantics.binary["+"] is not numbers.add:
        return None
    try:
        return _Writer(vm, statements, expressions, opener, closer, counting=True).passes()
    except _Unsupported:
        return None


def _binary32() -> memoryview:
    """A binary32 to round through: a store rounds as ``numbers.f32``'s struct does, an infinity when too large.
    Made for each call, so that no two runs share one and a snapshot of the state never meets it."""
    return memoryview(bytearray(4)).cast("f")


class _LocalEmitter(Emitter):
    """Names each variable as a local, and writes each rounding as a line of its own before the statement's.

    A result too large for binary32 is stored as an infinity, which is error 3; it is tested where the result
    is used by anything but more arithmetic, which turns an infinity into an infinity or a NaN, never a number.
    """

    def __init__(self) -> None:
        super().__init__()
        self.slots: dict[int, None] = {}  # the variables read or written, in order
        self.before: list[str | None] = []  # the lines the statement being written needs first
        self.untested: dict[str, int] = {}  # a rounded result -> where its test is in ``before``
        self._temporaries = 0

    def scalar(self, scalars: list[float], slot: int) -> str:
        self.slots[slot] = None
        return f"v{slot}"

    def rounded(self, text: str, *operands: Source) -> str:
        for operand in operands:
            test = self.untested.pop(operand.text, None)
            if test is not None:
                self.before[test] = None  # this result's infinity or NaN reaches the one rounded here
        name = f"t{self._temporaries}"
        self._temporaries += 1
        self.before.append(f"_f[0] = {text}; {name} = _f[0]")
        self.untested[name] = len(self.before)
        self.before.append(f"if {name} - {name}: raise _big()")  # not 0 only for an infinity or a NaN
        return name

    def test_later(self, result: Source) -> str:
        """The line testing ``result``, taken out of the lines before the statement to be written where it is
        needed ("" when it needs none)."""
        index = self.untested.pop(result.text, None)
        if index is None:
            return ""
        self.before[index] = None
        return f"if {result.text} - {result.text}: raise _big()"

    def take(self) -> list[str]:
        """The lines written since the last take, each result tested where it needs to be."""
        lines = [line for line in self.before if line is not None]
        self.before, self.untested = [], {}
        return lines


@record(frozen=False)
class _Lines:
    """The generated text, and for each of its lines the statement it belongs to and how many statements of
    the pass ran before it and are not yet counted in ``n`` (an error there is the statement's)."""

    text: list[str] = field(default_factory=list)
    places: list[tuple[int, int]] = field(default_factory=list)

    def add(self, depth: int, line: str, pc: int, pending: int) -> None:
        self.text.append(_INDENT * depth + line)
        self.places.append((pc, pending))


# Where a FOR loop's variable is past its end, upwards and downwards (the step's sign is known when it runs).
_PAST_END = "_past_end_"
_UPWARDS, _DOWNWARDS = ">", "<"


class _Writer:
    """Writes the generated passes of the loop opened at ``opener`` and closed at ``closer``.

    A pass whose statements are always the same (no ``IF .. THEN``) is a ``for`` over as many passes as the
    budget holds, counted at the end; one whose length varies is a ``while`` that counts as it goes.
    """

    def __init__(
        self,
        vm: Interpreter,
        statements: Sequence[n.Statement],
        expressions: ExpressionCompiler,
        opener: int,
        closer: int,
        *,
        counting: bool = False,
    ) -> None:
        self.vm = vm
        self.statements = statements
        self.counting = counting  # a FOR loop whose variable is added its step without rounding
        self.assigned: set[int] = set()  # the slots the body assigns
        self.expressions = expressions
        self.opener = opener
        self.closer = closer
        self.emitter = _LocalEmitter()
        self.lines = _Lines()
        self.scalars = self.emitter.name(vm.scalars)
        self.leave = self.emitter.call(vm.leave_loop, self.emitter.name(opener))
        self.setup = ""  # what a pass needs from the loop's stack entry
        self.longest = closer + 1 - (opener + 1)  # each statement runs at most once a pass: nothing jumps back
        self.varying = any(type(statements[pc]) is n.IfThen for pc in range(opener + 1, closer))

    def passes(self) -> tuple[Passes, Passes]:
        """The generated passes for a positive step (or no step) and for a negative one."""
        depth = 3  # def, try, while or for
        pending = self._block(self.opener + 1, self.closer, depth)
        self._closer(pending, depth)
        if not self.lines.text:  # LOOP .. ENDL alone
            self.lines.add(depth, "pass", self.closer, 0)
        text = "\n".join([*self._head(), *self.lines.text, *self._tail()]) + "\n"
        upwards = self._function(text.replace(_PAST_END, _UPWARDS))
        return upwards, (self._function(text.replace(_PAST_END, _DOWNWARDS)) if self.setup else upwards)

    def _head(self) -> list[str]:
        emitter, entry = self.emitter, self.opener + 1
        load = "".join(f"v{slot} = {self.scalars}[{slot}]; " for slot in emitter.slots)
        parameters = "".join(f"_{index}, " for index in range(len(emitter.values)))
        loop = f"while n <= budget - {self.longest}:" if self.varying else "for passes in range(whole):"
        return [
            f"def _mint(budget, loop, {parameters}_binary32, _big, _vm, _at, _fails):",
            f"    _f = _binary32(); {load}{self.setup}",
            f"    n = 0; passes = 0; whole = budget // {self.longest}; pc = {entry}; ran = {self.closer}",
            "    try:",
            f"        {loop}",
        ]

    def _tail(self) -> list[str]:
        store = "".join(f"{self.scalars}[{slot}] = v{slot}; " for slot in self.emitter.slots)
        counted = (
            []
            if self.varying
            else ["        else:", "            passes = whole", f"        n += passes * {self.longest}"]
        )
        return [
            *counted,
            "    except BaseException as error:",
            "        pc, pending = _at[error.__traceback__.tb_lineno]",
            f"        n += {'' if self.varying else f'passes * {self.longest} + '}pending; {store}_vm.pc = pc",
            "        if isinstance(error, _fails): return n",
            "        raise",
            f"    {store}_vm.pc = pc; _vm.ran = ran",
            "    return n",
        ]

    def _function(self, text: str) -> Passes:
        entry = (self.opener + 1, 0)
        head = len(self._head())
        at = (entry,) * (head + 1) + tuple(self.lines.places) + (entry,) * len(self._tail())
        defaults = (*self.emitter.values, _binary32, generated.too_large, self.vm, at, (MintError, NotSimulated))
        return generated.function(generated.defined(text), defaults)  # type: ignore[return-value]

    def _count(self, depth: int, statements: int, pc: int, pending: int) -> None:
        """Add ``statements`` to ``n`` (a pass that always runs the same statements is counted whole)."""
        if self.varying and statements:
            self.lines.add(depth, f"n += {statements}", pc, pending)

    def _block(self, first: int, last: int, depth: int) -> int:
        """Write the statements at ``first`` up to ``last`` (not included); how many of the pass ran since
        ``n`` was last added to."""
        pending = 0
        pc = first
        while pc < last:
            statement = self.statements[pc]
            kind = type(statement)
            if kind is n.Assignment:
                self._assignment(statement, pc, pending, depth)  # type: ignore[arg-type]
                pending += 1
                pc += 1
            elif kind is n.IfThen:
                skip = pc + layout_size(statement)
                if skip > last:
                    raise _Unsupported("the loop closes inside the IF .. THEN")
                condition = self._condition(statement.condition, pc, pending, depth)  # type: ignore[union-attr]
                self._count(depth, pending + 1, pc, pending)
                self.lines.add(depth, f"if {condition.truth}:", pc, -1)  # a call in it may fail: n counts the IF
                inner = self._block(pc + 1, skip, depth + 1)
                self.lines.add(depth + 1, f"n += {inner}" if inner else "pass", skip - 1, inner)
                pending = 0
                pc = skip
            elif kind is n.BlockWord and statement.word == "EXIT":  # type: ignore[union-attr]
                self._leave(pending + 1, pc, pending, depth)
                pending += 1
                pc += 1
            else:
                raise _Unsupported(kind.__name__)
        return pending

    def _assignment(self, statement: n.Assignment, pc: int, pending: int, depth: int) -> None:
        target = statement.target
        if type(target) is not n.VariableRef or target.name.identity in self.expressions.names.macros:
            raise _Unsupported("a store in an array or a macro")
        value = self._source(statement.value)
        slot = self.expressions.scalar_slot(target.name)
        self.assigned.add(slot)
        variable = self.emitter.scalar(self.vm.scalars, slot)
        stored = generated.stored(self.emitter, value, self.expressions.semantics.number)
        self._before(pc, pending, depth)
        self.lines.add(depth, f"{variable} = {stored}", pc, pending)

    def _source(self, expression: n.Expression) -> Source:
        """``expression`` over locals; an array element or a function the interpreter calls would read the
        variables where the generated loop does not keep them."""
        for part in n.walk_expression(expression):
            kind = type(part)
            if kind is n.ElementRef or (kind is n.VariableRef and part.name.identity in self.expressions.names.macros):  # type: ignore[union-attr]
                raise _Unsupported("an array element or a macro")
            if kind is n.Call and part.function not in self.expressions.semantics.functions:  # type: ignore[union-attr]
                raise _Unsupported("a keyword function")
        return self.expressions.source(expression, self.emitter)

    def _condition(self, expression: n.Expression, pc: int, pending: int, depth: int) -> Source:
        condition = self._source(expression)
        self._before(pc, pending, depth)
        return condition

    def _before(self, pc: int, pending: int, depth: int) -> None:
        for line in self.emitter.take():
            self.lines.add(depth, line, pc, pending)

    def _leave(self, counted: int, pc: int, pending: int, depth: int) -> None:
        """Count ``counted`` statements, leave the loop and go on after its closer."""
        self.lines.add(depth, f"n += {counted}; {self.leave}; ran = {pc}; pc = {self.closer + 1}; break", pc, pending)

    def _closer(self, pending: int, depth: int) -> None:
        """The closer's test of another pass, at the end of each pass."""
        closer = self.closer
        statement = self.statements[closer]
        kind = type(statement)
        word = statement.word if kind is n.BlockWord else ""  # type: ignore[union-attr]
        if kind is n.Until or word == "ENDW":
            tested = statement.condition if kind is n.Until else self._while()  # type: ignore[union-attr]
            condition = self._condition(tested, closer, pending, depth)
            leaves = condition.truth if kind is n.Until else f"not ({condition.truth})"
            self.lines.add(depth, f"if {leaves}:", closer, pending)
            self._leave(pending + 1, closer, pending, depth + 1)
        elif word == "NEXT":
            self._next(pending, depth)
        elif word != "ENDL":
            raise _Unsupported(word or kind.__name__)
        self._count(depth, pending + 1, closer, pending)

    def _while(self) -> n.Expression:
        return self.statements[self.opener].condition  # type: ignore[union-attr]

    def _next(self, pending: int, depth: int) -> None:
        """``NEXT``: the variable plus the step, past the end (upwards or downwards) leaves the loop with the
        variable as the last pass left it (NM-9)."""
        closer, emitter = self.closer, self.emitter
        opener = self.statements[self.opener]
        slot = self.expressions.names.scalars.get(opener.variable.identity)  # type: ignore[union-attr]
        if slot is None:
            raise _Unsupported("a FOR whose variable has no slot")
        variable = emitter.scalar(self.vm.scalars, slot)
        if self.counting:
            if slot in self.assigned:
                raise _Unsupported("the body assigns the FOR variable")
            candidate, test = Source(f"{variable} + step"), ""
        else:
            add = self.expressions.semantics.binary["+"]
            candidate = generated.binary(emitter, add, Source(variable), Source("step"))
            # too large for binary32, the variable plus the step is an infinity of the step's sign, past any end
            test = emitter.test_later(candidate)
        self.setup = "end = loop.end; step = loop.step"
        self._before(closer, pending, depth)
        following = candidate.text
        if not following.isidentifier():  # a call (v3's arithmetic): made once
            self.lines.add(depth, f"following = {following}", closer, pending)
            following = "following"
        self.lines.add(depth, f"if {following} {_PAST_END} end:", closer, pending)
        if test:
            self.lines.add(depth + 1, test, closer, pending)
        self._leave(pending + 1, closer, pending, depth + 1)
        self.lines.add(depth, f"{variable} = {following}", closer, pending)
