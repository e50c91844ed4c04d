"""The dialects ``mint-run`` runs: Mint v4 (the reference), Mint v3 (the older guide's language) and MintMT."""

from __future__ import annotations

from importlib import import_module
from types import ModuleType
from typing import TYPE_CHECKING

from mintlang.dialect import Dialect

if TYPE_CHECKING:
    from mintlang.runtime.semantics import Semantics

# Each dialect's semantics, by module and name: imported by the run that needs them, so that a command
# line naming the dialects (``mint-run --help``) does not load the runtime.
_SEMANTICS = {
    Dialect.V4: ("mintlang.runtime.dialects.v4", "V4"),
    Dialect.V3: ("mintlang.runtime.dialects.v3.semantics", "V3"),
    Dialect.MINTMT: ("mintlang.runtime.dialects.mintmt", "MINTMT"),
}
SIMULATED = tuple(_SEMANTICS)


def semantics(dialect: Dialect | str) -> Semantics:
    """What ``dialect`` means by a program's numbers, names and messages (ValueError for one not simulated)."""
    found = _SEMANTICS.get(Dialect(dialect))
    if found is None:
        raise ValueError(f"{Dialect(dialect).value} programs are not simulated yet: mint-run runs v4 and v3")
    module, name = found
    dialect_semantics: Semantics = getattr(import_module(module), name)
    return dialect_semantics


# The parts of the controller a dialect adds to the Mint v4 machine (its interrupts, keywords and motion), by
# module: imported by a run of that dialect alone (``controller.build_controller``).
_MACHINES = {
    Dialect.V3: "mintlang.runtime.dialects.v3.machine",
    Dialect.MINTMT: "mintlang.runtime.dialects.mintmt.machine",
}


def machine(dialect: Dialect) -> ModuleType:
    """The module of what ``dialect`` adds to the Mint v4 machine (KeyError for v4, which adds nothing)."""
    return import_module(_MACHINES[dialect])
