"""Mint v4, the reference dialect: binary32 numbers, the v4 guide's functions and constants, ``Rnnnn`` errors."""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing
from mintlang.runtime.errors import V4Errors
from mintlang.runtime.numbers import BINARY_OPERATORS, FUNCTIONS, UNARY_OPERATORS, f32
from mintlang.runtime.printing import format_number, format_using
from mintlang.runtime.semantics import Semantics

V4 = Semantics(
    dialect=Dialect.V4,
    number=f32,
    initial=f32,  # held as any number is (NM-6): DIM a(1) = 0.1 equals a(1) = 0.1
    binary=BINARY_OPERATORS,
    unary=UNARY_OPERATORS,
    functions=FUNCTIONS,
    constants={name.upper(): float(record.value) for name, record in database().constants.items()},
    axis_keywords=frozenset(
        name for name, record in database().keywords.items() if record.addressing is Addressing.AXIS
    ),
    one_value_keywords=frozenset(name for name, record in database().keywords.items() if record.one_value_a_write),
    format_number=format_number,
    format_using=format_using,
    printers={},
    errors=lambda latched: V4Errors(),
)
