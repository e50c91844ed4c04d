"""Linking an application into one operation list: configuration file first, then program.

Variables are shared by both files and allocated in compile order; arrays are
sized and initialised now, as the controller's compiler does (``arrays.py``).
Labels stay per file: the two files cannot call each other's subroutines,
event handlers included. ``END`` in
the configuration, or running off its end, continues with the program; in the
program it ends the run.

MintMT's blocks are entered by the controller, never by the code around them
(mintlang/MINTMT.md, MT-7): the program starts with its ``Startup`` block, if
it has one, however the configuration before it ends, and goes on at its
first line, stepping over the ``Startup`` and ``Event`` blocks it meets;
``Event Comms1`` is the handler of that event, as ``#COMMS1`` is in v4, and
``End Event`` returns from it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from mintlang.records import record
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter import compiled_loops
from mintlang.runtime.interpreter.arrays import array_problem, initial_values
from mintlang.runtime.interpreter.expressions import ExpressionCompiler, Names
from mintlang.runtime.interpreter.purity import endw_as_its_while, is_pure
from mintlang.runtime.interpreter.statements import FileLayout, StatementCompiler
from mintlang.runtime.interpreter.vm import Interpreter, Operation, Site, StopReason
from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.semantics import Semantics
from mintlang.runtime.terminal import Terminal
from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document


@record
class Linked:
    """What the rest of the runtime needs to know about the compiled application."""

    handlers: Mapping[str, int]  # the program's labels by identity (ONERROR, IN3, TIMER ...) -> pc
    configuration_handlers: Mapping[str, int]  # the configuration file's
    names: Names
    plain: frozenset[str]  # the names the program uses as plain variables, an array's name too (000:1086-1087)
    elses: Mapping[int, tuple[int, int]]  # an IF block's ELSE -> its IF .. DO and its ENDIF, by pc


def link(
    model: SemanticModel, vm: Interpreter, table: KeywordTable, terminal: Terminal, semantics: Semantics
) -> Linked:
    """Compile ``model`` into ``vm`` with the meaning ``semantics`` gives it; raises ``NotSimulated`` or
    ``MintError`` for what cannot run."""
    names = Names(macros=frozenset(model.symbols.macros))
    _allocate(model, vm, names, semantics.initial)
    expressions = ExpressionCompiler(vm, table, names, semantics)
    handlers: dict[Unit, Mapping[str, int]] = {}
    units = list(model.documents())
    layouts: list[tuple[dict[Place, int], dict[str, int], int, int]] = []  # positions, labels, start, end
    startup = next((block for block in model.structures[Unit.PROGRAM].blocks if block.kind is BlockKind.STARTUP), None)
    start = 0
    for unit, document in units:
        positions, labels, size = _layout(document, start)
        if unit is not Unit.PROGRAM and startup is not None:
            size += 1  # where the configuration runs off its end: the step into the program's Startup block
        layouts.append((positions, labels, start, start + size))
        start += size
    program_positions, _, program_start, _ = layouts[-1]
    entry = program_positions[startup.opener] + 1 if startup is not None else program_start
    statements: list[n.Statement] = []  # of each operation
    for (unit, document), (positions, labels, start, end_of_unit) in zip(units, layouts, strict=True):
        blocks = _blocks_by_place(model.structures[unit].blocks)
        on_end = _end_of_program(vm) if unit is Unit.PROGRAM else _continue_with_program(vm, entry)
        layout = FileLayout(positions, blocks, labels, start, end_of_unit, on_end)
        compiler = StatementCompiler(vm, table, terminal, expressions, layout)
        if unit is Unit.PROGRAM:
            vm.program_start = start
        handlers[unit] = labels
        for line in document.placed:
            text = line.syntax.text
            for index, statement in enumerate(n.flatten_statements(line.syntax.statements)):
                pc = len(vm.operations)
                vm.operations.append(_compiled(compiler, statement, Place(line.number, index), pc))
                statements.append(statement)
                vm.pure.append(is_pure(statement, semantics.functions))
                written = text[statement.span.start : statement.span.end].strip()
                declares = _declares(statement)
                vm.sites.append(Site(unit.value, line.number, written, type(statement).__name__, declares))
                vm.steps_over.append(declares)
        if unit is not Unit.PROGRAM and startup is not None:
            _enter_startup(vm, statements, units[-1][1], startup.opener, entry)
    vm.compiled_loops[:] = [None] * len(vm.operations)
    for (unit, _), (positions, *_) in zip(units, layouts, strict=True):
        endw_as_its_while(vm.pure, model.structures[unit].blocks, positions)
        compiled_loops.attach(vm, statements, model.structures[unit].blocks, positions, expressions)
    if program_start == 0:  # no configuration file: the program runs first, from its entry
        vm.pc = entry
    elses = {
        pc: ends
        for (unit, _), (positions, *_) in zip(units, layouts, strict=True)
        for pc, ends in _elses(model.structures[unit].blocks, positions).items()
    }
    return Linked(
        handlers.get(Unit.PROGRAM, {}),
        handlers.get(Unit.CONFIGURATION, {}),
        names,
        frozenset(expressions.plain),
        elses,
    )


def _declares(statement: n.Statement) -> bool:
    """Whether ``statement`` opens a MintMT Event or Startup block (``Site.declares``)."""
    return type(statement) is n.EventBlock or (type(statement) is n.BlockWord and statement.word == "STARTUP")


def _compiled(compiler: StatementCompiler, statement: n.Statement, place: Place, pc: int) -> Operation:
    """The statement's operation; one the simulator cannot build raises, when it runs, why not.

    The controller's compiler rejects only what ``mint check`` calls a compile error
    (those stop the run before it starts); a write to a read-only keyword (2000), a
    read of a write-only one (2002) or a keyword alone (2005) is raised by its line,
    which ``#ONERROR`` then sees. A keyword the simulator does not model stops the
    run only if its line runs, and names that line.
    """
    try:
        return compiler.compile(statement, place, pc)
    except (MintError, NotSimulated) as problem:
        return _raising(problem)


def _raising(problem: MintError | NotSimulated) -> Operation:
    def fail() -> None:
        raise problem

    return fail


def _layout(document: Document, start: int) -> tuple[dict[Place, int], dict[str, int], int]:
    """The pc of every statement (by its place: equal lines share their syntax) and label of one file;
    a MintMT ``Event`` block's handler is filed as the label of its event (``COMMS1``)."""
    positions: dict[Place, int] = {}
    labels: dict[str, int] = {}
    pc = start
    for line in document.placed:
        syntax = line.syntax
        if syntax.label is not None:
            labels.setdefault(syntax.label.identity, pc)
        for index, statement in enumerate(n.flatten_statements(syntax.statements)):
            positions[Place(line.number, index)] = pc
            if type(statement) is n.EventBlock:
                labels.setdefault(statement.name.text.upper(), pc + 1)
            pc += 1
    return positions, labels, pc - start


