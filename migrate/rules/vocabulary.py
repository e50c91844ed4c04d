"""Which words are v4 keywords, which of them the migrator writes, and safe new user names."""

from __future__ import annotations

from mintlang.keyworddb import database
from mintlang.semantic.symbols import Symbol
from mintlang.syntax.nodes import SIGNIFICANT_CHARACTERS, identity

# v4 keywords the rules write that the v3 reader takes for user names. A v3 variable with one
# of these names reads like the migrator's own output. It is the user's where the application
# does not show v4 (``recognise``) and the name is assigned and read, as a variable that does
# something is; the migrator writes a v3 keyword's assignment (``HMSPEED = 10``) as one of
# these and nothing more. Within a run M-IDENT reads the text before any rule has written one.
_WRITTEN = frozenset(
    {
        *("KPROP", "HOMEBACKOFF", "HOMESPEED", "KINTLIMIT", "MASTERDISTANCE", "FOLERROR", "STOPSWITCH"),
        *("STOPINPUTMODE", "FOLERRORFATAL", "POSTARGET", "POSREMAINING", "HOMESWITCH", "IDLEPOS"),
        *("DACLIMITMAX", "CURRENTLIMIT", "SRAMP", "TERMINAL", "CONTOURMODE", "LIMITMODE", "EVENTDISABLE"),
        *("HANDLERDISABLE", "AXISMODE", "AXISERROR", "BOOST", "DRIVEENABLE", "INPUTMODE", "INPUTNEGTRIGGER"),
        *("DECELTIME", "ENCODERWRAP", "FASTENCODER", "ENCODERPRESCALE", "ERRORINPUT", "BIN"),
        *("MASTERSOURCE", "MASTERCHANNEL", "FOLLOWMODE", "FOLLOWDENOM"),
    }
)

# v3's predefined comms array is v4's COMMS keyword (v3:13204, v4:8289): never a user name.
_V3_PREDEFINED = frozenset({"COMMS"})

# v4 keywords the rules write only where a value is read (S-CARD writes NODE for CARD, S-IN INSTATE for IN). The
# v3 reader takes them for user names as well, but these can be told apart: v3 declares a
# variable by its first assignment (or FOR, INPUT, DIM) and rejects reading one not declared
# before (v3:1352-1367, v3:1425-1429), so a name that is never written is the migrator's keyword.
_READ_ONLY_WRITTEN = frozenset({"NODE", "INSTATE"})


def is_migrator_read(symbol: Symbol) -> bool:
    """Whether ``symbol`` is a v4 keyword the migrator wrote as a read (see ``_READ_ONLY_WRITTEN``)."""
    written = bool(symbol.definitions) or any(reference.is_write for reference in symbol.references)
    return symbol.identity in _READ_ONLY_WRITTEN and not written


def is_v4_word(name: str) -> bool:
    """Whether a user name is a v4 keyword, abbreviation or glued-channel form (v4 error 2006)."""
    upper = name.upper()
    return not upper.startswith("_") and database().lookup(upper) is not None and upper not in _V3_PREDEFINED


def is_assigned_and_read(symbol: Symbol) -> bool:
    """Whether a user name is written and then read: a v3 variable, not a keyword the migrator
    wrote as an assignment (see ``_WRITTEN``). A read before the name is declared
    (``x = x | 128``, what the migrator writes for input modes) is not a variable's."""
    return any(not reference.is_write and reference.declared_before for reference in symbol.references)


def is_reserved_user_name(name: str) -> bool:
    """Whether a user name is a v4 word the migrator does not write (see ``_WRITTEN``): in an
    application that shows v4, the only v4 words that are certainly the user's."""
    return is_v4_word(name) and name.upper() not in _WRITTEN


def unique_rename(name: str, taken: set[str]) -> tuple[int, str]:
    """How to rename ``name``: keep its first ``n`` characters and add a suffix, so that the
    new ten-character identity is neither taken nor a v4 word."""
    for suffix in ("_u", *(f"_u{i}" for i in range(2, 100))):
        keep = min(len(name), SIGNIFICANT_CHARACTERS - len(suffix))
        candidate = name[:keep] + suffix
        if identity(candidate) not in taken and database().lookup(candidate) is None:
            return keep, suffix
    raise ValueError(f"no free name for {name}")  # pragma: no cover - 98 suffixes cannot all be taken
