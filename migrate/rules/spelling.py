"""Writing a new word in the style of the word it replaces.

Mint is case-insensitive; a program written in lower case should stay readable
after a rename, so ``hmspeed`` becomes ``homespeed`` and ``HMSPEED`` becomes
``HOMESPEED``. Mixed case (``HmSpeed``) gets the manual's upper case.
"""

from __future__ import annotations


def like(written: str, new: str) -> str:
    """``new`` in lower case when ``written`` is all lower case, else as the manual spells it."""
    letters = [c for c in written if c.isalpha()]
    return new.lower() if letters and all(c.islower() for c in letters) else new
