"""``RELEASE`` in a configuration file: the user variables cleared before the program runs.

The manuals allow RELEASE only there, to start each run with no variables left from the
last (000:932-939, 001:1385). Variables are defined when the application is compiled and
RELEASE clears them when it runs (001:11328); the simulator compiles both files before the
run, so the program's own variables already exist and keep their places: cleared, each reads
0 again until the program sets it, as at the start of the run. Mint v4's RELEASE clears the
arrays too (000:5541-5543) and puts each back as its DIM initialises it when compiled; Mint
v3's keeps the array values (001:11326). runtime/BEHAVIOUR.md records the choice.
"""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.interpreter.vm import Interpreter, Operation


def release(vm: Interpreter, dialect: Dialect) -> Operation:
    """The operation of a ``RELEASE`` statement, compiled once the application's arrays are initialised."""
    scalars = vm.scalars
    arrays = vm.arrays if dialect is not Dialect.V3 else []
    compiled = [list(values) for values in arrays]

    def run_release() -> None:
        if not vm.in_configuration():  # Mint v4 refuses it when compiling (2006); v3's guide gives no error
            raise NotSimulated("RELEASE", "in a program")
        scalars[:] = [0.0] * len(scalars)  # in place: compiled statements hold these lists
        for values, initial in zip(arrays, compiled, strict=True):
            values[:] = initial

    return run_release
