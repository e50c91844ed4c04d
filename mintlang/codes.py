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
    "W111": "Line too long",
    "W112": "EXIT outside a loop",
    "W113": "GOTO out of a block",
    "W114": "AUTO ignored",
    "W115": "Recursive GOSUB",
    "W116": "GOSUB nested too deep",
    "I201": "Faster dot syntax",
}


# What the controller's compiler rejects before a program runs (000:4564-4570, 4611-4615): syntax (2003,
# 2004, 2006-2008), mismatched blocks (2009, 2011-2014) and nesting beyond the stack (2015), labels
# (3000, 3004), variables (3001, 3002), memory (3003), macros (3005, 3006) and keywords (3007). Every
# other error is raised by the line that causes it, when it runs, and #ONERROR sees it (000:4616-4619).
COMPILE_ERRORS = frozenset(
    {2003, 2004, 2006, 2007, 2008, 2009, 2011, 2012, 2013, 2014, 2015, 3000, 3001, 3002, 3003, 3004, 3005, 3006, 3007}
)


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
    at_run_time: bool | None = None,
) -> Diagnostic:
    """A diagnostic numbered as the controller numbers it, titled as the manual titles it.

    Whether the controller raises it when compiling or when the line runs follows
    from the number (``COMPILE_ERRORS``) unless ``at_run_time`` says otherwise.
    """
    record = database().errors.get(code)
    message = f"{record.title}: {detail}" if record is not None else detail
    if at_run_time is None:
        at_run_time = code not in COMPILE_ERRORS
    return Diagnostic(
        f"E{code}", severity, span, message, mint_error=code, fixes=fixes, from_v3=from_v3, at_run_time=at_run_time
    )


def own(code: str, span: Span, detail: str, *, fixes: tuple[Fix, ...] = (), from_v3: bool = False) -> Diagnostic:
    """A diagnostic of the toolchain's own (W… warnings, I… hints)."""
    severity = Severity.WARNING if code.startswith("W") else Severity.INFO
    return Diagnostic(code, severity, span, detail, fixes=fixes, from_v3=from_v3)
