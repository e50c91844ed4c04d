"""Read the error code lists of chapter 12 (``#<code> <dash> <title> (<_erCONSTANT>)``)."""

from __future__ import annotations

import re

from mintlang.keyworddb.model import ErrorCode, ErrorKind
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.seeds import Seed

_ERROR = re.compile(r"^#(?P<code>-?\d+)\s*[\u2013-]\s*(?P<title>.*?)\s*(?:\((?P<constant>_er\w+)\))?\s*$")
_CONSTANT_ALONE = re.compile(r"^\((?P<constant>_er\w+)\)$")
_FIRST_MINT_CODE = 500


def _constant_below(seed: Seed, number: int) -> str | None:
    """The constant when the conversion wrapped it onto its own line (#101)."""
    following = seed.next_nonblank(number)
    match = _CONSTANT_ALONE.match(seed.stripped(following)) if following <= len(seed.lines) else None
    return match["constant"] if match else None


def build_errors(seed: Seed) -> dict[int, ErrorCode]:
    """Every ``#code`` line from "12.2 MML Error Codes" to the end of the guide."""
    start = seed.find(r"^12\.2 MML Error Codes")
    errors: dict[int, ErrorCode] = {}
    for number in range(start, len(seed.lines) + 1):
        match = _ERROR.match(seed.stripped(number))
        if not match:
            continue
        code = int(match["code"])
        errors[code] = ErrorCode(
            code=code,
            kind=ErrorKind.MML if code < _FIRST_MINT_CODE else ErrorKind.MINT,
            title=match["title"],
            constant=match["constant"] or _constant_below(seed, number),
            line=number,
        )
    return errors


def shared_constants(errors: dict[int, ErrorCode]) -> list[Conflict]:
    """Conflicts: one ``_er`` constant printed for two codes (62 and 65)."""
    by_constant: dict[str, list[int]] = {}
    for error in errors.values():
        if error.constant:
            by_constant.setdefault(error.constant, []).append(error.code)
    return [
        conflict(
            "error_constant",
            constant,
            f"{constant} is printed for error codes {', '.join(map(str, codes))}; the constant keeps the first",
            (errors[code].line for code in codes),
        )
        for constant, codes in sorted(by_constant.items())
        if len(codes) > 1
    ]
