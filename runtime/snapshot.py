"""The state of a running simulation, saved so that it can be put back into the very same objects.

The debugger goes back by restoring a checkpoint and running on from it
(``debugger/checkpoints.py``). The controller's parts are wired to one another
by closures and bound methods (``controller.py``, every compiled statement):
``copy.deepcopy`` copies objects but not functions, so a copied controller
would run closures still bound to the original. A snapshot records instead what
each mutable object reachable from its roots holds, one level deep (a list's
items, an instance's attributes, the value of a closure cell that a closure
rebinds with ``nonlocal``), and ``restore`` puts
that back into the same objects: every closure, bound method and outside
reference stays right, and the objects made since the snapshot are simply no
longer referenced. What it keeps is the size of the state, not of the run.

Only the runtime's own classes and the built-in containers are walked; meeting
any other object (a lock, a file, a random generator) raises ``NotSnapshotted``
rather than restoring a state that is not the one saved. Objects in
``outside`` are neither walked nor saved: the observers of the run.
"""

from __future__ import annotations

import contextlib
import dataclasses
import dis
import enum
import functools
import re
import types
from collections import deque
from collections.abc import Callable, Collection, Iterable
from pathlib import PurePath
from typing import Any

from mintlang.allocation import kept_without_collector
from mintlang.records import record

_OWN = "mintlang."  # the modules whose classes a snapshot knows how to walk
_ATOMIC: frozenset[type] = frozenset(
    {int, float, complex, bool, str, bytes, type(None), range, types.CodeType, types.BuiltinFunctionType}
)
_EMPTY = object()  # an unset slot or an empty closure cell


class NotSnapshotted(Exception):
    """The state holds an object a snapshot cannot save and put back."""


Put = Callable[[Any, Any], None]  # puts a saved state back into its object


@record
class Snapshot:
    """What every mutable object reachable from the roots held when it was taken."""

    saved: tuple[tuple[Put, Any, Any], ...]  # (how to put it back, the object, what it held)

    def restore(self) -> None:
        for put, target, state in self.saved:
            put(target, state)

    def __len__(self) -> int:
        return len(self.saved)


@kept_without_collector  # the snapshot outlives the call: its hundreds of containers would set off full collections
def take(roots: Iterable[object], outside: Collection[object] = ()) -> Snapshot:
    """A snapshot of everything reachable from ``roots`` but not through ``outside``; raises ``NotSnapshotted``."""
    seen = {id(item) for item in outside}
    seen.add(id(_EMPTY))
    saved: list[tuple[Put, Any, Any]] = []
    pending = list(roots)
    while pending:
        item = pending.pop()
        kind = type(item)
        if kind in _ATOMIC or id(item) in seen:
            continue
        seen.add(id(item))
        walker = _WALKERS.get(kind) or _walker_of(kind)
        walker(item, saved, pending)
    return Snapshot(tuple(saved))


# ------------------------------------------------------------------ the walkers, one per kind of object

Walker = Callable[[Any, list[tuple[Put, Any, Any]], list[Any]], None]


def _put_list(target: list[Any] | bytearray, state: Any) -> None:
    target[:] = state


def _put_dict(target: dict[Any, Any], state: dict[Any, Any]) -> None:
    target.clear()
    target.update(state)


def _put_set(target: set[Any], state: tuple[Any, ...]) -> None:
    target.clear()
    target.update(state)


def _put_deque(target: deque[Any], state: tuple[Any, ...]) -> None:
    target.clear()
    target.extend(state)


def _put_cell(target: types.CellType, state: Any) -> None:
    if state is not _EMPTY:
        target.cell_contents = state
    else:
        with contextlib.suppress(ValueError):  # bound since the snapshot: unbound again
            del target.cell_contents


def _put_attributes(target: Any, state: dict[str, Any]) -> None:
    attributes = target.__dict__
    attributes.clear()
    attributes.update(state)


