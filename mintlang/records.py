"""``node``: a frozen, slotted dataclass whose constructor is cheap.

A frozen dataclass sets each field in ``__init__`` through
``object.__setattr__``, a Python-level call per field, which made building
the syntax tree 15 % of a whole check. Slot descriptors can set a field
directly (they bypass the class's ``__setattr__``, which is what keeps the
record frozen for everyone else), so ``node`` gives the class an
``__init__`` that does just that. Everything else — equality, hashing,
``repr``, ``match`` patterns, immutability — is the dataclass's own.
"""

from __future__ import annotations

from dataclasses import MISSING, dataclass, fields
from typing import TypeVar

T = TypeVar("T", bound=type)


def node(cls: T) -> T:
    """``@dataclass(frozen=True, slots=True)`` with a constructor that sets the slots directly."""
    record = dataclass(frozen=True, slots=True)(cls)
    names = [field.name for field in fields(record)]
    namespace: dict[str, object] = {f"_set_{name}": record.__dict__[name].__set__ for name in names}
    parameters = []
    for field in fields(record):
        assert field.default_factory is MISSING, "node fields take plain defaults"
        if field.default is not MISSING:
            namespace[f"_default_{field.name}"] = field.default
            parameters.append(f"{field.name}=_default_{field.name}")
        else:
            parameters.append(field.name)
    body = "".join(f"    _set_{name}(self, {name})\n" for name in names) or "    pass\n"
    exec(f"def __init__(self, {', '.join(parameters)}):\n{body}", namespace)
    init = namespace["__init__"]
    init.__qualname__ = f"{record.__qualname__}.__init__"  # type: ignore[attr-defined]
    record.__init__ = init  # type: ignore[misc]
    return record
