"""Mint v3 errors: the ``ERR`` codes of #ONERROR and the ``ERROR: ...`` messages (001:4905-5008, 001:12916-13186).

The simulated machine raises the v4 runtime's errors; here each becomes what a
v3 controller reports. Only system errors (0 out of range, 3 invalid axis setup,
4 invalid axis, 5 motion in progress, 6 servo off) and motion errors (11
following, 12 limit, 13 card aborted, 14 external) reach ``#ONERROR``; a
programming error ends the run with its chapter 11 message (001:4916). A v4
error with no v3 counterpart is not simulated.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType

from mintlang.runtime.errors import MintError, NotSimulated, error_title
from mintlang.runtime.motion.axis import ER_ABORT, ER_ERROR_INPUT, ER_FOLLOWING, ER_FWD_HARD, ER_REV_HARD

MOTION_ERROR = 12  # the v4 runtime's refusal to move an axis with an error latched

# v4 code -> (ERR, the chapter 11 message); ERR None: not trappable, the run ends
_TRAPPABLE: Mapping[int, tuple[int, str]] = MappingProxyType(
    {
        3: (0, "Out of range"),
        11: (3, "Invalid mode"),
        2: (4, "Invalid axis"),
        10: (5, "Motion in progress"),
        40: (6, "Servo off"),
    }
)
_PROGRAMMING: Mapping[int, str] = MappingProxyType(
    {
        2000: "Read only or Command",
        2001: "Missing parameter",
        2002: "Write only",
        2003: "Syntax error",
        2005: "No expression",
        2006: "Invalid Command",
        2007: "THEN or DO expected",
        2008: "TO expected",
        2009: "NEXT w/o FOR",
        2010: "RETURN w/o GOSUB",
        2011: "ELSE/ENDIF w/o IF DO",
        2012: "ENDW w/o WHILE",
        2013: "UNTIL w/o REPEAT",
        2014: "Incorrect loop terminator",
        2015: "Too many levels of nesting",
        2016: "Invalid Index",
        2017: "Missing parameter",
        3000: "Too many labels",
        3001: "Undefined Variables",
        3002: "Too many variables",
        3003: "Out of memory",
        3004: "Invalid label",
        3007: "Invalid Command",
    }
)
# the toolchain's checks the v3 compiler stops on -> chapter 11's message: a line past 127 characters (001:12999-13001)
_COMPILER_CHECKS: Mapping[str, str] = MappingProxyType({"W111": "Line too long"})
# AXISERROR bits -> (ERR, message), the first that is latched (ascending ERR)
_MOTION: tuple[tuple[int, int, str], ...] = (
    (ER_FOLLOWING, 11, "Following Error"),
    (ER_FWD_HARD | ER_REV_HARD, 12, "Limit Error"),
    (ER_ABORT, 13, "Card Aborted"),
    (ER_ERROR_INPUT, 14, "External Error"),
)
_UNITS = {"program": "Program", "configuration": "Config"}


class V3Errors:
    """The v3 style; ``latched`` reads the errors latched on an axis (its ``AXISERROR`` bits)."""

    stops_compiling = frozenset(_COMPILER_CHECKS)

    def __init__(self, latched: Callable[[int], int]) -> None:
        self.latched = latched

    def _described(self, error: MintError) -> tuple[int | None, str]:
        if error.code == MOTION_ERROR and error.axis is not None:
            return self._motion(self.latched(error.axis))
        if error.code in _TRAPPABLE:
            return _TRAPPABLE[error.code]
        if error.code in _PROGRAMMING:
            return None, _PROGRAMMING[error.code]
        raise NotSimulated(f"error {error.code}", f"{error.title}, which Mint v3 has no counterpart of")

    @staticmethod
    def _motion(bits: int) -> tuple[int, str]:
        for mask, number, title in _MOTION:
            if bits & mask:
                return number, title
        raise NotSimulated(f"AXISERROR {bits}", "an axis error Mint v3 has no counterpart of")

    def number(self, error: MintError) -> int | None:
        return self._described(error)[0]

    def resumes(self, error: MintError) -> bool:
        """A trapped error (system or motion) resumes after the failing line (001:5532): programming errors
        never reach ``#ONERROR``."""
        return True

    def message(self, error: MintError, unit: str | None, line: int | None, *, explained: bool = True) -> str:
        """``ERROR: Program: Out of range at line 10 on axis 2`` (001:4978-4982, 5008)."""
        title = self._described(error)[1]
        text = f"ERROR: {title}" if unit is None else f"ERROR: {_UNITS[unit]}: {title} at line {line}"
        if error.axis is not None:
            text += f" on axis {error.axis}"
        if error.detail and explained:
            text += f" ({error.detail})"
        return text

    def compiled(self, code: int | str, unit: str, line: int, explanation: str | None = None) -> str:
        title = _COMPILER_CHECKS[code] if isinstance(code, str) else _PROGRAMMING.get(code) or error_title(code)
        text = f"ERROR: {_UNITS[unit]}: {title} at line {line}"
        return f"{text} ({explanation})" if explanation else text

    def motion_error(self, axis: int, bits: int) -> MintError:
        """A motion error is reported as the refusal it is, with the error latched on ``axis``."""
        return MintError(MOTION_ERROR, axis, f"AXISERROR {bits}")
