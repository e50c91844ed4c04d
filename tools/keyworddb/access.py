"""Cross-check the examples of the access errors (#2000, #2002) against the attribute tables.

Chapter 12 illustrates "Read only or Command" and "Write only" with a keyword;
when that keyword's own entry says otherwise the guide contradicts itself. The
error example wins: it is the guide's explicit statement of how the controller
rejects the keyword (ACCELTIME: the table allows reads, the #2002 example says
it is write only), and the conflict is recorded.
"""

from __future__ import annotations

import re
from dataclasses import replace

from mintlang.keyworddb.model import ErrorCode, Keyword
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.seeds import Seed

_FORBIDDEN_ACCESS = {2000: ("write", "written"), 2002: ("read", "read")}
"""Error code -> the ``Attributes`` flag its example says the keyword lacks, and its participle."""
_EXAMPLE = re.compile(r"^e\.g\.\s+(?P<code>.+)$")
_WORD = re.compile(r"\b[A-Z][A-Z0-9]+\b")


def _example(seed: Seed, error: ErrorCode) -> tuple[int, str] | None:
    number = seed.next_nonblank(seed.next_nonblank(error.line))
    match = _EXAMPLE.match(seed.stripped(number))
    return (number, match["code"]) if match else None


def apply_access_examples(
    seed: Seed, errors: dict[int, ErrorCode], keywords: dict[str, Keyword]
) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Keywords with the access the error examples show, and the conflicts this settles."""
    found = []
    updated = dict(keywords)
    for code, (access, participle) in sorted(_FORBIDDEN_ACCESS.items()):
        example = _example(seed, errors[code])
        if example is None:
            continue
        number, text = example
        for word in _WORD.findall(text):
            keyword = updated.get(word)
            if keyword is None or not keyword.attributes:
                continue
            if any(getattr(row, access) for row in keyword.attributes):
                detail = (
                    f"{word}: its attributes table (entry line {keyword.line}) allows {access}s, but the example "
                    f"of error #{code} '{errors[code].title}' (line {number}) says it cannot be {participle}; "
                    "the error example is followed"
                )
                found.append(conflict("access", word, detail, (keyword.line, number), keywords=[word]))
                rows = tuple(replace(row, **{access: False}) for row in keyword.attributes)
                updated[word] = replace(keyword, attributes=rows)
    return updated, found
