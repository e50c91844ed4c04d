"""Compiling statements into operations.

Each statement becomes one operation (an ``IF .. THEN`` line becomes a
conditional jump followed by its body), laid out in a flat list; block
statements jump to positions resolved before any closure is built, so a loop
iteration is a comparison and an integer assignment.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence

from mintlang.diagnostics import Span
from mintlang.keyworddb.model import CIRCLE_AXES, CIRCLES
from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import MISSING_PARAMETER, SYNTAX_ERROR, TOO_MANY_VALUES, MintError, NotSimulated
from mintlang.runtime.interpreter import generated
from mintlang.runtime.interpreter.arrays import array_problem
from mintlang.runtime.interpreter.expressions import Evaluate, ExpressionCompiler
from mintlang.runtime.interpreter.generated import Emitter
from mintlang.runtime.interpreter.release import release
from mintlang.runtime.interpreter.vm import Interpreter, Loop, Operation, Recovery
from mintlang.runtime.keywords import ArrayArgument, ArrayCommand, KeywordAccess, KeywordTable, Values
from mintlang.runtime.printing import format_bin, format_chr, format_hex
from mintlang.runtime.ranges import check_range
from mintlang.runtime.terminal import NumberEntry, Terminal
from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.syntax import nodes as n

WRITE_OF_READ_ONLY = 2000
NO_EXPRESSION = 2005
UNDEFINED_KEYWORD = 3007
MAX_INPUT_INTEGER_DIGITS = 15  # INPUT .. USING: <int> is at most 15 characters, the sign excluded (000:12247)
MAX_INPUT_FRACTION_DIGITS = 3  # and <frac> at most 3 (000:12249)


def layout_size(statement: n.Statement) -> int:
    """How many operations a statement compiles to."""
    if type(statement) is n.IfThen:
        return 1 + sum(layout_size(inner) for inner in statement.body)
    return 1


@record
class FileLayout:
    """Where everything of one file sits in the operation list."""

    positions: Mapping[Place, int]  # the pc of the statement at each place
    blocks: Mapping[Place, Block]  # the block of each opener, middle and closer
    labels: Mapping[str, int]  # label identity -> pc
    start: int  # the pc of the file's first operation
    end: int  # the pc after the file's last operation
    on_end: Callable[[], None]  # what END does in this file


class StatementCompiler:
    """Builds the operation of one statement, given where every block statement sits."""

    def __init__(
        self,
        vm: Interpreter,
        table: KeywordTable,
        terminal: Terminal,
        expressions: ExpressionCompiler,
        layout: FileLayout,
    ) -> None:
        self.vm = vm
        self.table = table
        self.terminal = terminal
        self.expressions = expressions
        self.number = expressions.semantics.number
        self.positions = layout.positions
        self.blocks = layout.blocks
        self.labels = layout.labels
        self.start_of_unit = layout.start
        self.end_of_unit = layout.end
        self.on_end = layout.on_end
        self.place = Place(0, 0)  # of the statement being compiled
        self.conditions: dict[Place, n.Expression] = {}  # each WHILE's condition, which its ENDW tests again

    def compile(self, statement: n.Statement, place: Place, pc: int) -> Operation:
        """The operation of ``statement``, which stands at ``place`` and is laid out at ``pc``."""
        kind = type(statement)
        method = _DISPATCH.get(kind)
        if method is None:
            raise NotSimulated(kind.__name__, "statement")
        self.place = place
        return method(self, statement, pc)

    # ---------------------------------------------------------------- helpers

    def _after(self, place: Place | None) -> int:
        """The pc after a block statement; the end of the file when the block is never closed."""
        return self.end_of_unit if place is None else self.positions[place] + 1

    def _block(self) -> Block | None:
        """The block of the statement being compiled; None for a closer without its opener."""
        return self.blocks.get(self.place)

    def _opened(self) -> Block:
        """The block the opener being compiled opens (an unclosed one too)."""
        return self.blocks[self.place]

    def _recover(self, pc: int, resume: int, loop: int | None = None) -> None:
        """An error in the block statement at ``pc`` resumes at ``resume``, leaving ``loop``, not in the block."""
        self.vm.recoveries[pc] = Recovery(resume, loop)

    # ----------------------------------------------------------- assignments

    def assignment(self, statement: n.Assignment, pc: int) -> Operation:
        target = statement.target
        if type(target) is n.VariableRef and target.name.identity not in self.expressions.names.macros:
            return self._assign_scalar(target.name, statement.value)
        value = self.expressions.compile(statement.value)
        return self._store(target, value)

    def _assign_scalar(self, name: n.Name, expression: n.Expression) -> Operation:
        """``a = expression`` as one generated function. The store holds the value as the dialect holds
        numbers, which for binary32 is nothing more to do when the last operation has rounded it."""
        emitter = Emitter()
        value = self.expressions.source(expression, emitter)
        slot = self.expressions.scalar_slot(name)
        stored = generated.stored(emitter, value, self.number)
        return emitter.function(f"{emitter.name(self.vm.scalars)}[{emitter.name(slot)}] = {stored}")

    def _store(self, target: n.VariableRef | n.ElementRef, value: Evaluate) -> Operation:
        setter = self._setter(target)
        return lambda: setter(value())

    def _setter(self, target: n.VariableRef | n.ElementRef) -> Callable[[float], None]:
        """A function that stores a value in the variable or array element ``target`` names."""
        if type(target) is n.VariableRef:
            self.expressions.variable(target.name)
            scalars = self.vm.scalars
            slot = self.expressions.names.scalars[target.name.identity]
            number = self.number

            def store_scalar(value: float) -> None:
                scalars[slot] = number(value)

            return store_scalar
        element: n.ElementRef = target  # type: ignore[assignment]
        values = self.expressions.element_slot(element.name)
        index = self.expressions.compile(element.index)
        size = len(values)
        number = self.number

        def store_element(value: float) -> None:
            position = int(index())
            if not 1 <= position <= size:
                raise MintError(2016, detail=f"index {position} outside 1 to {size}")
            values[position - 1] = number(value)

        return store_element

    def dim(self, statement: n.Dim, pc: int) -> Operation:
        if (
            statement.size is not None
            and (problem := array_problem(statement, self.expressions.semantics.initial)) is not None
        ):
            raise problem
        if statement.size is not None or not statement.values:
            return _nothing  # arrays are initialised when the program is compiled, not when DIM runs
        return self._store(
            n.VariableRef(statement.name.span, statement.name), self.expressions.compile(statement.values[0])
        )

    # -------------------------------------------------------------- keywords

    def _channels(self, reference: n.KeywordRef) -> Callable[[], tuple[int, ...] | None]:
        found = self.expressions.channels(reference)
        if found is None:
            return lambda: None
        if found is True:
            vm = self.vm
            return lambda: vm.default_axes
        expressions = found

        def evaluate() -> tuple[int, ...]:
            return tuple(int(channel()) for channel in expressions)  # type: ignore[operator]

        return evaluate

    def keyword_statement(self, statement: n.KeywordStatement, pc: int) -> Operation:
        reference = statement.keyword
        if reference.keyword == "WAIT":
            return self._wait(statement, pc)
        if reference.keyword == "LINE" and statement.values is None:
            return self._line(statement)
        if reference.keyword == "PROTECT" and statement.values is None:
            return _nothing  # PROTECT <password> locks the buffer where it is stored; running it does nothing
        if reference.keyword == "RELEASE" and statement.values is None:
            return release(self.vm, self.expressions.semantics.dialect)  # in a configuration file (mint check)
        printer = self.expressions.semantics.printers.get(reference.keyword)
        if printer is not None and statement.values is None:
            return self._printing_keyword(statement, printer)
        access = self.table.in_program(reference.keyword)
        if reference.keyword in CIRCLES and self.expressions.semantics.dialect.modern:
            _a_circles_axes(reference.selector)
        if reference.selector is not None and reference.selector.indices:
            return self._indexed_write(statement, access)
        channels = self._channels(reference)
        vm = self.vm
        clock = vm.clock
        if statement.values is not None:
            if access is None or access.write is None:
                if access is not None and access.indexed_write is not None:  # MintMT's MOVEOUT(0) = 7: no bank
                    raise MintError(MISSING_PARAMETER, detail=f"{reference.keyword} needs its index after the axes")
                refused = self.table.refused_by_the_guide(reference.keyword, write=True)  # VER = 1: 2000
                handled = access is not None and (access.read is not None or access.command is not None)
                if refused is None and handled and not self.table.decides(reference.keyword):
                    refused = WRITE_OF_READ_ONLY  # the simulator reads it or runs it, and writes it not (2000)
                if refused is not None:
                    raise MintError(refused, detail=reference.keyword)
                raise NotSimulated(reference.keyword, "write")
            _given_a_value(reference.keyword, statement.values)
            write = access.write
            values = tuple(self.expressions.compile(value) if value is not None else None for value in statement.values)
            fill = statement.fill
            semantics = self.expressions.semantics
            one_per_axis = reference.keyword in semantics.axis_keywords and reference.keyword not in CIRCLES
            one_value = reference.keyword in semantics.one_value_keywords

            def write_values() -> bool:
                addressed = channels()
                if one_per_axis:
                    _within_the_axes(len(values), addressed)
                elif one_value:
                    _one_value(len(values), reference.keyword)
                evaluated = _evaluated(values, fill, addressed)
                clock.horizon = NEVER
                if write(addressed, evaluated):
                    vm.wake_at = clock.horizon  # a full buffer frees when the running move ends
                    return True
                return False

            return write_values
        if access is None or access.command is None:
            if access is not None and access.read is not None:
                raise MintError(NO_EXPRESSION, detail=f"{reference.keyword} needs a value")
            raise NotSimulated(reference.keyword, "command")
        command = access.command
        arguments = tuple(
            self.expressions.compile(argument)
            for argument in statement.arguments
            if type(argument) is not n.StringLiteral
        )

        def run_command() -> bool:
            clock.horizon = NEVER
            if command(channels(), tuple(argument() for argument in arguments)):
                vm.wake_at = clock.horizon
                return True
            return False

        return run_command

    def _indexed_write(self, statement: n.KeywordStatement, access: KeywordAccess | None) -> Operation:
        """MintMT's ``CONTOURPARAMETER([0,1],0) = 10;``: the indices after the axes go to the keyword too."""
        reference = statement.keyword
        if access is None or access.indexed_write is None or statement.values is None:
            raise NotSimulated(reference.keyword, "write with an index")
        write = access.indexed_write
        channels = self._channels(reference)
        selector = reference.selector
        assert selector is not None, "only a keyword with a selector has indices"
        indices = tuple(self.expressions.compile(item) for item in selector.items[-selector.indices :] if item)
        values = tuple(self.expressions.compile(value) if value is not None else None for value in statement.values)
        fill = statement.fill
        one_per_axis = reference.keyword in self.expressions.semantics.axis_keywords

        def write_indexed() -> bool:
            addressed = channels()
            if one_per_axis:
                _within_the_axes(len(values), addressed)  # the indices are no values (000:572-576)
            return write(addressed, tuple(int(index()) for index in indices), _evaluated(values, fill, addressed))

        return write_indexed

    def _wait(self, statement: n.KeywordStatement, pc: int) -> Operation:
        _one_value(len(statement.values or ()), "WAIT")  # WAIT = <expression> (000:17324), as any one-value write
        if not statement.values or statement.values[0] is None:
            raise MintError(NO_EXPRESSION, detail="WAIT needs a time in milliseconds")
        duration = self.expressions.compile(statement.values[0])
        limits = self.table.bounds("WAIT")  # 2 ms at least on NextMove (000:17314-17333)
        vm = self.vm
        clock = vm.clock
        waits = vm.waits

        def wait() -> bool:
            key = (len(vm.frames), pc)
            deadline = waits.get(key)
            if deadline is None:
                deadline = waits[key] = clock.now + int(check_range("WAIT", duration(), limits))
            if clock.now >= deadline:
                del waits[key]
                return False
            vm.wake_at = deadline
            return True

        return wait

    def function_statement(self, statement: n.FunctionStatement, pc: int) -> Operation:
        call = statement.call
        access = self.table.in_program(call.function)
        if statement.values is None and access is not None and access.array_command is not None:
            return self._array_command(call, access.array_command)
        arguments = tuple(self.expressions.compile(argument) for argument in call.arguments)
        if statement.values is None:
            if access is None or access.command is None:
                raise NotSimulated(call.function, "command")
            command = access.command
            return lambda: command(None, tuple(argument() for argument in arguments))
        if access is None or access.write is None:
            raise NotSimulated(call.function, "write")
        if len(arguments) != 1:
            raise NotSimulated(call.function, f"write with {len(arguments)} arguments")
        _given_a_value(call.function, statement.values)
        write = access.write
        (index,) = arguments
        values = tuple(self.expressions.compile(value) if value is not None else None for value in statement.values)
        return lambda: write((int(index()),), tuple(value() if value is not None else None for value in values))

    def _array_command(self, call: n.Call, command: ArrayCommand) -> Operation:
        """``CAMTABLE(0, table, NULL)``: a bare array name passes the array itself, ``NULL`` passes 0."""
        arguments = tuple(self._array_argument(argument) for argument in call.arguments)
        return lambda: command(tuple(argument() for argument in arguments))

    def _array_argument(self, argument: n.Expression) -> Callable[[], ArrayArgument]:
        if type(argument) is n.VariableRef and argument.name.identity in self.expressions.names.arrays:
            values = self.expressions.element_slot(argument.name)
            return lambda: values
        if type(argument) is n.ConstantRef and argument.name.upper() == "NULL":
            return lambda: 0.0
        return self.expressions.compile(argument)

    def bare_name(self, statement: n.BareName, pc: int) -> Operation:
        name = statement.name.text

        def undefined() -> None:
            raise MintError(UNDEFINED_KEYWORD, detail=name)

        return undefined

    def syntax_error(self, statement: n.SyntaxError_, pc: int) -> Operation:
        def fail() -> None:
            raise MintError(SYNTAX_ERROR)

        return fail

    def axes(self, statement: n.Axes, pc: int) -> Operation:
        if statement.selector is None:

            def alone() -> None:
                raise MintError(NO_EXPRESSION, detail="AXES needs a list of axes in a program")

            return alone
        items = tuple(self.expressions.compile(item) for item in statement.selector.items if item is not None)
        vm = self.vm
        table = self.table
        validate = table.get("AXES")

        def set_axes() -> None:
            axes = tuple(int(item()) for item in items)
            if validate is not None and validate.command is not None:
                validate.command(axes, ())
            vm.default_axes = axes

        return set_axes

    # ------------------------------------------------------------ flow of control

    def if_then(self, statement: n.IfThen, pc: int) -> Operation:
        emitter = Emitter()
        condition = self.expressions.source(statement.condition, emitter)
        skip = pc + layout_size(statement)
        self._recover(pc, skip)
        return generated.branch(emitter, condition, "pass", self._jump(emitter, skip))

    def _jump(self, emitter: Emitter, target: int) -> str:
        """The generated line that continues the program at ``target``."""
        return f"{emitter.name(self.vm)}.pc = {emitter.name(target)}"

    def _leave(self, emitter: Emitter, opener: int) -> str:
        """The generated line that leaves the loop opened at ``opener`` (going on after its closer)."""
        return emitter.call(self.vm.leave_loop, emitter.name(opener))

    def if_do(self, statement: n.IfDo, pc: int) -> Operation:
        """Either branch runs inside the block, which holds a place on the stack until its ENDIF or ELSE."""
        block = self._opened()
        condition = self.expressions.compile(statement.condition)
        after = self._after(block.closer)
        otherwise = self._after(block.middle) if block.middle is not None else None
        self._recover(pc, after)
        vm = self.vm

        def branch() -> None:
            if condition():
                vm.enter_loop(Loop(pc, after, BlockKind.IF))
            elif otherwise is not None:
                vm.enter_loop(Loop(pc, after, BlockKind.IF))
                vm.pc = otherwise
            else:
                vm.pc = after

        return branch

    def for_(self, statement: n.For, pc: int) -> Operation:
        block = self._opened()
        self.expressions.variable(statement.variable)
        slot = self.expressions.names.scalars[statement.variable.identity]
        start = self.expressions.compile(statement.start)
        end = self.expressions.compile(statement.end)
        step = self.expressions.compile(statement.step) if statement.step is not None else (lambda: 1.0)
        exit_pc = self._after(block.closer)
        self._recover(pc, exit_pc, pc)
        vm = self.vm
        scalars = vm.scalars

        def enter() -> None:
            first, last, increment = start(), end(), step()
            scalars[slot] = first
            if (increment >= 0 and first > last) or (increment < 0 and first < last):
                vm.pc = exit_pc  # the body never runs; the variable keeps the start value (NM-9 RC)
                return
            vm.enter_loop(Loop(pc, exit_pc, BlockKind.FOR, slot, last, increment))

        return enter

    def block_word(self, statement: n.BlockWord, pc: int) -> Operation:
        word = statement.word
        vm = self.vm
        block_word = _BLOCK_WORDS.get(word)
        if block_word is not None:
            block = self._block()
            if block is None:
                return _nothing  # an unmatched closer is a compile error, so the program never runs
            return block_word(self, block, pc)
        if word == "EXIT":
            return self._exit()
        if word == "RETURN":
            return vm.return_
        if word == "END":
            return self.on_end
        raise NotSimulated(word, "statement")

    def event_block(self, statement: n.EventBlock, pc: int) -> Operation:
        return self._step_over(self._opened(), pc)

    def _step_over(self, block: Block, pc: int) -> Operation:
        """A MintMT Event or Startup block met by the code around it: the controller alone enters it."""
        after = self._after(block.closer)
        vm = self.vm

        def step_over() -> None:
            vm.pc = after

        return step_over

    def _end_event(self, block: Block, pc: int) -> Operation:
        return self.vm.return_

    def _end_startup(self, block: Block, pc: int) -> Operation:
        """The Startup block is done: the program runs from its first line."""
        start = self.start_of_unit
        vm = self.vm

        def begin() -> None:
            vm.pc = start

        return begin

    def _endif(self, block: Block, pc: int) -> Operation:
        opener = self.positions[block.opener]
        vm = self.vm
        return lambda: vm.leave_loop(opener)

    def _else(self, block: Block, pc: int) -> Operation:
        """The end of the true branch: leave the block."""
        after = self._after(block.closer)
        opener = self.positions[block.opener]
        vm = self.vm

        def skip() -> None:
            vm.leave_loop(opener)
            vm.pc = after

        return skip

    def _next(self, block: Block, pc: int) -> Operation:
        opener = self.positions[block.opener]
        self._recover(pc, pc + 1, opener)
        vm = self.vm
        scalars = vm.scalars
        add = generated.operator(self.expressions.semantics.binary["+"])
        again = opener + 1

        def next_() -> None:
            loops = vm.loops
            loop = loops[-1] if loops else None
            if loop is None or loop.opener != opener or (vm.frames and len(loops) <= vm.frames[-1].loops):
                loop = vm.innermost_loop(opener)  # not the top of the stack, or a caller's: look further
                if loop is None:
                    raise MintError(2009, detail="NEXT reached outside its FOR loop")
            slot, step = loop.slot, loop.step
            candidate = add(scalars[slot], step)
            if (step >= 0 and candidate > loop.end) or (step < 0 and candidate < loop.end):
                vm.leave_loop(opener)  # the variable keeps the last value the body ran with (NM-9)
                return
            scalars[slot] = candidate
            vm.pc = again

        return next_

    def _open_loop(self, block: Block, pc: int) -> Operation:
        exit_pc = self._after(block.closer)
        self._recover(pc, exit_pc, pc)
        vm = self.vm

        kind = block.kind

        def enter() -> None:
            vm.enter_loop(Loop(pc, exit_pc, kind))

        return enter

    def _endl(self, block: Block, pc: int) -> Operation:
        opener = self.positions[block.opener]
        vm = self.vm

        def again() -> None:
            vm.pc = opener + 1

        return again

    def until(self, statement: n.Until, pc: int) -> Operation:
        block = self._block()
        emitter = Emitter()
        condition = self.expressions.source(statement.condition, emitter)
        if block is None:
            return generated.branch(emitter, condition, "pass", "pass")
        opener = self.positions[block.opener]
        self._recover(pc, pc + 1, opener)
        return generated.branch(emitter, condition, self._leave(emitter, opener), self._jump(emitter, opener + 1))

    def while_(self, statement: n.While, pc: int) -> Operation:
        """Entering the loop; its ENDW tests the condition again for each further pass."""
        block = self._opened()
        exit_pc = self._after(block.closer)
        self._recover(pc, exit_pc, pc)  # first: a condition that cannot be compiled raises when the WHILE runs
        condition = self.expressions.compile(statement.condition)
        self.conditions[self.place] = statement.condition
        vm = self.vm

        def while_() -> None:
            if condition():
                vm.enter_loop(Loop(pc, exit_pc, BlockKind.WHILE))
            else:
                vm.pc = exit_pc

        return while_

    def _endw(self, block: Block, pc: int) -> Operation:
        opener = self.positions[block.opener]
        written = self.conditions.get(block.opener)
        if written is None:
            return _nothing  # its WHILE raises instead of entering the loop, and an error there resumes after it
        self._recover(pc, pc + 1, opener)
        emitter = Emitter()
        condition = self.expressions.source(written, emitter)
        return generated.branch(emitter, condition, self._jump(emitter, opener + 1), self._leave(emitter, opener))

    def _exit(self) -> Operation:
        vm = self.vm

        def exit_() -> None:
            loop = vm.exit_loop()
            if loop is None:  # a loop of the caller cannot be left from a subroutine or an event handler
                raise MintError(SYNTAX_ERROR, detail="EXIT outside a loop")
            vm.pc = loop.exit

        return exit_

    def jump(self, statement: n.Jump, pc: int) -> Operation:
        target = self.labels.get(statement.label.identity)
        if target is None:
            raise MintError(3004, detail=f"#{statement.label.text}")
        vm = self.vm
        if statement.word == "GOSUB":
            return lambda: vm.call(target)

        def goto() -> None:
            vm.pc = target

        return goto

    def pause(self, statement: n.Pause, pc: int) -> Operation:
        waited_for = statement.condition
        if waited_for is None and not self.expressions.semantics.dialect.modern:
            # v3's PAUSE alone waits until a key is pressed (001:2211), as its PAUSE INKEY does, which reads it
            end = statement.span.end
            waited_for = n.KeywordRef(Span(end, end), "INKEY", "INKEY", Span(end, end), None, None)
        if waited_for is None:
            raise MintError(NO_EXPRESSION, detail="PAUSE needs a condition")
        condition = self.expressions.compile(waited_for)
        complete = self.expressions.complete_horizon(waited_for)
        keys = any(type(part) is n.KeywordRef and part.keyword == "INKEY" for part in n.walk_expression(waited_for))
        vm = self.vm
        clock = vm.clock

        def pause() -> bool:
            clock.horizon = NEVER
            if condition():
                return False
            vm.wake_at = clock.horizon
            vm.asleep = complete  # nothing it reads can change before wake_at: no need to try it again sooner
            vm.awaits_keys = keys
            return True

        return pause

    # ------------------------------------------------------------------ terminal

    def print_(self, statement: n.Print, pc: int) -> Operation:
        using = tuple(self.expressions.compile(value) for value in statement.using)
        parts = tuple(self._print_item(item, using) for item in statement.items)
        terminal = self.terminal

        def print_() -> None:
            terminal.print_items([(render(), separator) for render, separator in parts], newline=True)

        return print_

    def _print_item(
        self, item: n.PrintItem, using: tuple[Evaluate, ...], render: Callable[[float], str] | None = None
    ) -> tuple[Callable[[], str], str | None]:
        """One item's text; ``render``, when given, prints every number (BINARY's binary digits)."""
        value = item.value
        if value is None:
            return (lambda: ""), item.separator
        if type(value) is n.StringLiteral:
            text = value.value
            return (lambda: text), item.separator
        if type(value) is n.Call and value.function == "CHR":
            code = self.expressions.compile(value)
            return (lambda: format_chr(code())), item.separator
        number = self.expressions.compile(value)  # type: ignore[arg-type]
        semantics = self.expressions.semantics
        if render is not None:
            return (lambda: render(number())), item.separator
        if item.format == "HEX":
            return (lambda: format_hex(number())), item.separator
        if item.format == "BIN":
            return (lambda: format_bin(number())), item.separator
        if using:
            whole = using[0]
            fraction = using[1] if len(using) > 1 else None
            format_using = semantics.format_using
            return (
                lambda: format_using(number(), int(whole()), int(fraction()) if fraction is not None else None)
            ), item.separator
        format_number = semantics.format_number
        return (lambda: format_number(number())), item.separator

    @staticmethod
    def _items(statement: n.KeywordStatement, first: int = 0) -> list[n.PrintItem]:
        """A terminal command's arguments from ``first`` on as PRINT items, each with the separator written after
        it (a trailing one keeps the line open)."""
        arguments = statement.arguments
        formats = statement.formats or (None,) * len(arguments)
        last = len(arguments) - 1

        def separator(index: int) -> str | None:
            if index == last and not statement.trailing:
                return None
            return ";" if index in statement.semicolons else ","

        return [n.PrintItem(arguments[i].span, arguments[i], formats[i], separator(i)) for i in range(first, last + 1)]

    def _printing_keyword(self, statement: n.KeywordStatement, render: Callable[[float], str]) -> Operation:
        """``BINARY "12 is ", 12``: PRINT with every number in the keyword's own format (001:6209-6239)."""
        items = self._items(statement)
        parts = tuple(self._print_item(item, (), render) for item in items)
        terminal = self.terminal

        def print_() -> None:
            terminal.print_items([(text(), separator) for text, separator in parts], newline=True)

        return print_

    def _line(self, statement: n.KeywordStatement) -> Operation:
        """``LINE n, items``: the items on a line of their own, as PRINT prints them (000:13630-13668).

        On a log the row cannot be chosen and clearing the rest of it shows nothing: a line that
        does not start at the left begins a new one, and a trailing comma keeps it open.
        """
        if not statement.arguments:
            raise MintError(NO_EXPRESSION, detail="LINE needs a line number and what to print")
        using = tuple(self.expressions.compile(value) for value in statement.using)
        items = self._items(statement, first=1)
        parts = tuple(self._print_item(item, using) for item in items)
        terminal = self.terminal

        def line() -> None:
            if terminal.column:
                terminal.newline()
            terminal.print_items([(render(), separator) for render, separator in parts], newline=True)

        return line

    def input_(self, statement: n.Input, pc: int) -> Operation:
        prompt = statement.prompt.value if statement.prompt is not None else ""
        terminal = self.terminal
        vm = self.vm
        clock = vm.clock
        store = self._setter(statement.target)
        current = self.expressions.compile(statement.target)
        accept = self._entry_format(statement.using)
        prompted: set[tuple[int, int]] = set()

        def input_() -> bool:
            key = (len(vm.frames), pc)
            if key not in prompted:
                shown = terminal.prompt(prompt)
                terminal.print_items([(shown, ",")] if shown else [], newline=False)
                prompted.add(key)
            entry = terminal.read_number()
            if entry is None:
                clock.horizon = NEVER
                vm.wake_at = NEVER  # only a keystroke (a scheduled world change) can wake it
                vm.holding = True  # no event runs before the line is taken (000:4397-4399)
                return True
            prompted.discard(key)
            vm.holding = False
            value = entry.value if entry.value is None else accept(entry, current())
            if entry.retry or (entry.value is not None and value is None):  # ask again, at once if keys wait
                vm.wake_at = clock.now + 1
                vm.holding = True
                return True
            if value is not None:
                store(value)
            return False

        return input_

    def _entry_format(self, using: tuple[n.Expression, ...]) -> Callable[[NumberEntry, float], float | None]:
        """``INPUT .. USING int, frac`` (000:12223-12230, 12247-12249): a sign only with a negative ``int``, or
        when the variable already holds a negative value, as the field without one ignores the '-' key
        (000:12239); no more integer digits than ``|int|`` (at most 15) or than the value already held has,
        and no more than ``frac`` decimals (at most 3), the rest truncated; None for an entry to refuse. The
        field editor's cursor keys (space, backspace) are not modelled: keys arrive as a line, and a line
        the field cannot hold is asked for again."""
        if not using:
            return lambda entry, _: entry.value
        places = self.expressions.compile(using[0])
        fraction = self.expressions.compile(using[1]) if len(using) > 1 else (lambda: 0.0)
        number = self.number

        def accept(entry: NumberEntry, existing: float) -> float | None:
            integer = places()
            signed = integer < 0 or existing < 0
            negative = signed and entry.typed.startswith("-") and entry.value != 0.0
            whole, _, decimals = entry.typed.lstrip("+-").partition(".")
            whole = whole.lstrip("0")
            if len(whole) > max(min(abs(math.trunc(integer)), MAX_INPUT_INTEGER_DIGITS), _whole_digits(existing)):
                return None
            kept = min(max(int(fraction()), 0), MAX_INPUT_FRACTION_DIGITS)
            magnitude = int(whole + decimals[:kept].ljust(kept, "0") or "0") / 10**kept  # truncated, not rounded
            return number(-magnitude if negative else magnitude)

        return accept

    def nothing(self, statement: n.Statement, pc: int) -> Operation:
        return _nothing


