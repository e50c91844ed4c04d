"""What the editor's Variables view shows of the paused controller, and the values it may set.

Mint has no local variables: every frame shows the same scopes, the
application's variables, its arrays, each axis, the digital I/O and the user
elements of the comms array. Axis values are read through the keyword table
(``POS.0``, ``FOLERROR.0`` …), so they are what the program would read at
this point. References are numbered afresh at every stop, as DAP allows.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.comms.array import USER_ELEMENTS
from mintlang.runtime.controller import Controller
from mintlang.runtime.debugger.evaluation import EvaluationError, Evaluator, shown
from mintlang.runtime.motion.axis import Axis

AXIS_KEYWORDS = ("POS", "VEL", "FOLERROR", "AXISMODE", "AXISERROR", "IDLE", "DRIVEENABLE", "MOVEBUFFERFREE")

Apply = Callable[[Controller], None]


class NotSettable(Exception):
    """The variable cannot be set from the editor (the message says why)."""


@record
class Variable:
    name: str
    value: str
    evaluate_name: str | None = None
    node: Node | None = None  # what expanding it shows
    indexed: int = 0  # how many indexed children it has (arrays, the comms array): the editor pages them


class Node(Protocol):
    def children(self, start: int, count: int | None) -> list[Variable]: ...

    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        """What setting ``name`` to ``value`` does (its description, and the change); raises ``NotSettable``."""
        ...


def _page(size: int, start: int, count: int | None) -> range:
    start = max(start, 0)
    return range(start, size if count is None or count <= 0 else min(size, start + count))


def _index(name: str, size: int) -> int:
    """The 1-based index an element's name ``(3)`` gives, checked against ``size``."""
    text = name.strip()
    if not (text.startswith("(") and text.endswith(")") and text[1:-1].strip().isdigit()):
        raise NotSettable(f"{name} is not an element")
    index = int(text[1:-1])
    if not 1 <= index <= size:
        raise NotSettable(f"index {index} outside 1 to {size}")
    return index


class _ReadOnly:
    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        raise NotSettable(f"{name} is shown, not set: change it with a statement of the program")


class Scalars:
    def __init__(self, controller: Controller, spellings: dict[str, str]) -> None:
        self.controller = controller
        self.spellings = spellings

    def children(self, start: int, count: int | None) -> list[Variable]:
        scalars = self.controller.vm.scalars
        named = sorted((self.spellings.get(identity, identity), slot) for identity, slot in self._slots().items())
        return [Variable(name, shown(scalars[slot]), name) for name, slot in named]

    def _slots(self) -> dict[str, int]:
        """Every variable's slot; an array's name has one too, a variable of its own when the program uses it as
        one (000:1086-1087)."""
        linked = self.controller.linked
        names = linked.names
        return {
            identity: slot
            for identity, slot in names.scalars.items()
            if identity not in names.arrays or identity in linked.plain
        }

    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        slot = self._slots().get(name[:10].upper())
        if slot is None:
            raise NotSettable(f"{name} is not a variable of the program")

        def apply(controller: Controller) -> None:
            controller.vm.scalars[slot] = value

        return f"{name} = {shown(value)}", apply


class Arrays(_ReadOnly):
    def __init__(self, controller: Controller, spellings: dict[str, str]) -> None:
        self.controller = controller
        self.spellings = spellings

    def children(self, start: int, count: int | None) -> list[Variable]:
        arrays = self.controller.vm.arrays
        found = []
        for identity, slot in sorted(self.controller.linked.names.arrays.items()):
            name = self.spellings.get(identity, identity)
            size = len(arrays[slot])
            found.append(Variable(name, f"array({size})", None, Elements(self.controller, name, slot), size))
        return found


class Elements:
    def __init__(self, controller: Controller, name: str, slot: int) -> None:
        self.controller = controller
        self.name = name
        self.slot = slot

    def children(self, start: int, count: int | None) -> list[Variable]:
        values = self.controller.vm.arrays[self.slot]
        return [
            Variable(f"({index + 1})", shown(values[index]), f"{self.name}({index + 1})")
            for index in _page(len(values), start, count)
        ]

    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        index = _index(name, len(self.controller.vm.arrays[self.slot]))
        slot = self.slot

        def apply(controller: Controller) -> None:
            controller.vm.arrays[slot][index - 1] = value

        return f"{self.name}({index}) = {shown(value)}", apply


