"""Diagnostic codes: the controller's numbered errors and the toolchain's own checks.

``E<n>`` diagnostics carry the manual's error number and its title, so users
recognise them from the controller; ``W…`` warnings and ``I…`` hints are the
toolchain's own.
"""

from __future__ import annotations

from mintlang.diagnostics import Diagnostic, Fix, Severity, Span
from mintlang.keyworddb import database

# The toolchain's own checks: code -> short title.
OWN_CODES: dict[str, str] = {
    "W101": "Typographic quotes",
    "W102": "Mint v3 label",
    "W103": "Unused variable",
    "W104": "Unused label",
    "W105": "Unused macro",
    "W106": "Unreachable code",
    "W107": "Falls into the next subroutine",
    "W108": "Names equal in their first ten characters",
    "W109": "Event handler not available on this controller",
    "W110": "Block never closed",
    "W111": "Line too long",
    "W112": "EXIT outside a loop",
    "W113": "GOTO out of a block",
    "W114": "AUTO ignored",
    "W115": "Recursive GOSUB",
    "W116": "GOSUB nested too deep",
    "I201": "Faster dot syntax",
}


def known_codes() -> frozenset[str]:
    """Every code a diagnostic can carry: ``E<n>`` for the manual's errors, and the toolchain's own."""
    return frozenset(f"E{number}" for number in database().errors) | OWN_CODES.keys()


def mint_error(
    code: int,
    span: Span,
    detail: str,
    *,
    severity: Severity = Severity.ERROR,
    fixes: tuple[Fix, ...] = (),
    from_v3: bool = False,
) -> Diagnostic:
    """A diagnostic numbered as the controller numbers it, titled as the manual titles it."""
    record = database().errors.get(code)
    message = f"{record.title}: {detail}" if record is not None else detail
    return Diagnostic(f"E{code}", severity, span, message, mint_error=code, fixes=fixes, from_v3=from_v3)


def own(code: str, span: Span, detail: str, *, fixes: tuple[Fix, ...] = (), from_v3: bool = False) -> Diagnostic:
    """A diagnostic of the toolchain's own (W… warnings, I… hints)."""
    severity = Severity.WARNING if code.startswith("W") else Severity.INFO
    return Diagnostic(code, severity, span, detail, fixes=fixes, from_v3=from_v3)
