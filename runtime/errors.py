"""Run-time errors with the controller's numbers.

A Mint program that fails at run time fails with one of the manual's error
codes (``ERR``), optionally tied to an axis or channel (``ERRAXIS``). The
interpreter turns a raised ``MintError`` into ``#ONERROR`` or into the end of
the run; nothing else in the runtime should raise for a program's mistake.
"""

from __future__ import annotations

from mintlang.keyworddb import database


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
