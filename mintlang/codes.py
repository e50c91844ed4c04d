"""Diagnostic codes: the controller's numbered errors and the toolchain's own checks.

``E<nnnn>`` diagnostics carry the manual's error number and its title, written
in four digits as the controller prints its codes (``E0002``, ``E2014``), so
users recognise them and a prefix selects one family only (``E2`` is E2000 to
E2021, never error 2). ``W…`` warnings and ``I…`` hints are the toolchain's own.
"""

from __future__ import annotations

import re
from functools import cache

from mintlang import keyworddb  # its loader is imported by the first call of keyworddb.database()
from mintlang.diagnostics import Diagnostic, Fix, Severity, Span

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
    "W113": "GOTO out of a block",
    "W114": "AUTO or PROTECT ignored",
    "W115": "Recursive GOSUB",
    "W116": "GOSUB nested too deep",
    "W117": "Unused suppression",
    "W118": "USING digits beyond the controller's limit",
    "W119": "Reverse software limit not below the forward one",
    "W120": "File not checked",
    "W121": "POW index from 0 to 1 on NextMove",
    "W122": "Fewer values than axes listed",
    "I201": "Faster dot syntax",
}


# What is checked unless a selection says otherwise: the controller's errors and the warnings. The
# hints (I…) suggest a faster spelling of correct code; they are asked for (``--select I``).
DEFAULT_SELECT = ("E", "W")


# What the controller's compiler rejects before a program runs (000:4564-4570, 4611-4615): syntax (2003,
# 2004, 2006-2008), mismatched blocks (2009, 2011-2014) and nesting beyond the stack (2015), labels
# (3000, 3004), variables (3001, 3002), memory (3003), macros (3005, 3006) and keywords (3007). Every
# other error is raised by the line that causes it, when it runs, and #ONERROR sees it (000:4616-4619).
SYNTAX_ERRORS = frozenset({2003, 2004, 2006, 2007, 2008})  # a statement not written as the compiler reads it
COMPILE_ERRORS = SYNTAX_ERRORS | {2009, 2011, 2012, 2013, 2014, 2015, 3000, 3001, 3002, 3003, 3004, 3005, 3006, 3007}


@cache  # one string per code, whatever the number of diagnostics that carry it
def error_code(number: int) -> str:
    """The code of the controller's error ``number``, in four digits as the controller prints it: E0002, E2014."""
    return f"E{number:04d}"


@cache
def known_codes() -> frozenset[str]:
    """Every code a diagnostic can carry: ``E<nnnn>`` for the manual's errors, and the toolchain's own."""
    errors = (error_code(number) for number in keyworddb.database().errors if number > 0)  # -1 is "Success"
    return frozenset(errors) | OWN_CODES.keys()


_SHORT_ERROR = re.compile(r"E([1-9][0-9]{0,2})")  # the manual's spelling of a number below 1000: E2, E17, E108


def _short_form(code: str) -> str | None:
    """The four-digit code an upper-cased short spelling names (E17 -> E0017), if it names a known error."""
    short = _SHORT_ERROR.fullmatch(code)
    full = error_code(int(short[1])) if short is not None else None
    return full if full in known_codes() else None


def code_named(text: str) -> str | None:
    """The code ``text`` names exactly, in either spelling (``e17``, ``E0017``, ``W103``); None if none.

    Where one code is meant (a suppression comment, a rule's documentation) the short
    spelling cannot be a prefix, so it always names its error.
    """
    code = text.strip().upper()
    return code if code in known_codes() else _short_form(code)


def selector(text: str) -> str:
    """A ``--select``/``--ignore`` entry as it is matched: the codes that begin with the result.

    Prefixes are read in the four-digit spelling, as ruff reads them: ``E2`` selects
    E2000 to E2021, ``E00`` the run-time errors below 100. The short spelling of an
    error is its alias only where it begins no code (``E17`` is E0017, ``E108``
    E0108); so ``E2``, ``E3``, ``E20`` and ``E30`` stay prefixes (write ``E0002``).
    ``ALL`` is every code, as in ruff: the empty prefix.
    Raises ValueError for an entry that selects nothing: a typo would hide findings.
    """
    code = text.strip().upper()
    if code == "ALL":
        return ""
    if any(name.startswith(code) for name in known_codes()):
        return code
    alias = _short_form(code)
    if alias is None:
        raise ValueError(f"'{code}' is no code and begins none (E0002, E2, W1, I201 ...)")
    return alias


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
    record = keyworddb.database().errors.get(code)
    message = f"{record.title}: {detail}" if record is not None else detail
    if at_run_time is None:
        at_run_time = code not in COMPILE_ERRORS
    return Diagnostic(
        error_code(code),
        severity,
        span,
        message,
        mint_error=code,
        fixes=fixes,
        from_v3=from_v3,
        at_run_time=at_run_time,
    )


def own(code: str, span: Span, detail: str, *, fixes: tuple[Fix, ...] = (), from_v3: bool = False) -> Diagnostic:
    """A diagnostic of the toolchain's own (W… warnings, I… hints)."""
    severity = Severity.WARNING if code.startswith("W") else Severity.INFO
    return Diagnostic(code, severity, span, detail, fixes=fixes, from_v3=from_v3)
