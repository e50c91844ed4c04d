"""Packages whose public names are imported when first used (PEP 562).

A package's ``__init__`` that imports its public names eagerly makes every
submodule import pay for them: ``mint --version`` imports ``mintlang.cli``, which
imports ``mintlang`` first. ``import_when_used(__name__, {name: module})`` at the
end of an ``__init__`` defers each name to its first use, so
``from mintlang import parse`` and ``mintlang.parse`` work as before.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from importlib import import_module
from types import ModuleType

_WHERE = "_public_modules"


class _Package(ModuleType):
    """A package module whose missing public names are imported from where they live."""

    def __getattr__(self, name: str) -> object:
        module = self.__dict__.get(_WHERE, {}).get(name)
        if module is None:
            raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")
        value = getattr(import_module(module), name)
        self.__dict__[name] = value  # the next use is a plain attribute
        return value

    def __setattr__(self, name: str, value: object) -> None:
        # The import system sets each submodule on its package as it loads it. A public name that is also a
        # submodule's (``mintlang.migrate.rules``: the function, and the folder of rules) keeps the public
        # name, as it did when the package bound it after importing its submodules.
        if isinstance(value, ModuleType) and name in self.__dict__.get(_WHERE, {}):
            return
        super().__setattr__(name, value)

    def __dir__(self) -> list[str]:
        return sorted({*self.__dict__, *self.__dict__.get(_WHERE, {})})


def import_when_used(package: str, public: Mapping[str, str]) -> None:
    """Import each public name of ``package`` (name -> the module defining it) when it is first used."""
    module = sys.modules[package]
    module.__dict__[_WHERE] = dict(public)
    module.__class__ = _Package  # a module may change its class to customise attribute access