def _list(item: list[Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    state = tuple(item)
    saved.append((_put_list, item, state))
    pending.extend(state)


def _dict(item: dict[Any, Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    saved.append((_put_dict, item, item.copy()))
    pending.extend(item)
    pending.extend(item.values())


def _set(item: set[Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    state = tuple(item)
    saved.append((_put_set, item, state))
    pending.extend(state)


def _deque(item: deque[Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    state = tuple(item)
    saved.append((_put_deque, item, state))
    pending.extend(state)


def _bytearray(item: bytearray, saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    saved.append((_put_list, item, bytes(item)))


def _immutable(item: tuple[Any, ...] | frozenset[Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    pending.extend(item)


def _function(item: types.FunctionType, saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    """A closure: what its cells hold is walked; a cell it rebinds (``nonlocal``) is saved too. A cell no function
    of the run rebinds holds the same object for ever (its contents are walked, through this or another closure),
    and those are most of them: the compiled program's."""
    code = item.__code__
    rebound = _REBOUND.get(code)
    if rebound is None:
        rebound = _REBOUND[code] = _rebinds(code)
    for name, cell in zip(code.co_freevars, item.__closure__ or (), strict=True):
        try:
            value = cell.cell_contents
        except ValueError:  # a closure over a name not bound yet
            value = _EMPTY
        if name in rebound:
            saved.append((_put_cell, cell, value))
        pending.append(value)
    pending.extend(item.__defaults__ or ())
    pending.extend((item.__kwdefaults__ or {}).values())


_REBOUND: dict[types.CodeType, frozenset[str]] = {}  # by a function's code: the names of its cells it rebinds


def _rebinds(code: types.CodeType) -> frozenset[str]:
    """The free variables ``code`` assigns to or deletes (declared ``nonlocal`` in it)."""
    free = frozenset(code.co_freevars)
    changing = {"STORE_DEREF", "DELETE_DEREF"}
    return frozenset(op.argval for op in dis.get_instructions(code) if op.opname in changing and op.argval in free)


def _method(item: types.MethodType, saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    pending.append(item.__self__)
    pending.append(item.__func__)


def _partial(item: functools.partial[Any], saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    pending.append(item.func)
    pending.extend(item.args)
    pending.extend(item.keywords.values())


def _atomic(item: Any, saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
    pass


_WALKERS: dict[type, Walker] = {
    list: _list,
    dict: _dict,
    set: _set,
    deque: _deque,
    bytearray: _bytearray,
    tuple: _immutable,
    frozenset: _immutable,
    types.FunctionType: _function,
    types.MethodType: _method,
    functools.partial: _partial,
}


def _walker_of(kind: type) -> Walker:
    """How to walk an instance of one of the runtime's classes (found once per class, then kept)."""
    if issubclass(kind, (enum.Enum, type, PurePath, re.Pattern)):  # values that never change
        walker: Walker = _atomic
    elif not kind.__module__.startswith(_OWN):
        raise NotSnapshotted(f"cannot save the state of a {kind.__module__}.{kind.__qualname__}")
    else:
        walker = _instance_walker(kind)
    _WALKERS[kind] = walker
    return walker


def _instance_walker(kind: type) -> Walker:
    """An instance: its attributes (``__dict__``) and slots; a frozen dataclass's fields are walked, not saved."""
    slots = tuple(
        name
        for klass in kind.__mro__
        for name in getattr(klass, "__slots__", ())
        if name not in ("__dict__", "__weakref__")
    )
    params = getattr(kind, "__dataclass_params__", None)
    frozen = dataclasses.is_dataclass(kind) and params is not None and params.frozen

    def put_slots(target: Any, state: tuple[Any, ...]) -> None:
        for name, value in zip(slots, state, strict=True):
            if value is _EMPTY:
                if hasattr(target, name):
                    object.__delattr__(target, name)
            else:
                object.__setattr__(target, name, value)

    def walk(item: Any, saved: list[tuple[Put, Any, Any]], pending: list[Any]) -> None:
        if slots:
            state = tuple(getattr(item, name, _EMPTY) for name in slots)
            if not frozen:
                saved.append((put_slots, item, state))
            pending.extend(state)
        attributes = getattr(item, "__dict__", None)
        if attributes is not None:
            if not frozen:
                saved.append((_put_attributes, item, dict(attributes)))
            pending.extend(attributes.values())

    return walk
