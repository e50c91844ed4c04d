"""The controller's error for a use of a keyword its record forbids, one answer for ``mint check`` and ``mint-run``.

Writing a keyword that is read only or a command is error 2000 (``CAMINDEX = 4``); reading one that
is write only is 2002 (``PRINT ACCELTIME``, 000:18905-18918); naming a parameter on its own as a
statement is 2005 (``SPEED``); reading a command, or operands after a command that takes only axes,
is 2003 (``STOP following``, a comment missing its REM); an editor command in a program is 2006
(``NEW``); a keyword its controller lacks is 17, whose detail names the controllers that have it. The
attributes table decides; a keyword the guide gives none is judged by its formats. ``mint check`` reports
the error where the line is written, and ``mint-run`` gives the same number (2000 and 2002 when the line
runs, the compiler's errors before the program starts), so the two cannot drift apart.
"""

from __future__ import annotations

from typing import NamedTuple

from mintlang.controllers import profile
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller, Keyword, KeywordKind, Use
from mintlang.keyworddb.supplements import attributes_for


class Refusal(NamedTuple):
    """The controller's error number and what, in the tools' words, is wrong with the use."""

    code: int
    detail: str


def refusal(
    keyword: Keyword, controller: Controller, dialect: Dialect, use: Use, *, has_arguments: bool = False
) -> Refusal | None:
    """The error of using ``keyword`` as ``use`` on ``controller`` (``has_arguments``: a command statement
    with operands), or None when its record allows the use."""
    name = keyword.name
    if keyword.kind is KeywordKind.COMMAND_LINE:
        return Refusal(2006, f"{name} is an editor command: it works only at the command line, not in a program")
    missing = unavailable(keyword, controller)
    if missing is not None:
        return Refusal(17, missing)
    attributes = attributes_for(keyword, controller, dialect)  # HOMEPOS's too, which prints none
    if attributes is None:
        return _refusal_from_formats(keyword, use, has_arguments=has_arguments)
    if use is Use.WRITE and not attributes.write:
        what = "a command" if attributes.command else "read only"
        return Refusal(2000, f"{name} is {what} and cannot be given a value")
    if use is Use.READ and not attributes.read:
        if attributes.write:
            return Refusal(2002, f"{name} can only be written, not read")
        return Refusal(2003, f"{name} is a command and gives no value")
    if use is Use.COMMAND and not attributes.command:
        return _not_a_command(name, has_arguments=has_arguments, read=attributes.read, write=attributes.write)
    if use is Use.COMMAND and has_arguments and not keyword.takes_operands:
        return _no_operands(keyword)
    return None


def unavailable(keyword: Keyword, controller: Controller) -> str | None:
    """Why ``controller`` lacks ``keyword``, naming the controllers that have it (error 17); None if it has it."""
    if keyword.available_on(controller):
        return None
    having = [profile(other).title for other in keyword.controllers]
    listed = having[0] if len(having) == 1 else f"{', '.join(having[:-1])} and {having[-1]}"
    return f"{keyword.name} is not available on {profile(controller).title}, only on {listed}"


def _no_operands(keyword: Keyword) -> Refusal:
    """Error 2003 of operands after a command whose format writes none: only its axes (``STOP[axes]``), a
    terminal (``CLS {#<terminal>}``) or nothing (``BEEP``, ``ABORT``) may follow its name."""
    layout = keyword.formats[0]
    axes = ", only its axes" if "[" in layout else ""
    return Refusal(2003, f"{keyword.name} takes no operands{axes} ('{layout}')")


def _not_a_command(name: str, *, has_arguments: bool, read: bool = True, write: bool = True) -> Refusal:
    """The error of a keyword that is no command written as a statement: 2005 named alone, as ``SPEED``
    (000:18930-18933); 2003 given operands without '='. The message offers only the uses its access allows:
    a read-only keyword is never shown given a value, which is error 2000."""
    if not has_arguments:
        if not write:
            return Refusal(2005, f"{name} is read only: read it here (for example 'PRINT {name}')")
        if not read:
            return Refusal(2005, f"{name} is write only: give it a value here (for example '{name} = …')")
        return Refusal(2005, f"{name} must be read or given a value here (for example '{name} = …')")
    if not write:
        return Refusal(2003, f"{name} is read only and takes no value")
    if name == "WAIT":  # WAIT IDLE.0, as other languages wait on a condition (000:17314-17324)
        return Refusal(2003, f"{name} waits a time in milliseconds ('{name} = 100'): to wait on a condition, use PAUSE")
    return Refusal(2003, f"{name} takes a value with '=': '{name} = …'")


def _refusal_from_formats(keyword: Keyword, use: Use, *, has_arguments: bool) -> Refusal | None:
    """Error 2000 for a write to a keyword the manual gives no attribute table, judged by its
    formats: read only when every format reads it (``v = ERR``), a command when none assigns it
    (``BEEP``, ``VER``, ``LINE``: 2000 is for a command given a value too, 000:18905-18908); and
    2003 for reading such a command, as for ``PRINT GO``: no format gives it a value, and for operands
    after one whose formats write none (``BEEP 3``). A parameter every format reads or assigns is no
    command, as one whose table says so (``ERR`` alone: 2005)."""
    if not keyword.formats:
        return None
    if use is Use.COMMAND and keyword.kind is KeywordKind.PARAMETER and all("=" in text for text in keyword.formats):
        assigned = [text.strip().upper().startswith(keyword.name) for text in keyword.formats]
        return _not_a_command(keyword.name, has_arguments=has_arguments, read=not all(assigned), write=any(assigned))
    if use is Use.COMMAND and has_arguments and not keyword.takes_operands:
        return _no_operands(keyword)
    assigned = any("=" in text for text in keyword.formats)
    if use is Use.READ and keyword.kind is KeywordKind.COMMAND and not assigned:
        return Refusal(2003, f"{keyword.name} is a command and gives no value")
    if use is not Use.WRITE:
        return None
    if all(text.startswith("v =") for text in keyword.formats):
        return Refusal(2000, f"{keyword.name} is read only and cannot be given a value")
    if keyword.kind is KeywordKind.COMMAND and not assigned:
        return Refusal(2000, f"{keyword.name} is a command and cannot be given a value")
    return None
