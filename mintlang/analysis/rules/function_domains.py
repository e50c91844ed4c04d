"""Functions given a constant value outside the values they are defined for (error 3).

ACOS and ASIN take a value "in the range of -1 to 1", LOG one "greater than 0" (000:6279, 000:6595,
000:13723). Outside it there is no answer, and mint-run stops the line with #3, "Data specified out of
range" (000:18518-18521). The value is known to be outside when the constant folding the other rules use
gives it, worked out in the controller's binary32 numbers (``held_value``): ``ACOS(2)``, ``LOG(0)``,
``ASIN(-1.5)``, ``LOG(1-1)``. A variable or a keyword's reading is known only while the program runs.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from types import MappingProxyType

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.semantic.constants import held_value

# Each function whose guide entry bounds its value: the test the value must pass, and what it says.
_DOMAINS: Mapping[str, tuple[Callable[[float], bool], str]] = MappingProxyType(
    {
        "ACOS": (lambda x: -1 <= x <= 1, "in the range of -1 to 1"),
        "ASIN": (lambda x: -1 <= x <= 1, "in the range of -1 to 1"),
        "LOG": (lambda x: x > 0, "greater than 0"),
    }
)


def each_line(scope: LineScope) -> Iterator[Finding]:
    for call in scope.facts.calls:
        domain = _DOMAINS.get(call.function)
        if domain is None or len(call.arguments) != 1:
            continue  # another count is the functions rule's error 2003
        (argument,) = call.arguments
        value = held_value(argument, scope.dialect)
        holds, wanted = domain
        if value is not None and not holds(value):
            detail = f"{call.function} of {value:.15g}: its value must be {wanted}"
            yield Finding(scope.unit, mint_error(3, argument.span, detail))
