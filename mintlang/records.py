"""``record``: a frozen dataclass made without compiling a method per class (``frozen=False``: a mutable one).

``@dataclass(frozen=True, slots=True)`` writes six methods of each class as source
(``__init__``, ``__repr__``, ``__eq__``, ``__hash__``, ``__setattr__``, ``__delattr__``)
and compiles each with ``exec``, and asks ``inspect.signature`` for a docstring where the
class has none: about 0.4 ms a class, and a one-line ``mint check`` creates over a hundred
classes. ``record`` lets ``dataclass`` do only its bookkeeping (the fields,
``__match_args__``, the slots) and gives the class methods made of closures over
``operator.attrgetter``, which need no compiling. ``__init__`` sets each slot directly
(a frozen dataclass's calls ``object.__setattr__`` per field, and building syntax nodes,
many per line, is hot); its code is compiled once per shape of fields (how each is set)
and shared, renamed, by every record of that shape: 13 shapes serve a hundred classes.

The result is a genuine dataclass (``fields``, ``replace``, ``asdict``, ``is_dataclass``,
``match``, ``copy`` and ``pickle``, ``__dataclass_params__`` saying ``frozen``) with the
equality, hash, ``repr`` and ``FrozenInstanceError`` of ``@dataclass(frozen=True,
slots=True)``; ``tests/core/test_records.py`` holds the two to each other on generated
classes. What the codebase does not use is refused rather than half done: ordering,
``kw_only``, ``InitVar`` and ``__post_init__``. A record that is not frozen is held to
``@dataclass(slots=True)`` the same way; its ``__init__`` sets each field as an attribute,
the attributes renamed in the shared code as the parameters are. A class without a docstring gets
``Name(field, ...)``, not dataclass's ``Name(field: type, ...)``, which needs ``inspect``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import MISSING, Field, FrozenInstanceError, dataclass, fields, is_dataclass
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
    documented = bool(cls.__doc__)
    if not documented:
        cls.__doc__ = cls.__name__  # for now: a class without one makes dataclass call inspect.signature
    own = dict(cls.__dict__)
    # Extending a record: dataclass checks that a frozen class's bases are frozen, and wants to make it so itself.
    cls = dataclass(cls, init=False, repr=False, eq=False, frozen=frozen and _extends_a_record(cls), slots=slots)
    _say_what_it_is(cls.__dataclass_params__, eq=eq, frozen=frozen)  # as snapshots read it
    every = fields(cls)
    _refuse_what_records_do_not_do(cls, own, every)
    methods = {
        "__init__": _init_method(cls, every, frozen),
        "__repr__": _repr_method([f.name for f in every if f.repr]),
    }
    if eq:
        methods["__eq__"] = _eq_method(_values(field.name for field in every if field.compare))
    if slots and frozen:  # pickling: a frozen class with slots has no __dict__ to restore, nor a __setattr__ that works
        methods |= {"__getstate__": _getstate, "__setstate__": _setstate}
    for name, method in methods.items():
        if name not in own:  # what the class body defines stays, as with dataclass
            _install(cls, name, method)
    if eq and not _explicit_hash(own):
        if frozen:
            hashed = (field.name for field in every if (field.compare if field.hash is None else field.hash))
            _install(cls, "__hash__", _hash_method(_values(hashed)))
        else:
            cls.__hash__ = None  # type: ignore[assignment] # changing fields would change the hash
    if frozen:
        names = frozenset(field.name for field in every)
        _install(cls, "__setattr__", _frozen_setattr(cls, names))
        _install(cls, "__delattr__", _frozen_delattr(cls, names))
    if not documented:
        cls.__doc__ = f"{cls.__name__}({', '.join(field.name for field in every)})"
    return cls


def _refuse_what_records_do_not_do(cls: type, own: dict[str, Any], every: tuple[Field[Any], ...]) -> None:
    """A TypeError for what a record would otherwise get wrong without a word."""
    annotations: dict[str, object] = own.get("__annotations__", {})
    unsupported = [name for name in ("__setattr__", "__delattr__") if name in own]
    unsupported += ["__post_init__"] if hasattr(cls, "__post_init__") else []
    unsupported += [f"InitVar {name}" for name, kind in annotations.items() if "InitVar" in str(kind)]
    unsupported += [f"kw_only {field.name}" for field in every if field.kw_only]
    if unsupported:
        raise TypeError(f"{cls.__qualname__}: a record has no {', '.join(unsupported)}")


def _extends_a_record(cls: type) -> bool:
    bases = [base for base in cls.__mro__[1:] if is_dataclass(base)]
    if any(not base.__dataclass_params__.frozen for base in bases):  # type: ignore[attr-defined]
        raise TypeError(f"{cls.__qualname__}: a record cannot extend a dataclass that is not frozen")
    return bool(bases)


def _say_what_it_is(params: Any, *, eq: bool, frozen: bool) -> None:
    """``__dataclass_params__`` as ``@dataclass(frozen=frozen, eq=eq, slots=...)`` sets them, from those of the
    bookkeeping, which was told to write no ``__init__``, ``__repr__`` nor ``__eq__``."""
    params.init = params.repr = True
    params.eq = eq
    params.frozen = frozen


def _install(cls: type, name: str, method: Callable[..., Any]) -> None:
    if method not in (_getstate, _setstate):  # shared by every record: they keep their own names
        method.__qualname__ = f"{cls.__qualname__}.{name}"
    setattr(cls, name, method)


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


def _frozen_setattr(cls: type, names: frozenset[str]) -> Callable[[object, str, object], None]:
    def __setattr__(self: object, name: str, value: object) -> None:
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)  # a subclass that is not a record keeps its own attributes

    return __setattr__


def _frozen_delattr(cls: type, names: frozenset[str]) -> Callable[[object, str], None]:
    def __delattr__(self: object, name: str) -> None:
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


def _init_method(cls: type, every: tuple[Field[Any], ...], frozen: bool) -> Callable[..., None]:
    """``__init__`` for ``cls``: the shared code of its fields' shape, its parameters named after the fields.

    The code reads the setters (``s0``...), factories and defaults as globals, which each class
    gives its own; a field's parameter is a local variable, so renaming it changes nothing else.
    A record that is not frozen sets its fields as attributes (``a0``...), renamed after the fields too.
    """
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
            namespace[f"s{i}"] = _setter(cls, field.name)
        if field.init:
            names.append(field.name)
            defaults += default
    code = _template(tuple(shape), frozen)
    code = code.replace(
        co_varnames=tuple(names),
        co_names=tuple(attributes.get(name, name) for name in code.co_names),
        co_qualname=f"{cls.__qualname__}.__init__",
    )
    return FunctionType(code, namespace, "__init__", tuple(defaults))


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
