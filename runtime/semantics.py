"""What a Mint generation means by a program, as far as the interpreter has to know (one record per dialect).

One interpreter runs both Mint v4 and Mint v3: the parser gives both the same
syntax, and what differs at run time is gathered in a ``Semantics``, chosen
once when a program is compiled: how numbers are held and combined, what the
functions and constants are, which keywords address axes, how a number prints
and how errors are numbered and reported. The instances live in
``runtime/dialects``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime.errors import ErrorStyle


@record
class Semantics:
    """The meaning of a program's numbers, names and messages in one dialect."""

    dialect: Dialect
    number: Callable[[float], float]  # a literal, or a value stored in a variable, as the dialect holds it
    initial: Callable[[float], float]  # an array element as DIM initialises it when the program is compiled
    binary: Mapping[str, Callable[[float, float], float]]  # operators by spelling (word and symbol)
    unary: Mapping[str, Callable[[float], float]]
    functions: Mapping[str, Callable[..., float]]
    constants: Mapping[str, float]  # predefined constants by upper-case name
    axis_keywords: frozenset[str]  # keywords addressed by axis: without a selector they take the default axes
    one_value_keywords: frozenset[str]  # keywords a write gives one value (a channel's, ``Keyword.one_value_a_write``)
    format_number: Callable[[float], str]  # PRINT x
    format_using: Callable[[float, int, int | None], str]  # PRINT x USING int, frac
    printers: Mapping[str, Callable[[float], str]]  # keywords printing like PRINT, each number their way (BINARY)
    errors: Callable[[Callable[[int], int]], ErrorStyle]  # a controller's style, given each axis's AXISERROR