class Axes(_ReadOnly):
    def __init__(self, controller: Controller, evaluator: Evaluator) -> None:
        self.controller = controller
        self.evaluator = evaluator

    def children(self, start: int, count: int | None) -> list[Variable]:
        found = []
        for axis in self.controller.axes:
            summary = (
                f"POS {_read(self.evaluator, f'POS.{axis.number}')}, VEL {_read(self.evaluator, f'VEL.{axis.number}')}"
            )
            found.append(
                Variable(f"axis {axis.number}", summary, None, AxisValues(self.evaluator, axis, self.controller.axes))
            )
        return found


class AxisValues(_ReadOnly):
    def __init__(self, evaluator: Evaluator, axis: Axis, axes: list[Axis]) -> None:
        self.evaluator = evaluator
        self.axis = axis
        self.axes = axes

    def children(self, start: int, count: int | None) -> list[Variable]:
        number = self.axis.number
        found = [
            Variable(keyword, _read(self.evaluator, f"{keyword}.{number}"), f"{keyword}.{number}")
            for keyword in AXIS_KEYWORDS
        ]
        loaded = len(self.axis.buffer)
        running = self.axis.move is not None
        summary = f"{'a move' if running else 'no move'} running, {loaded} loaded"
        # an empty buffer has nothing to show: the editor offers no arrow to expand it
        contents = MoveBuffer(self.axis, self.axes) if running or loaded else None
        found.append(Variable("move buffer", summary, None, contents))
        return found


class MoveBuffer(_ReadOnly):
    """The move running on an axis and those loaded behind it, with their modes, axes and end positions."""

    def __init__(self, axis: Axis, axes: list[Axis]) -> None:
        self.axis = axis
        self.axes = axes  # a vector's end positions are in each of its axes' units

    def children(self, start: int, count: int | None) -> list[Variable]:
        axis = self.axis
        found = []
        if axis.move is not None:
            move = axis.move
            ends = "open-ended" if move.end >= NEVER else f"ends at {move.end} ms"
            found.append(Variable("running", f"AXISMODE {move.mode}, axes {list(move.axes)}, {ends}"))
        for place, request in enumerate(axis.buffer, start=1):
            value = f"AXISMODE {request.mode}, axes {list(request.axes)}"
            if request.targets is not None:
                ends = zip(request.axes, request.targets, strict=True)
                value += ", to " + ", ".join(shown(self.axes[number].position(counts)) for number, counts in ends)
            found.append(Variable(f"({place})", value))
        return found


def _read(evaluator: Evaluator, expression: str) -> str:
    try:
        return shown(evaluator.evaluate(expression))
    except EvaluationError as error:
        return f"<{error}>"


class InputsOutputs(_ReadOnly):
    """The digital inputs (active states, after INPUTACTIVELEVEL), outputs and relay, as bit patterns."""

    def __init__(self, controller: Controller) -> None:
        self.controller = controller

    def children(self, start: int, count: int | None) -> list[Variable]:
        io = self.controller.io
        found = [
            Variable("IN", _bits(io.active, io.inputs.high + 1), None, Inputs(self.controller), io.inputs.high + 1),
            Variable("OUT", _bits(io.out, io.outputs.high + 1), "OUT"),
            Variable("RELAY", str(io.relay), "RELAY"),
        ]
        for channel in range(len(io.adc)):  # what ADC reads: a channel turned off holds its value
            found.append(Variable(f"ADC.{channel}", shown(io.adc_reading(channel)), f"ADC.{channel}"))
        return found


