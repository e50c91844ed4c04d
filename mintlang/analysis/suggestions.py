""" "Did you mean …": the known word spelt most like a misspelt one, for names, labels and keywords alike."""

from __future__ import annotations

from collections.abc import Iterable
from functools import cache

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing, Controller, Keyword, KeywordKind

NAME_LIKENESS = 0.8  # difflib's ratio: 'IDL' is 0.86 like 'IDLE', 'pos' 0.67 like 'post'
_ONE_SLIP_FROM = 3  # words this long or longer are matched one slip of the finger away whatever the ratio


def closest(word: str, known: Iterable[str], *, likeness: float = NAME_LIKENESS) -> str | None:
    """The word of ``known`` most like ``word`` (compared as given: fold the case first if it does not
    matter), if one is at least ``likeness`` alike or, failing that, one slip away (a letter added,
    dropped, changed, or two neighbours swapped: 'IDEL' for 'IDLE' is only 0.75 alike)."""
    from difflib import SequenceMatcher, get_close_matches  # noqa: PLC0415 - imported for a misspelt word alone

    candidates = list(known)
    found = get_close_matches(word, candidates, n=1, cutoff=likeness)
    if found:
        return found[0]
    if len(word) < _ONE_SLIP_FROM:
        return None
    slips = [candidate for candidate in candidates if one_slip_apart(word, candidate)]
    return max(slips, key=lambda candidate: SequenceMatcher(None, word, candidate).ratio(), default=None)


def one_slip_apart(word: str, other: str) -> bool:
    """Whether one insertion, deletion, substitution or swap of neighbours turns ``word`` into ``other``."""
    if word == other or abs(len(word) - len(other)) > 1:
        return False
    start = next((i for i, (a, b) in enumerate(zip(word, other, strict=False)) if a != b), min(len(word), len(other)))
    if len(word) == len(other):
        rest, other_rest = word[start + 1 :], other[start + 1 :]
        swapped = word[start + 2 :] == other[start + 2 :] and word[start : start + 2] == other[start : start + 2][::-1]
        return rest == other_rest or swapped
    longer, shorter = (word, other) if len(word) > len(other) else (other, word)
    return longer[start + 1 :] == shorter[start:]


# Words of other BASICs, which Mint spells otherwise (3.7.3: a WHILE loop ends with ENDW; 3.8, 000:1841-1842:
# a subroutine is called with GOSUB).
OTHER_BASICS = {"WEND": "ENDW", "ENDWHILE": "ENDW", "CALL": "GOSUB"}

# Move types the guide's See-also lists and AXISMODE table name as if they were keywords, with the keyword that
# starts the move (000:6209, 7157; HTA 000:11676).
MOVE_TYPES = {"HOLDTOANALOG": "HTA"}

_WAIT = "a wait of a time is WAIT = milliseconds"  # WAIT = <expression> (000:17324, 17343)

# An IF block has one ELSE, alone on its line, and an IF nested in it has its own ENDIF (000:1589-1600, 1633-1654):
# how Mint writes other BASICs' ELSEIF and ELSE IF.
NESTED_IF = "write ELSE on its own line, then an IF block of its own inside it, closed before the outer one"

# Words of other BASICs that no Mint word replaces, with how Mint writes what they do.
OTHER_BASICS_WRITTEN = {
    "ELSEIF": f"an IF block has no ELSEIF: {NESTED_IF}",
    "LET": "Mint assigns without LET: leave it out",  # newPos = 2 (000:917-922)
    "SUB": "a subroutine begins with its label, #name, ends with RETURN and is called by GOSUB name",  # 000:1841-1850
    "CONST": "a named constant is a macro: DEFINE name = value",  # 000:1460-1462
    "DELAY": _WAIT,
    "SLEEP": _WAIT,
}


# The jumps, which name a label (GOSUB, GOTO: 000:11146, 11187-11188): a word alone on its statement is none.
_NAMING_A_LABEL = frozenset({"GOSUB", "GOTO"})


@cache
def _keywords_of(
    controller: Controller | None, *, values: bool, dialect: Dialect, axes: bool = False, alone: bool = False
) -> tuple[str, ...]:
    """The keywords a program for ``controller`` (any, when None) in ``dialect`` can use, by their full names
    (not the editor's commands); with ``values``, only those read or written (SPEED, POS), not commands or block
    words; with ``axes``, only those that take an axis or channel; ``alone``, none that names a label."""
    found = []
    for name, keyword in database().keywords_of(dialect).items():
        if keyword.kind is KeywordKind.COMMAND_LINE:
            continue
        if controller is not None and not keyword.available_on(controller):
            continue
        if (axes and keyword.addressing is Addressing.NONE) or (alone and name in _NAMING_A_LABEL):
            continue
        if not values or _holds_a_value(keyword, controller):
            found.append(name)
    return tuple(found)


def _holds_a_value(keyword: Keyword, controller: Controller | None) -> bool:
    """Whether ``keyword`` is read or written on ``controller``: its attributes row says so, and a parameter the
    guide gives no row (MOVEBUFFERSIZE, listed without an attributes table) is taken to be one."""
    if not keyword.attributes:
        return keyword.kind is KeywordKind.PARAMETER
    rows = keyword.attributes if controller is None else (keyword.attributes_for(controller),)
    return any(row is not None and (row.read or row.write) for row in rows)


@cache
def keyword_like(
    word: str,
    controller: Controller | None,
    *,
    values: bool = False,
    dialect: Dialect = Dialect.V4,
    axes: bool = False,
    alone: bool = False,
) -> str | None:
    """The keyword of ``controller`` (any, when None) in ``dialect`` that ``word`` (upper case) is most likely a
    misspelling of; with ``values``, a keyword that holds a value, for a word used as a variable; with ``axes``,
    one that takes the axes or channel the word is given; ``alone``, one that can be a statement by itself. A move
    type the guide names as a keyword is the keyword that starts the move, on a controller that has it."""
    if word in OTHER_BASICS_WRITTEN:
        return None
    started_by = MOVE_TYPES.get(word)
    if started_by is not None and started_by in _keywords_of(controller, values=False, dialect=dialect):
        return started_by  # on a controller that has the move
    return OTHER_BASICS.get(word) or closest(
        word, _keywords_of(controller, values=values, dialect=dialect, axes=axes, alone=alone)
    )


def not_a_keyword(word: str, meant: str | None, *, alone: bool = False) -> str:
    """Error 3007's detail for ``word``, with the keyword ``meant`` if it resembles one. A word ``alone`` as a
    statement that resembles none may be a variable its author meant to give a value (000:877-879)."""
    if (written := OTHER_BASICS_WRITTEN.get(word.upper())) is not None:
        return f"'{word}' is not a keyword ({written})"
    hint = did_you_mean(meant) if meant is not None else "check the spelling and the abbreviation"
    if alone and meant is None:
        hint += f"; a variable alone is no statement: give it a value, {word} = …"
    return f"'{word}' is not a keyword ({hint})"


def did_you_mean(word: str) -> str:
    """The words that end a message offering ``word``."""
    return f"did you mean '{word}'?"
