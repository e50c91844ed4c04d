"""Which word of a comment's ``@word`` names a directive, spelt right or nearly (``@expext``, ``@sims``).

A misspelt directive is a comment like any other to the controller, so left alone it would silently
take an expectation out of a test. A word one slip from ``sim`` or ``expect`` is therefore taken as
meant for it and reported; other ``@`` words (``@author``, ``@simple``) stay comments.
"""

from __future__ import annotations

import re

from mintlang.analysis.suggestions import closest

KINDS = ("sim", "expect")
# REM, or MintMT's ' (which the lexer makes a comment only in MintMT, where v4 has character constants).
DIRECTIVE = re.compile(r"(?:\bREM|')\s*@(?P<word>\w+)(?P<body>.*)", re.IGNORECASE)


def meant_kind(word: str) -> str | None:
    """The directive ``word`` names or was surely meant to name (any case); None for any other word."""
    folded = word.lower()
    return folded if folded in KINDS else closest(folded, KINDS)