class Inputs:
    """Each digital input's active state; setting one is wiring it on or off now (until the scenario next
    changes it), so ``IN``, its edges and ``#INx`` see it as the program goes on."""

    def __init__(self, controller: Controller) -> None:
        self.controller = controller

    def children(self, start: int, count: int | None) -> list[Variable]:
        io = self.controller.io
        return [
            Variable(f"IN.{channel}", str(io.active >> channel & 1))
            for channel in _page(io.inputs.high + 1, start, count)
        ]

    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        prefix, _, number = name.partition(".")
        channels = self.controller.io.inputs.high + 1
        if prefix.upper() != "IN" or not number.isdigit() or int(number) >= channels:
            raise NotSettable(f"{name} is not an input: IN.0 to IN.{channels - 1}")
        if value not in (0, 1):
            raise NotSettable(f"an input is 0 or 1, not {shown(value)}")
        channel, active = int(number), bool(value)

        def apply(controller: Controller) -> None:
            io, world = controller.io, controller.world
            high = active == bool(io.active_level >> channel & 1)  # the electrical level that reads as ``active``
            world.levels = world.levels | 1 << channel if high else world.levels & ~(1 << channel)
            io.sample(world.apply(controller.clock.now))

        return f"IN.{channel} = {int(active)}", apply


def _bits(value: int, width: int) -> str:
    """A bank as the manual writes one, highest channel first, with its decimal value."""
    return f"{value:0{max(width, 1)}b} ({value})"


class Comms:
    """``COMMS(1)`` to ``COMMS(99)``: the elements the program and the host share."""

    def __init__(self, controller: Controller) -> None:
        self.controller = controller

    def children(self, start: int, count: int | None) -> list[Variable]:
        comms = self.controller.system.comms
        return [
            Variable(f"({address})", shown(comms.read(address)), f"COMMS({address})")
            for address in (USER_ELEMENTS.start + index for index in _page(len(USER_ELEMENTS), start, count))
        ]

    def assignment(self, name: str, value: float) -> tuple[str, Apply]:
        address = _index(name, USER_ELEMENTS.stop - 1)

        def apply(controller: Controller) -> None:
            controller.system.comms.write(address, value, external=False)

        return f"COMMS({address}) = {shown(value)}", apply


class References:
    """The variable references of one stop: scopes and expandable values by number."""

    def __init__(self) -> None:
        self.nodes: dict[int, Node] = {}
        self.indexed: set[int] = set()  # the references whose children are all indexed (elements), none named

    def clear(self) -> None:
        self.nodes.clear()
        self.indexed.clear()

    def add(self, node: Node, indexed: bool = False) -> int:
        reference = len(self.nodes) + 1
        self.nodes[reference] = node
        if indexed:
            self.indexed.add(reference)
        return reference

    def listed(self, reference: int, start: int, count: int | None, kind: str | None = None) -> list[dict[str, Any]]:
        """The ``variables`` response's list for ``reference``; ``KeyError`` for one this stop never gave.

        ``kind`` is the request's filter, ``named`` or ``indexed``: a node's children are all of one kind,
        so the other kind lists none (a client that asks for an array's named children gets no elements)."""
        node = self.nodes[reference]
        if kind is not None and (kind == "indexed") != (reference in self.indexed):
            return []
        return [self.as_dap(variable) for variable in node.children(start, count)]

    def as_dap(self, variable: Variable) -> dict[str, Any]:
        body: dict[str, Any] = {
            "name": variable.name,
            "value": variable.value,
            "variablesReference": self.add(variable.node, variable.indexed > 0) if variable.node is not None else 0,
        }
        if variable.evaluate_name is not None:
            body["evaluateName"] = variable.evaluate_name
        if variable.indexed:
            body["indexedVariables"] = variable.indexed
        return body


def scopes(controller: Controller, evaluator: Evaluator, spellings: dict[str, str]) -> list[tuple[str, Node, int]]:
    """The scopes of every frame: (name, node, how many values it holds, 0 when not counted)."""
    return [
        ("Variables", Scalars(controller, spellings), 0),
        ("Arrays", Arrays(controller, spellings), 0),
        ("Axes", Axes(controller, evaluator), 0),
        ("I/O", InputsOutputs(controller), 0),
        ("Comms", Comms(controller), len(USER_ELEMENTS)),
    ]
