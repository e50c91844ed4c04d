""" "Did you mean …": the known word spelt most like a misspelt one, for names, labels and keywords alike."""

from __future__ import annotations

from collections.abc import Iterable
from difflib import get_close_matches

NAME_LIKENESS = 0.8  # difflib's ratio: 'IDL' is 0.86 like 'IDLE', 'pos' 0.67 like 'post'


def closest(word: str, known: Iterable[str], *, likeness: float = NAME_LIKENESS) -> str | None:
    """The word of ``known`` most like ``word`` (compared as given: fold the case first if it does not
    matter), if one is at least ``likeness`` alike."""
    found = get_close_matches(word, list(known), n=1, cutoff=likeness)
    return found[0] if found else None


def did_you_mean(word: str) -> str:
    """The words that end a message offering ``word``."""
    return f"did you mean '{word}'?"