def _nothing() -> None:
    return None


def _whole_digits(value: float) -> int:
    """How many digits the integer part of ``value`` has: none for a value under 1."""
    whole = abs(math.trunc(value))
    return len(str(whole)) if whole else 0


def _within_the_axes(count: int, addressed: tuple[int, ...] | None) -> None:
    """More values than the axes addressed is #2017, before anything is written (000:572-576, 19047)."""
    if addressed is not None and count > len(addressed):
        axes = f"{len(addressed)} ax{'is' if len(addressed) == 1 else 'es'}"
        raise MintError(TOO_MANY_VALUES, detail=f"{count} values for {axes}")


def _a_circles_axes(selector: n.Selector | None) -> None:
    """A circle listing more than its two axes is #2017 in v4 and MintMT when its line runs, where ``mint check``
    reports it (000:8152, 19047); the default axes (AXES) may be more, and the first two carry the circle."""
    if selector is not None and not selector.dot and len(selector.axes) > CIRCLE_AXES:
        raise MintError(TOO_MANY_VALUES, detail=f"a circle moves two axes, {len(selector.axes)} listed")


def _one_value(count: int, keyword: str) -> None:
    """A channel keyword takes one value a write, on one channel a call (000:547-548), and so does one that
    addresses nothing: more is #2017, before anything is written, as for more values than axes (000:572-576,
    19047)."""
    if count > 1:
        raise MintError(TOO_MANY_VALUES, detail=f"{count} values; {keyword} takes one")


