"""A keyword Mint v4 has on the controller and MintMT does not is flagged: the migrated line would be error 17.

The MintMT notes mark some sections "NextMove only" (004:109, 136, 153, 176, 250, 288), and their
keywords are the NextMoves' alone in MintMT (MT-2), though v4 may give them to every controller:
``SUSPEND``, on all five in v4 (000:17775), is in the note's contouring section (004:176-248). What
such a line should do on a MintDrive is a choice for a person, so it is flagged and nothing is rewritten.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller
from mintlang.keyworddb.usage import unavailable
from mintlang.migrate.mintmt.source import Action, Flag, Source
from mintlang.syntax.tokens import TokenKind

ID = "MT-PLATFORM"
SUMMARY = "a keyword v4 has on the controller and MintMT does not is flagged (error 17 in MintMT)"


def find(source: Source, actions: Iterable[Action], controller: Controller | str) -> Iterator[Flag]:
    """A flag on each keyword of ``source`` that ``controller`` has in Mint v4 and not in MintMT."""
    machine = Controller(controller)
    db = database()
    v4, mintmt = db.keywords_of(Dialect.V4), db.keywords_of(Dialect.MINTMT)
    for _, _, token in source.tokens():
        if token.kind is not TokenKind.KEYWORD:
            continue
        name = db.owner(token.text, machine) or token.text.upper()
        before, after = v4.get(name), mintmt.get(name)
        if before is None or after is None or not before.available_on(machine):
            continue
        missing = unavailable(after, machine)
        if missing is not None:
            yield Flag(ID, token.start, f"in MintMT, {missing} (error 17)")
