"""``record``: a frozen dataclass made without compiling a method per class (``frozen=False``: a mutable one).

``@dataclass(frozen=True, slots=True)`` writes six methods of each class as source
(``__init__``, ``__repr__``, ``__eq__``, ``__hash__``, ``__setattr__``, ``__delattr__``)
and compiles each with ``exec``, and asks ``inspect.signature`` for a docstring where the
class has none: about 0.4 ms a class, and a one-line ``mint check`` creates over a hundred
classes. Even told to write no method, ``dataclass`` spends about 0.3 ms a class on its
bookkeeping, most of it asking of each field's annotation, three times over with a regular
expression and module look-ups, whether it is a ``ClassVar``, an ``InitVar`` or ``KW_ONLY``.
``record`` keeps the bookkeeping itself (the ``Field`` objects ``dataclasses.fields`` reads,
``__dataclass_params__``, ``__match_args__``, the class made again with slots, as
``dataclass`` makes it; a ``ClassVar`` or ``InitVar`` is refused, seen in its annotation's
text) and gives the class methods made of closures over ``operator.attrgetter``, which need
no compiling. ``__init__`` sets each slot directly
(a frozen dataclass's calls ``object.__setattr__`` per field, and building syntax nodes,
many per line, is hot); its code is compiled once per shape of fields (how each is set)
and shared, renamed, by every record of that shape: 13 shapes serve a hundred classes.

The result is a genuine dataclass (``fields``, ``replace``, ``asdict``, ``is_dataclass``,
``match``, ``copy`` and ``pickle``, ``__dataclass_params__`` saying ``frozen``) with the
equality, hash, ``repr`` and ``FrozenInstanceError`` of ``@dataclass(frozen=True,
slots=True)``; ``tests/core/test_records.py`` holds the two to each other on generated
classes. What the codebase does not use is refused rather than half done: ordering,
``kw_only``, ``ClassVar``, ``InitVar`` and ``__post_init__``. A record that is not frozen is held to
``@dataclass(slots=True)`` the same way; its ``__init__`` sets each field as an attribute,
the attributes renamed in the shared code as the parameters are. A class without a docstring gets
``Name(field, ...)``, not dataclass's ``Name(field: type, ...)``, which needs ``inspect``.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable
from dataclasses import _FIELD, KW_ONLY, MISSING, Field, FrozenInstanceError, _DataclassParams, fields
from dataclasses import field as dataclass_field
from functools import cache
from operator import attrgetter
from reprlib import recursive_repr
from types import CodeType, FunctionType, MemberDescriptorType
from typing import Any, TypeVar, overload

T = TypeVar("T", bound=type)
Values = Callable[[object], tuple[object, ...]]


@overload
def record(cls: T, /) -> T: ...
@overload
def record(*, slots: bool = True, eq: bool = True, frozen: bool = True) -> Callable[[T], T]: ...
def record(
    cls: T | None = None, /, *, slots: bool = True, eq: bool = True, frozen: bool = True
) -> T | Callable[[T], T]:
    """``@dataclass(frozen=frozen, slots=slots, eq=eq)``, its methods shared rather than compiled.

    ``slots=False`` is for a class that keeps ``cached_property`` values (they need an
    instance ``__dict__``); ``eq=False`` for one compared, and hashed, by identity;
    ``frozen=False`` for working state changed while it is built (a symbol table, the
    blocks a check has open), whose fields are set as any attribute is and which has no hash.
    """
    if cls is None:
        return lambda cls: _make(cls, slots=slots, eq=eq, frozen=frozen)
    return _make(cls, slots=slots, eq=eq, frozen=frozen)


def _make(cls: T, *, slots: bool, eq: bool, frozen: bool) -> T:
    own = dict(cls.__dict__)
    every = _fields(cls, own, frozen)
    mine = [field for field in every.values() if field._field_type is _FIELD]  # as fields() picks them
    made: list[type] = []  # the class, once made: what a frozen one's guards and field setters belong to
    added: dict[str, Any] = {
        "__dataclass_fields__": every,  # what makes it a dataclass
        "__dataclass_params__": _params(eq=eq, frozen=frozen, slots=slots),
    }
    if "__match_args__" not in own:
        added["__match_args__"] = tuple(field.name for field in mine if field.init)
    init, setters = _init_method(cls, mine, frozen)
    methods = {"__init__": init, "__repr__": _repr_method([f.name for f in mine if f.repr])}
    if eq:
        methods["__eq__"] = _eq_method(_values(field.name for field in mine if field.compare))
    if slots and frozen:  # pickling: a frozen class with slots has no __dict__ to restore, nor a __setattr__ that works
        methods |= {"__getstate__": _getstate, "__setstate__": _setstate}
    methods = {name: method for name, method in methods.items() if name not in own}  # the body's stay, as dataclass's
    if eq and not _explicit_hash(own):
        if frozen:
            hashed = (field.name for field in mine if (field.compare if field.hash is None else field.hash))
            methods["__hash__"] = _hash_method(_values(hashed))
        else:
            added["__hash__"] = None  # changing fields would change the hash
    if frozen:
        names = frozenset(field.name for field in mine)
        methods |= {"__setattr__": _frozen_setattr(made, names), "__delattr__": _frozen_delattr(made, names)}
    for name, method in methods.items():
        if method not in (_getstate, _setstate):  # shared by every record: they keep their own names
            method.__qualname__ = f"{cls.__qualname__}.{name}"
    added |= methods
    if not cls.__doc__:
        added["__doc__"] = f"{cls.__name__}({', '.join(field.name for field in mine)})"
    if slots:  # made with its methods: setting each on a class made already updates the class's slots one by one
        cls = _slotted(cls, [field.name for field in mine], added)
    else:
        for name, value in added.items():
            setattr(cls, name, value)
    made.append(cls)
    init.__globals__.update({setter: _setter(cls, name) for setter, name in setters.items()})
    return cls


def _fields(cls: type, own: dict[str, Any], frozen: bool) -> dict[str, Field[Any]]:
    """The fields of ``cls``, its bases' first, as ``dataclass`` finds them, or a TypeError for what a record
    would otherwise get wrong without a word (and for what ``dataclass`` refuses)."""
    every: dict[str, Field[Any]] = {}
    bases = [base for base in cls.__mro__[-1:0:-1] if "__dataclass_fields__" in base.__dict__]
    for base in bases:
        every.update(base.__dataclass_fields__)  # type: ignore[attr-defined]
    if bases and not frozen and any(base.__dataclass_params__.frozen for base in bases):  # type: ignore[attr-defined]
        raise TypeError("cannot inherit non-frozen dataclass from a frozen one")
    if bases and frozen and not all(base.__dataclass_params__.frozen for base in bases):  # type: ignore[attr-defined]
        raise TypeError(f"{cls.__qualname__}: a record cannot extend a dataclass that is not frozen")
    annotations: dict[str, object] = own.get("__annotations__", {})
    unsupported = [name for name in ("__setattr__", "__delattr__") if name in own]
    unsupported += ["__post_init__"] if hasattr(cls, "__post_init__") else []
    keywords_only = False  # after a KW_ONLY marker
    for name, kind in annotations.items():
        written = str(kind)
        if written.rpartition(".")[2] == "KW_ONLY" or kind is KW_ONLY:
            keywords_only = True
            continue
        unsupported += [f"{pseudo} {name}" for pseudo in ("InitVar", "ClassVar") if pseudo in written]
        every[name] = _field(cls, name, kind, own.get(name, MISSING), keywords_only)
    for name, value in own.items():
        if isinstance(value, Field) and name not in annotations:
            raise TypeError(f"{name!r} is a field but has no type annotation")
    unsupported += [f"kw_only {field.name}" for field in every.values() if field.kw_only]
    if unsupported:
        raise TypeError(f"{cls.__qualname__}: a record has no {', '.join(unsupported)}")
    return every


def _field(cls: type, name: str, kind: object, default: object, keywords_only: bool) -> Field[Any]:
    """The field ``name: kind = default`` of ``cls``; a ``field(...)`` default leaves the class as its default."""
    made = default if isinstance(default, Field) else dataclass_field(default=default)
    made.name, made.type, made._field_type = name, kind, _FIELD  # as dataclass marks a field
    if made.kw_only is MISSING:
        made.kw_only = keywords_only
    if made.default.__class__.__hash__ is None:
        raise ValueError(f"mutable default {type(made.default)} for field {name} is not allowed: use default_factory")
    if made is default:
        if made.default is MISSING:
            delattr(cls, name)
        else:
            setattr(cls, name, made.default)
    return made


def _params(*, eq: bool, frozen: bool, slots: bool) -> Any:
    """``__dataclass_params__`` as ``@dataclass(frozen=frozen, eq=eq, slots=slots)`` sets them."""
    options = {"init": True, "repr": True, "eq": eq, "order": False, "unsafe_hash": False, "frozen": frozen}
    if sys.version_info >= (3, 12):  # pragma: no cover - the parameters dataclass gained these in 3.12
        options |= {"match_args": True, "kw_only": False, "slots": slots, "weakref_slot": False}
    return _DataclassParams(**options)


def _slotted(cls: T, names: list[str], added: dict[str, Any]) -> T:
    """``cls`` made again with a slot for each field and what ``added`` holds, as ``dataclass(slots=True)``
    makes it (a class's slots are fixed when it is made)."""
    if "__slots__" in cls.__dict__:
        raise TypeError(f"{cls.__name__} already specifies __slots__")
    namespace = dict(cls.__dict__) | added
    inherited = {slot for base in cls.__mro__[1:-1] for slot in _slots_of(base)}
    namespace["__slots__"] = tuple(name for name in names if name not in inherited)
    for name in (*names, "__dict__", "__weakref__"):  # the defaults stay in the fields; the old class's descriptors
        namespace.pop(name, None)
    qualname = cls.__qualname__
    cls = type(cls)(cls.__name__, cls.__bases__, namespace)
    cls.__qualname__ = qualname
    return cls


def _slots_of(cls: type) -> tuple[str, ...]:
    slots = cls.__dict__.get("__slots__", ())
    return (slots,) if isinstance(slots, str) else tuple(slots)


def _explicit_hash(own: dict[str, Any]) -> bool:
    """Whether the class body set ``__hash__`` (Python sets it to None where the body defines only ``__eq__``)."""
    kept = own.get("__hash__", MISSING)
    return not (kept is MISSING or (kept is None and "__eq__" in own))


def _values(names: Iterable[str]) -> Values:
    """A function giving a record's values of ``names`` as a tuple (``attrgetter`` of one name gives it bare)."""
    names = tuple(names)
    if len(names) > 1:
        return attrgetter(*names)
    if names:
        get = attrgetter(names[0])
        return lambda record: (get(record),)
    return lambda record: ()


def _repr_method(names: list[str]) -> Callable[[object], str]:
    values = _values(names)
    labels = [f"{name}=" for name in names]

    @recursive_repr()
    def __repr__(self: object) -> str:
        shown = ", ".join([label + repr(value) for label, value in zip(labels, values(self), strict=True)])
        return f"{self.__class__.__qualname__}({shown})"

    return __repr__


def _eq_method(values: Values) -> Callable[[object, object], bool]:
    def __eq__(self: object, other: object) -> bool:
        if other.__class__ is self.__class__:
            return values(self) == values(other)
        return NotImplemented

    return __eq__


def _hash_method(values: Values) -> Callable[[object], int]:
    def __hash__(self: object) -> int:
        return hash(values(self))

    return __hash__


def _frozen_setattr(made: list[type], names: frozenset[str]) -> Callable[[object, str, object], None]:
    """``__setattr__`` of the class ``made`` will hold."""

    def __setattr__(self: object, name: str, value: object) -> None:
        cls = made[0]
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)  # a subclass that is not a record keeps its own attributes

    return __setattr__


