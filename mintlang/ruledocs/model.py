"""What the documentation of one diagnostic code says, as data: ``mint rule``, the pages in
``docs/rules/`` and the links from each diagnostic are all made from these records."""

from __future__ import annotations

from enum import StrEnum

from mintlang import check_application
from mintlang.codes import OWN_CODES, error_code
from mintlang.diagnostics import Diagnostic
from mintlang.keyworddb import database
from mintlang.records import record


class FixSafety(StrEnum):
    """Whether the checker's fix for a code can be applied without reading it."""

    SAFE = "safe"  # the program means what it meant (or what it plainly meant): applied by --fix
    UNSAFE = "unsafe"  # a guess at the author's intent, or a change of behaviour: review it
    NONE = "none"  # no fix is offered: what to write depends on the program


@record
class Example:
    """A file that has the problem and the same file without it; a test checks both.

    The file is a program, or with ``with_program`` a configuration file checked together
    with that program."""

    before: str
    after: str
    controller: str | None = None  # the controller the example is checked for; None: the default
    with_program: str | None = None

    def diagnostics(self, text: str, codes: tuple[str, ...]) -> tuple[Diagnostic, ...]:
        """What the checker reports of ``codes`` in ``text`` (``before`` or ``after``) as this example places it."""
        options = {"controller": self.controller} if self.controller is not None else {}
        if self.with_program is None:
            return check_application(text, select=codes, **options).program
        return check_application(self.with_program, config=text, select=codes, **options).configuration


@record
class RuleDoc:
    """The documentation of one code.

    ``key`` is the controller's error number (an int, however the code spells it) or the
    toolchain's own code (``"W103"``); ``manual`` cites the guides by line of the project's
    text extractions (``"v4:18920"``), shown to readers as sections. A code about a file rather
    than its text (W120, a file not checked) has no example program and nothing in the guides.
    """

    key: int | str
    catches: str
    why: str
    example: Example | None
    manual: tuple[str, ...]
    fix: str
    safety: FixSafety

    @property
    def code(self) -> str:
        """The code the checker reports (``E2016``, ``W103``)."""
        return self.key if isinstance(self.key, str) else error_code(self.key)

    @property
    def title(self) -> str:
        if isinstance(self.key, str):
            return OWN_CODES[self.key]
        return database().errors[self.key].title

    @property
    def severity(self) -> str:
        """What the checker reports it as: the controller's errors are errors (a RETURN the main program only
        reaches by falling into a subroutine, which may be a fragment's, is 2010 as a warning: its page says
        so)."""
        if isinstance(self.key, int):
            return "error"
        return "warning" if self.key.startswith("W") else "info"


@record
class Group:
    """Codes about one kind of problem, documented together."""

    name: str
    summary: str
    rules: tuple[RuleDoc, ...]