def _evaluated(values: tuple[Evaluate | None, ...], fill: bool, addressed: tuple[int, ...] | None) -> Values:
    """The values written, a skipped place as None; a trailing ``;`` repeats the last for every axis left."""
    evaluated = tuple(value() if value is not None else None for value in values)
    if addressed is not None and fill and len(evaluated) < len(addressed):
        evaluated += (evaluated[-1],) * (len(addressed) - len(evaluated))
    return evaluated


_BLOCK_WORDS: dict[str, Callable[[StatementCompiler, Block, int], Operation]] = {
    "ENDIF": StatementCompiler._endif,
    "ELSE": StatementCompiler._else,
    "NEXT": StatementCompiler._next,
    "REPEAT": StatementCompiler._open_loop,
    "LOOP": StatementCompiler._open_loop,
    "ENDL": StatementCompiler._endl,
    "ENDW": StatementCompiler._endw,
    "STARTUP": StatementCompiler._step_over,
    "ENDSTARTUP": StatementCompiler._end_startup,
    "ENDEVENT": StatementCompiler._end_event,
}

_DISPATCH: dict[type, Callable[[StatementCompiler, n.Statement, int], Operation]] = {
    n.Assignment: StatementCompiler.assignment,  # type: ignore[dict-item]
    n.KeywordStatement: StatementCompiler.keyword_statement,  # type: ignore[dict-item]
    n.FunctionStatement: StatementCompiler.function_statement,  # type: ignore[dict-item]
    n.BareName: StatementCompiler.bare_name,  # type: ignore[dict-item]
    n.IfThen: StatementCompiler.if_then,  # type: ignore[dict-item]
    n.IfDo: StatementCompiler.if_do,  # type: ignore[dict-item]
    n.For: StatementCompiler.for_,  # type: ignore[dict-item]
    n.Until: StatementCompiler.until,  # type: ignore[dict-item]
    n.While: StatementCompiler.while_,  # type: ignore[dict-item]
    n.BlockWord: StatementCompiler.block_word,  # type: ignore[dict-item]
    n.EventBlock: StatementCompiler.event_block,  # type: ignore[dict-item]
    n.Jump: StatementCompiler.jump,  # type: ignore[dict-item]
    n.Pause: StatementCompiler.pause,  # type: ignore[dict-item]
    n.Dim: StatementCompiler.dim,  # type: ignore[dict-item]
    n.Define: StatementCompiler.nothing,
    n.Axes: StatementCompiler.axes,  # type: ignore[dict-item]
    n.Print: StatementCompiler.print_,  # type: ignore[dict-item]
    n.Input: StatementCompiler.input_,  # type: ignore[dict-item]
    n.SyntaxError_: StatementCompiler.syntax_error,  # type: ignore[dict-item]
}


def _given_a_value(keyword: str, values: Sequence[n.Expression | None]) -> None:
    """A write with every place empty (``SPEED.0 =``, ``MOVER = ,``, ``COMMS(1) =``) gives the keyword no
    value, #2005 (000:18930-18934), raised when its line runs, as ``mint check`` says; a skipped place
    beside a value (``SPEED = ,,20``) is legal."""
    if all(value is None for value in values):
        raise MintError(NO_EXPRESSION, detail=f"{keyword} is given no value after '='")
