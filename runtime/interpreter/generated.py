"""Python functions generated from Mint expressions, with the binary32 rounding written inline.

A tree of closures costs a Python call per node and one more per rounding
(``numbers.f32``); ``s + i * 2 - 1`` took about twenty. Here an expression
becomes the text of one Python function, ``_u(_p(_u(_p(s + _u(_p(i * 2))[0]))[0] - 1))[0]``
in spirit, where ``_p``/``_u`` are the pack and unpack of a ``struct.Struct('<f')``:
the same rounding ``f32`` does, without the calls around it, and the same
error 3 when a result is too large for binary32.

The text names every value it uses by position (``_0``, ``_1`` …: variable
slots, literals, the functions it calls), bound as the function's defaults,
so it depends only on the shape of the expression; the compiled code is
cached by that text, and a program's many ``a = b + c`` share one code object.
"""

from __future__ import annotations

import functools
import struct
from collections.abc import Callable
from types import CodeType, FunctionType

from mintlang.records import record
from mintlang.runtime import numbers
from mintlang.runtime.errors import MintError

_BINARY32 = struct.Struct("<f")

# Every generated function's own names after its values: the rounding and the error it raises.
_HELPERS = "_p, _u, _big"
_GLOBALS = {"__builtins__": __builtins__}


def too_large() -> MintError:
    """What ``numbers.f32`` raises for a result binary32 cannot hold."""
    return MintError(numbers.OUT_OF_RANGE, detail="number too large")


@record
class Source:
    """An expression's Python text, always one atom (a name, a call, a subscript or a parenthesised whole)."""

    text: str
    binary32: bool = False  # its last operation rounded it to binary32
    test: str = ""  # a comparison's Python truth, without the 1.0 or 0.0 it makes of it

    @property
    def truth(self) -> str:
        """Text whose Python truth is the expression's truth in an IF, WHILE or UNTIL (non-zero)."""
        return self.test or self.text


class Emitter:
    """Names the values one generated function uses, then builds the function from its body."""

    def __init__(self) -> None:
        self._values: list[object] = []

    def name(self, value: object) -> str:
        """A name the generated text uses for ``value`` (a slot, a literal, a function, a list)."""
        self._values.append(value)
        return f"_{len(self._values) - 1}"

    @property
    def values(self) -> tuple[object, ...]:
        """The values named so far, in the order of their names."""
        return tuple(self._values)

    def scalar(self, scalars: list[float], slot: int) -> str:
        """Text reading the scalar variable kept at ``scalars[slot]``."""
        return f"{self.name(scalars)}[{self.name(slot)}]"

    def rounded(self, text: str, *operands: Source) -> str:
        """Text of ``text``'s value rounded to binary32 (round to nearest even, as ``numbers.f32``); ``text``
        is the arithmetic of ``operands``, when it is one."""
        return f"_u(_p({text}))[0]"

    def call(self, function: Callable[..., object], *arguments: str) -> str:
        return f"{self.name(function)}({', '.join(arguments)})"

    def expression(self, source: Source) -> Callable[[], float]:
        return self.function(f"return {source.text}")

    def function(self, body: str, arguments: str = "") -> Callable[..., object]:
        """A function of ``arguments`` (none by default) running ``body``; binary32 overflow becomes error 3."""
        parameters = "".join(f"_{index}, " for index in range(len(self._values)))
        code = _code(f"{arguments}{parameters}{_HELPERS}", body.replace("\n", "\n        "))
        return function(code, (*self._values, _BINARY32.pack, _BINARY32.unpack, too_large))


def _code(parameters: str, body: str) -> CodeType:
    """The code of ``def mint(parameters): body`` (keyed by its text, which names no value)."""
    return defined(
        f"def _mint({parameters}):\n"
        f"    try:\n        {body}\n"
        "    except OverflowError:\n        raise _big() from None\n"
    )


@functools.lru_cache(maxsize=4096)
def defined(text: str) -> CodeType:
    """The code of the function ``_mint`` that ``text`` defines, compiled once per text."""
    namespace: dict[str, object] = {}
    exec(compile(text, "<mint>", "exec"), namespace)
    return namespace["_mint"].__code__  # type: ignore[attr-defined]


def function(code: CodeType, defaults: tuple[object, ...]) -> Callable[..., object]:
    """A function running ``code`` with ``defaults`` as the values of its last parameters."""
    return FunctionType(code, _GLOBALS, "mint", defaults)


_ROUNDED: dict[Callable[..., float], str] = {numbers.add: "+", numbers.subtract: "-", numbers.multiply: "*"}
_COMPARED: dict[Callable[..., float], str] = {
    numbers.equal: "==",
    numbers.not_equal: "!=",
    numbers.less: "<",
    numbers.greater: ">",
    numbers.less_equal: "<=",
    numbers.greater_equal: ">=",
}


def binary(emitter: Emitter, operate: Callable[[float, float], float], left: Source, right: Source) -> Source:
    """``operate(left, right)``, written out when it is one of ``numbers``' arithmetic or comparisons
    (the left operand is evaluated first either way)."""
    symbol = _ROUNDED.get(operate)
    if symbol is not None:
        return Source(emitter.rounded(f"{left.text} {symbol} {right.text}", left, right), binary32=True)
    symbol = _COMPARED.get(operate)
    if symbol is not None:
        test = f"{left.text} {symbol} {right.text}"
        return Source(f"(1.0 if {test} else 0.0)", test=test)
    return Source(emitter.call(operate, left.text, right.text))


def unary(emitter: Emitter, operate: Callable[[float], float], operand: Source) -> Source:
    """``operate(operand)``, written out for ``numbers``' negation, unary plus (a rounding) and NOT."""
    if operate is numbers.negate:
        return Source(f"(-{operand.text})")
    if operate is numbers.f32:
        return Source(emitter.rounded(operand.text, operand), binary32=True)
    if operate is numbers.logical_not:
        return Source(f"(1.0 if {operand.text} == 0 else 0.0)", test=f"{operand.text} == 0")
    return Source(emitter.call(operate, operand.text))


def operator(operate: Callable[[float, float], float]) -> Callable[[float, float], float]:
    """``operate`` as one generated function when it is ``numbers``' arithmetic (a NEXT's step), else itself."""
    if operate not in _ROUNDED:
        return operate
    emitter = Emitter()
    return emitter.function(f"return {binary(emitter, operate, Source('a'), Source('b')).text}", "a, b, ")  # type: ignore[return-value]


def stored(emitter: Emitter, value: Source, number: Callable[[float], float]) -> str:
    """Text of ``value`` as a variable holds it, in the dialect's ``number``: binary32 holds a value its last
    operation has rounded as it is."""
    return value.text if value.binary32 and number is numbers.f32 else emitter.call(number, value.text)


def branch(emitter: Emitter, condition: Source, taken: str, otherwise: str) -> Callable[[], None]:
    """A statement that runs the line ``taken`` when ``condition`` holds and ``otherwise`` when not
    (IF .. THEN, ENDW, UNTIL): one call, the condition included."""
    return emitter.function(f"if {condition.truth}:\n    {taken}\nelse:\n    {otherwise}")  # type: ignore[return-value]
