"""Mint v3's semantics: scaled-integer numbers, its operators, functions and constants, its messages."""

from __future__ import annotations

import math
from types import MappingProxyType

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing
from mintlang.runtime.dialects.v3 import numbers, trig
from mintlang.runtime.dialects.v3.errors import V3Errors
from mintlang.runtime.dialects.v3.printing import format_binary, format_number
from mintlang.runtime.printing import format_using
from mintlang.runtime.semantics import Semantics


def _int(value: float) -> float:
    """``INT`` strips the fraction: "it will effectively round down" (001:9244-9278)."""
    return float(math.floor(value))


V3 = Semantics(
    dialect=Dialect.V3,
    number=numbers.fixed,
    initial=numbers.fixed,
    binary=numbers.BINARY_OPERATORS,
    unary=numbers.UNARY_OPERATORS,
    functions=MappingProxyType(
        {"ABS": abs, "INT": _int, "SIN": trig.sine, "COS": trig.cosine, "TAN": trig.tangent, "CHR": float}
    ),
    constants=MappingProxyType({name.upper(): record.value for name, record in database().v3_constants.items()}),
    axis_keywords=frozenset(
        name for name, record in database().v3_keywords.items() if record.addressing is Addressing.AXIS
    ),
    one_value_keywords=database().v3_one_value_writes,
    format_number=format_number,
    format_using=format_using,
    printers=MappingProxyType({"BINARY": format_binary}),
    errors=V3Errors,
)