def _enter_startup(
    vm: Interpreter, statements: list[n.Statement], program: Document, opener: Place, entry: int
) -> None:
    """The operation after the configuration's last one, where it runs off its end or jumps past its last line:
    the program begins inside its MintMT ``Startup`` block (MT-7), as END in the configuration begins it. It is
    the ``Startup`` line's step into its block, which no reader sees run, as the controller alone enters it."""
    line = next(line for line in program.placed if line.number == opener.line)
    statement = n.flatten_statements(line.syntax.statements)[opener.index]
    vm.operations.append(_continue_with_program(vm, entry))
    statements.append(statement)
    vm.pure.append(False)
    written = line.syntax.text[statement.span.start : statement.span.end].strip()
    vm.sites.append(Site(Unit.PROGRAM.value, line.number, written, type(statement).__name__, True))
    vm.steps_over.append(True)


def _elses(blocks: tuple[Block, ...], positions: Mapping[Place, int]) -> dict[int, tuple[int, int]]:
    """Each closed IF block's ELSE with its opener and ``ENDIF``: the ELSE is the jump that ends the true
    branch, which coverage counts for the ENDIF (the block ended there) rather than for the ELSE."""
    return {
        positions[block.middle]: (positions[block.opener], positions[block.closer])
        for block in blocks
        if block.middle is not None and block.closer is not None
    }


def _blocks_by_place(blocks: tuple[Block, ...]) -> dict[Place, Block]:
    found: dict[Place, Block] = {}
    for block in blocks:
        for place in (block.opener, block.middle, block.closer):
            if place is not None:
                found[place] = block
    return found


def _allocate(model: SemanticModel, vm: Interpreter, names: Names, initial: Callable[[float], float]) -> None:
    """Slots for every variable and array, arrays sized and initialised from their DIM."""
    for symbol in model.symbols.variables.values():
        names.scalars[symbol.identity] = len(vm.scalars)
        vm.scalars.append(0.0)
    for _, _, facts in model.lines:
        for statement in facts.statements:
            if type(statement) is n.Dim and statement.size is not None and array_problem(statement, initial) is None:
                _dim_array(statement, vm, names, [initial(value) for value in initial_values(statement)])


def _dim_array(statement: n.Dim, vm: Interpreter, names: Names, initial: list[float]) -> None:
    identity = statement.name.identity
    if identity in names.arrays:
        vm.arrays[names.arrays[identity]][:] = initial
        return
    names.arrays[identity] = len(vm.arrays)
    vm.arrays.append(initial)


def _end_of_program(vm: Interpreter):
    def end() -> None:
        vm.stop(StopReason.END)

    return end


def _continue_with_program(vm: Interpreter, program_start: int):
    def end() -> None:
        vm.pc = program_start

    return end
