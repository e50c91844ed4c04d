"""A ``record`` behaves as ``@dataclass(frozen=True, slots=True)`` does, without compiling its methods
(and ``record(frozen=False)`` as ``@dataclass(slots=True)``).

Generated classes (field lists with defaults, factories and the ``field`` flags) are made twice,
once each way, and their instances, built from the same generated values, are held to each other:
equality, hash, ``repr``, ``fields``, ``replace``, ``copy`` (the pickling protocol), ``match``
and ``FrozenInstanceError``, or for one not frozen, what setting a field does.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle
from collections.abc import Callable
from dataclasses import FrozenInstanceError, dataclass, field, fields, replace
from functools import cached_property
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.records import record

# Plain names, and names a generated method could confuse with its own (``__record_*__`` ones are reserved).
NAMES = st.sampled_from(["a", "b", "self", "other", "name", "value", "object", "hash", "type", "_FACTORY", "a0", "f0"])
SCALARS = st.none() | st.integers(-3, 3) | st.text(max_size=3) | st.sampled_from([math.nan, 0.0, -0.0, 1.5])
DEFAULTS = st.recursive(SCALARS, lambda inner: st.tuples(inner, inner), max_leaves=4)  # dataclass wants them hashable
VALUES = st.recursive(  # a list in a field makes its record unhashable
    SCALARS, lambda inner: st.tuples(inner, inner) | st.lists(inner, max_size=2), max_leaves=4
)


@st.composite
def specs(draw: st.DrawFn) -> list[dict[str, Any]]:
    """Fields: a name, maybe a default or a factory (required ones first), and the ``field`` flags."""
    names = draw(st.lists(NAMES, unique=True, max_size=5))
    required = draw(st.integers(0, len(names)))
    result = []
    for index, name in enumerate(names):
        kind = "required" if index < required else draw(st.sampled_from(["default", "factory"]))
        flags = {
            "repr": draw(st.booleans()),
            "compare": draw(st.booleans()),
            "hash": draw(st.sampled_from([None, True, False])),
            "init": kind == "required" or draw(st.booleans()),
        }
        result.append({"name": name, "kind": kind, "default": draw(DEFAULTS), "flags": flags})
    return result


def made(spec: list[dict[str, Any]], decorate: Callable[[type], type]) -> type:
    """A class named ``Generated`` with the fields of ``spec``, decorated."""
    namespace: dict[str, Any] = {"__annotations__": {}, "__module__": __name__, "__qualname__": "Generated"}
    for item in spec:
        namespace["__annotations__"][item["name"]] = "object"
        if item["kind"] == "default":
            namespace[item["name"]] = field(default=item["default"], **item["flags"])
        elif item["kind"] == "factory":
            namespace[item["name"]] = field(default_factory=lambda item=item: ("made", item["name"]), **item["flags"])
        else:
            namespace[item["name"]] = field(**item["flags"])
    return decorate(type("Generated", (), namespace))


def outcome(action: Callable[[], Any]) -> tuple[str, Any]:
    """What ``action`` gives, or the kind of exception it raises."""
    try:
        return "gives", action()
    except Exception as error:
        return "raises", type(error)


def same(left: tuple[str, Any], right: tuple[str, Any]) -> bool:
    """Equal outcomes; NaN, and containers holding it, are compared by their repr."""
    return left == right or repr(left) == repr(right)


def described(cls: type) -> list[tuple[Any, ...]]:
    return [
        (
            f.name,
            f.type,
            f.default,
            f.init,
            f.repr,
            f.compare,
            f.hash,
            f.kw_only,
            f.default_factory is dataclasses.MISSING,
        )
        for f in fields(cls)
    ]


@st.composite
def classes_and_arguments(draw: st.DrawFn) -> tuple[list[dict[str, Any]], bool, list[tuple[list[Any], dict[str, Any]]]]:
    """A spec, whether slotted, and the arguments of three instances (given by position or keyword, or left out)."""
    spec = draw(specs())
    calls = []
    for _ in range(3):
        positional: list[Any] = []
        keywords: dict[str, Any] = {}
        by_position = True
        for item in (item for item in spec if item["flags"]["init"]):
            if item["kind"] != "required" and draw(st.booleans()):
                by_position = False  # left out: what follows goes by keyword
                continue
            value = draw(VALUES)
            by_position = by_position and draw(st.booleans())
            if by_position:
                positional.append(value)
            else:
                keywords[item["name"]] = value
        calls.append((positional, keywords))
    return spec, draw(st.booleans()), calls


@given(classes_and_arguments(), st.booleans())
def test_a_record_and_a_dataclass_of_the_same_fields_behave_alike(
    case: tuple[list[dict[str, Any]], bool, list[tuple[list[Any], dict[str, Any]]]], frozen: bool
) -> None:
    spec, slots, calls = case
    mine = made(spec, record(slots=slots, frozen=frozen))
    theirs = made(spec, dataclass(frozen=frozen, slots=slots))
    assert described(mine) == described(theirs)
    assert mine.__match_args__ == theirs.__match_args__  # type: ignore[attr-defined]
    assert dataclasses.is_dataclass(mine)
    assert repr(mine.__dataclass_params__) == repr(theirs.__dataclass_params__)  # type: ignore[attr-defined]
    for item in spec:  # the class's own attribute: the default, or none (slots: the field's descriptor)
        assert (
            repr(getattr(mine, item["name"], None)).split(" of ")[0]
            == repr(getattr(theirs, item["name"], None)).split(" of ")[0]
        )
    ours = [mine(*positional, **keywords) for positional, keywords in calls]
    their = [theirs(*positional, **keywords) for positional, keywords in calls]
    for one, other in zip(ours, their, strict=True):
        assert repr(one) == repr(other)
        assert same(outcome(lambda one=one: hash(one)), outcome(lambda other=other: hash(other)))
        assert same(outcome(lambda one=one: copy.copy(one)), outcome(lambda other=other: copy.copy(other)))
        assert repr(copy.deepcopy(one)) == repr(copy.deepcopy(other))
        assert outcome(lambda one=one: dataclasses.asdict(one)) == outcome(
            lambda other=other: dataclasses.asdict(other)
        )
        for item in spec:
            assert same(("gives", getattr(one, item["name"])), ("gives", getattr(other, item["name"])))
        changes = {item["name"]: ("changed",) for item in spec[:1] if item["flags"]["init"]}
        assert repr(replace(one, **changes)) == repr(replace(other, **changes))
        for item in spec:
            setting = outcome(lambda one=one, name=item["name"]: setattr(one, name, ("set", name)))
            assert setting == outcome(lambda other=other, name=item["name"]: setattr(other, name, ("set", name)))
            assert setting == (("raises", FrozenInstanceError) if frozen else ("gives", None))
            if frozen:
                with pytest.raises(FrozenInstanceError):
                    delattr(one, item["name"])
        assert repr(one) == repr(other)
    for index, one in enumerate(ours):
        for later, other in enumerate(ours):
            assert (one == other) == (their[index] == their[later])
        assert one != their[index]  # another class: NotImplemented both ways, then identity


def test_a_record_pickles() -> None:
    point = Point(1, (2, 3))
    assert pickle.loads(pickle.dumps(point)) == point


def test_a_record_can_extend_a_record_and_the_fields_add_up() -> None:
    labelled = Labelled(1, label="a")
    assert [f.name for f in fields(labelled)] == ["x", "y", "label"]
    assert labelled == Labelled(1, (), "a")
    assert labelled != Point(1)
    assert repr(labelled) == "Labelled(x=1, y=(), label='a')"
    match labelled:
        case Labelled(x, y, label):
            assert (x, y, label) == (1, (), "a")
    with pytest.raises(FrozenInstanceError):
        labelled.label = "b"  # type: ignore[misc]


def test_a_record_without_slots_keeps_cached_properties() -> None:
    cached = Cached(3)
    assert cached.squared == 9
    assert cached.__dict__["squared"] == 9
    with pytest.raises(FrozenInstanceError):
        cached.n = 4  # type: ignore[misc]


def test_a_record_without_eq_is_compared_and_hashed_by_identity() -> None:
    one, other = Identity(1), Identity(1)
    assert one != other
    assert hash(one) == object.__hash__(one)
    assert repr(one) == "Identity(n=1)"


def test_a_class_without_a_docstring_is_documented_by_its_fields() -> None:
    assert Point.__doc__ == "Point(x, y)"
    assert Labelled.__doc__ == "Extends Point with a label."


def test_a_body_that_defines_a_method_keeps_it() -> None:
    @record
    class Shown:
        n: int

        def __repr__(self) -> str:
            return "shown"

    assert repr(Shown(1)) == "shown"


@pytest.mark.parametrize(
    ("body", "refused"),
    [
        ({"__post_init__": lambda self: None}, "__post_init__"),
        ({"__setattr__": lambda self, name, value: None}, "__setattr__"),
        ({"__annotations__": {"late": "dataclasses.KW_ONLY", "n": "int"}}, "kw_only n"),
        ({"__annotations__": {"n": "InitVar[int]"}}, "InitVar n"),
        ({"__annotations__": {"n": "ClassVar[int]"}}, "ClassVar n"),
    ],
    ids=["post_init", "setattr", "kw_only", "InitVar", "ClassVar"],
)
def test_what_a_record_does_not_do_is_refused(body: dict[str, Any], refused: str) -> None:
    namespace = {"__annotations__": {"n": "int"}, "__module__": __name__} | body
    with pytest.raises(TypeError, match=refused):
        record(type("Refused", (), namespace))


def test_a_record_cannot_extend_a_dataclass_that_is_not_frozen() -> None:
    @dataclass
    class Loose:
        n: int

    with pytest.raises(TypeError, match="not frozen"):
        record(type("Tight", (Loose,), {"__annotations__": {}, "__module__": __name__}))


@pytest.mark.parametrize(
    ("namespace", "extends_a_record", "refused"),
    [
        ({"__annotations__": {"n": "list[int]"}, "n": []}, False, "mutable default"),
        ({"__annotations__": {}, "n": field(default=1)}, False, "'n' is a field but has no type annotation"),
        ({"__annotations__": {"m": "int"}}, True, "cannot inherit non-frozen dataclass from a frozen one"),
    ],
    ids=["mutable default", "unannotated field", "mutable extending frozen"],
)
def test_what_a_dataclass_refuses_a_record_refuses(
    namespace: dict[str, Any], extends_a_record: bool, refused: str
) -> None:
    bases = (Point,) if extends_a_record else ()
    with pytest.raises((TypeError, ValueError), match=refused):
        dataclass(type("Refused", bases, namespace | {"__module__": __name__}), slots=True)
    with pytest.raises((TypeError, ValueError), match=refused):
        record(frozen=False)(type("Refused", bases, namespace | {"__module__": __name__}))


def test_no_parameter_without_a_default_may_follow_one_with_a_default() -> None:
    namespace = {"__annotations__": {"a": "int", "b": "int"}, "a": 1, "__module__": __name__}
    with pytest.raises(TypeError, match="non-default argument 'b' follows default argument"):
        record(type("Misordered", (), namespace))


@record
class Point:
    x: int
    y: tuple[int, ...] = ()


@record
class Labelled(Point):
    """Extends Point with a label."""

    label: str = ""


@record(slots=False)
class Cached:
    """Keeps a computed value."""

    n: int

    @cached_property
    def squared(self) -> int:
        return self.n * self.n


@record(eq=False)
class Identity:
    """Compared by identity."""

    n: int
