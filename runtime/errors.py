"""Run-time errors with the controller's numbers.

A Mint program that fails at run time fails with one of the manual's error
codes (``ERR``), optionally tied to an axis or channel (``ERRAXIS``). The
interpreter turns a raised ``MintError`` into ``#ONERROR`` or into the end of
the run; nothing else in the runtime should raise for a program's mistake.
"""

from __future__ import annotations

from typing import Protocol

from mintlang.keyworddb import database

AXIS_ERROR_PRESENT = 500  # ERR in #ONERROR for an asynchronous motion error (EV-17 RC)
# Errors raised for a program's mistakes in many places, with their constants in the guide's list (000:18509-18960)
INVALID_AXIS = 2  # _erINVALID_AXIS
OUT_OF_RANGE = 3  # _erVALUE_OUT_OF_RANGE
INVALID_CHANNEL = 4  # _erINVALID_CHANNEL
MISSING_PARAMETER = 2001
SYNTAX_ERROR = 2003
INVALID_INDEX = 2016
TOO_MANY_VALUES = 2017
# The interpreter errors, mistakes in the source met when their line runs: the 2000s of section 12.4, as
# "Syntax error" (2003) and "NEXT w/o FOR" (2009), the ERR entry's examples (000:9912-9913, 18891-18892).
# The compiler errors are the 3000s (its examples: 3002, 3003), the system (motion library) errors below 500.
INTERPRETER_ERRORS = range(2000, 3000)


def error_title(code: int) -> str:
    """The manual's title of error ``code``, as the controller prints it."""
    record = database().errors.get(code)
    return record.title if record is not None else f"error {code}"


class MintError(Exception):
    """A run-time error the controller would report with ``code`` (and ``axis``, its ``ERRAXIS``)."""

    def __init__(self, code: int, axis: int | None = None, detail: str = "") -> None:
        self.code = code
        self.axis = axis
        self.detail = detail
        super().__init__(self.describe())

    @property
    def title(self) -> str:
        return error_title(self.code)

    def describe(self, *, explained: bool = True) -> str:
        """``R0003: Data specified out of range [axis/channel 0]``, as the controller prints it, then (when
        ``explained``) the simulator's own word on the cause in brackets."""
        text = f"R{self.code:04d}: {self.title}"
        if self.axis is not None:
            text += f" [axis/channel {self.axis}]"
        if self.detail and explained:
            text += f" ({self.detail})"
        return text


class NotSimulated(Exception):
    """A keyword or use the simulator does not model: the run stops and says which, instead of guessing."""

    def __init__(self, keyword: str, use: str) -> None:
        super().__init__(f"{keyword} ({use}) is not simulated by mint-run")
        self.keyword = keyword


class ErrorStyle(Protocol):
    """How a dialect numbers errors for ``ERR`` and words the messages the controller prints."""

    stops_compiling: frozenset[str]  # the toolchain's own checks (W…) whose finding the compiler also stops on

    def number(self, error: MintError) -> int | None:
        """What ``ERR`` reads after ``error``; None when ``#ONERROR`` cannot take it and the run ends.

        Raises ``NotSimulated`` for an error the dialect has no counterpart of.
        """
        ...

    def resumes(self, error: MintError) -> bool:
        """Whether ``RETURN`` from ``#ONERROR`` goes on with the program after ``error``; if not, the run then
        ends with the error's message, as when no handler takes it."""
        ...

    def message(self, error: MintError, unit: str | None, line: int | None, *, explained: bool = True) -> str:
        """The message of a run-time error at ``line`` of ``unit`` (``"program"`` or ``"configuration"``)."""
        ...

    def compiled(self, code: int | str, unit: str, line: int, explanation: str | None = None) -> str:
        """The message of compile error ``code`` (an error number, or one of ``stops_compiling``), which stops
        ``unit`` before it runs (``explanation``: the checker's own words, for the report; without it the
        message is as the controller prints it)."""
        ...

    def motion_error(self, axis: int, bits: int) -> MintError:
        """The error an axis raises when errors ``bits`` (``AXISERROR``) latch on it."""
        ...


class V4Errors:
    """Mint v4: ``ERR`` is the error's own number; ``R0003: PROGRAM Data specified out of range [line 20]``."""

    stops_compiling: frozenset[str] = frozenset()  # a line too long does not download, no error (000:18454-18456)

    def number(self, error: MintError) -> int | None:
        return error.code

    def resumes(self, error: MintError) -> bool:
        """An interpreter error calls ``#ONERROR`` and still ends the program (000:4614-4619); a system error
        resumes after the failing statement (EV-19 RC)."""
        return error.code not in INTERPRETER_ERRORS

    def message(self, error: MintError, unit: str | None, line: int | None, *, explained: bool = True) -> str:
        """``R0003: PROGRAM Data specified out of range [axis/channel 0] [line 20]`` (EV-13 RC)."""
        described = error.describe(explained=explained)
        if unit is None:
            return described
        return described.replace(":", f": {unit.upper()}", 1) + f" [line {line}]"

    def compiled(self, code: int, unit: str, line: int, explanation: str | None = None) -> str:
        """``C2014: PROGRAM Incorrect loop terminator [line 12]``."""
        return f"C{code:04d}: {unit.upper()} {explanation or error_title(code)} [line {line}]"

    def motion_error(self, axis: int, bits: int) -> MintError:
        return MintError(AXIS_ERROR_PRESENT, axis, f"AXISERROR {bits}")