def _frozen_delattr(made: list[type], names: frozenset[str]) -> Callable[[object, str], None]:
    def __delattr__(self: object, name: str) -> None:
        cls = made[0]
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)

    return __delattr__


def _getstate(self: object) -> list[object]:
    return [getattr(self, field.name) for field in fields(self)]  # type: ignore[arg-type]


def _setstate(self: object, state: list[object]) -> None:
    for field, value in zip(fields(self), state, strict=True):  # type: ignore[arg-type]
        object.__setattr__(self, field.name, value)


class _Factory:
    """The default of a parameter whose field has a ``default_factory``: the factory makes the value."""

    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()

# What ``__init__`` sets the field at index ``i`` to: its parameter (which may have a default), its
# parameter or else what its factory makes, what its factory makes (``init=False``), or its default (``init=False``).
_VALUES = {
    "given": "p{i}",
    "given_or_made": "f{i}() if p{i} is FACTORY else p{i}",
    "made": "f{i}()",
    "fixed": "d{i}",
}


def _init_method(cls: type, every: list[Field[Any]], frozen: bool) -> tuple[FunctionType, dict[str, str]]:
    """``__init__`` for ``cls``: the shared code of its fields' shape, its parameters named after the fields;
    and, for a frozen record, the field each of its setters sets.

    The code reads the setters (``s0``...), factories and defaults as globals, which each class
    gives its own; a field's parameter is a local variable, so renaming it changes nothing else.
    The setters are the slots of the class as made with its slots: they are added to the globals then.
    A record that is not frozen sets its fields as attributes (``a0``...), renamed after the fields too.
    """
    setters: dict[str, str] = {}
    shape: list[str] = []
    names = ["__record_self__" if any(field.name == "self" for field in every) else "self"]
    defaults: list[object] = []
    attributes: dict[str, str] = {}
    namespace: dict[str, object] = {"FACTORY": _FACTORY, "__name__": cls.__module__}
    for field in every:
        i = len(shape)
        if field.default_factory is not MISSING:
            namespace[f"f{i}"] = field.default_factory
            kind, default = ("given_or_made", (_FACTORY,)) if field.init else ("made", ())
        elif field.default is not MISSING:
            namespace[f"d{i}"] = field.default
            kind, default = ("given", (field.default,)) if field.init else ("fixed", ())
        elif field.init:
            if defaults:
                raise TypeError(f"non-default argument {field.name!r} follows default argument")
            kind, default = "given", ()
        else:
            continue  # left unset, as dataclass leaves it
        shape.append(kind)
        attributes[f"a{i}"] = field.name
        if frozen:
            setters[f"s{i}"] = field.name
        if field.init:
            names.append(field.name)
            defaults += default
    code = _template(tuple(shape), frozen)
    code = code.replace(
        co_varnames=tuple(names),
        co_names=tuple(attributes.get(name, name) for name in code.co_names),
        co_qualname=f"{cls.__qualname__}.__init__",
    )
    return FunctionType(code, namespace, "__init__", tuple(defaults)), setters


@cache
def _template(shape: tuple[str, ...], frozen: bool) -> CodeType:
    """The code of an ``__init__`` setting fields of ``shape``, compiled once for every record of that shape."""
    parameters = [f"p{i}" for i, kind in enumerate(shape) if kind.startswith("given")]
    sets = "s{i}(self, {value})" if frozen else "self.a{i} = {value}"
    body = (
        "".join(f"    {sets.format(i=i, value=_VALUES[kind].format(i=i))}\n" for i, kind in enumerate(shape))
        or "    pass\n"
    )
    namespace: dict[str, Any] = {}
    exec(f"def __init__({', '.join(['self', *parameters])}):\n{body}", namespace)
    return namespace["__init__"].__code__  # type: ignore[no-any-return]


def _setter(cls: type, name: str) -> Callable[[object, object], None]:
    """Sets field ``name`` of a new record: through its slot, which the class's ``__setattr__`` does not guard."""
    slot = next((klass.__dict__[name] for klass in cls.__mro__ if name in klass.__dict__), None)
    if isinstance(slot, MemberDescriptorType):
        return slot.__set__
    return lambda record, value: object.__setattr__(record, name, value)
