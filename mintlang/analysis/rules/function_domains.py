"""Functions given constant values they have no result for in a Mint number (error 3, or 2021).

ACOS and ASIN take a value "in the range of -1 to 1", LOG one "greater than 0" (000:6279, 000:6595,
000:13723). A number has an 8-bit exponent and a 24-bit mantissa (000:714-716): EXP(100) or
POW(10, 39) is larger than any. Either way there is no answer, and mint-run stops the line with #3,
"Data specified out of range" (000:18518-18521). POW of 0 to a negative power divides by zero
(#2021, 000:19063-19070) and a negative number to a fraction has no real value (#3), as mint-run
stops on them (runtime/BEHAVIOUR.md, NM-5). The values are known when the constant folding the
other rules use gives them, worked out in the controller's binary32 numbers (``held_value``), and
EXP and POW are worked out by the functions mint-run uses (``mintlang.binary32``): ``ACOS(2)``,
``LOG(1-1)``, ``EXP(89)``. A variable or a keyword's reading is known only while the program runs.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from types import MappingProxyType

from mintlang import binary32
from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.semantic.constants import held_value
from mintlang.syntax import nodes as n

# Each function whose guide entry bounds its value: the test the value must pass, and what it says.
_DOMAINS: Mapping[str, tuple[Callable[[float], bool], str]] = MappingProxyType(
    {
        "ACOS": (lambda x: -1 <= x <= 1, "in the range of -1 to 1"),
        "ASIN": (lambda x: -1 <= x <= 1, "in the range of -1 to 1"),
        "LOG": (lambda x: x > 0, "greater than 0"),
    }
)

# The functions whose result can be too large for a number, by their argument count.
_GROWING: Mapping[str, tuple[int, Callable[..., float]]] = MappingProxyType(
    {"EXP": (1, binary32.exp), "POW": (2, binary32.power)}
)


def each_line(scope: LineScope) -> Iterator[Finding]:
    for call in scope.facts.calls:
        domain = _DOMAINS.get(call.function)
        if domain is not None and len(call.arguments) == 1:  # another count is the functions rule's error 2003
            (argument,) = call.arguments
            value = held_value(argument, scope.dialect)
            holds, wanted = domain
            if value is not None and not holds(value):
                detail = f"{call.function} of {value:.15g}: its value must be {wanted}"
                yield Finding(scope.unit, mint_error(3, argument.span, detail))
        elif call.function in _GROWING:
            found = _without_value(call, scope)
            if found is not None:
                number, detail = found
                yield Finding(scope.unit, mint_error(number, call.span, detail))


def _without_value(call: n.Call, scope: LineScope) -> tuple[int, str] | None:
    """The error number a call with constant arguments stops on, and why, when its result is no number:
    too large (3), 0 to a negative power (2021, a division by zero), a negative number to a fraction (3)."""
    count, function = _GROWING[call.function]
    values = [held_value(argument, scope.dialect) for argument in call.arguments]
    if len(values) != count or None in values:
        return None
    try:
        function(*values)
    except OverflowError:
        return 3, f"the result of {call.function} is too large for a Mint number"
    except ZeroDivisionError:
        return 2021, f"{call.function} of 0 to a negative power divides by zero"
    except ValueError:
        return 3, f"{call.function} of a negative number to a fraction has no real value"
    return None
