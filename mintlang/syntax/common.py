"""What two versions of a text share at their start and at their end.

Found by halves, comparing whole slices: strings compare at the speed of memory,
so finding where a keystroke changed a file of a megabyte takes a few
comparisons, not a loop over its characters. The language server asks for the
same two versions more than once per keystroke (the dialect's detection, the
re-parse), so ``shared_ends`` remembers its last answer.
"""

from __future__ import annotations

# The last two texts ``shared_ends`` compared, kept alive so that identity names them, with its answer:
# one tuple, replaced whole, so that a reader on another thread never sees one pair with another's answer.
_last: tuple[str, str, tuple[int, int]] = ("", "", (0, 0))


def shared_ends(old: str, new: str) -> tuple[int, int]:
    """How many characters ``old`` and ``new`` share at the start, then at the end after that start."""
    global _last  # noqa: PLW0603 - a one-pair memory of the module's own
    last_old, last_new, ends = _last
    if old is last_old and new is last_new:
        return ends
    start = _common_prefix(old, new)
    ends = (start, _common_suffix(old, new, min(len(old), len(new)) - start))
    _last = (old, new, ends)
    return ends


def _common_prefix(old: str, new: str) -> int:
    """How many characters ``old`` and ``new`` share at the start: compares halves, not characters."""
    low, high = 0, min(len(old), len(new))
    while low < high:
        middle = (low + high + 1) // 2
        if new.startswith(old[low:middle], low):
            low = middle
        else:
            high = middle - 1
    return low


def _common_suffix(old: str, new: str, most: int) -> int:
    """How many characters (at most ``most``) ``old`` and ``new`` share at the end."""
    low, high = 0, most
    old_length, new_length = len(old), len(new)
    while low < high:
        middle = (low + high + 1) // 2
        if new.endswith(old[old_length - middle : old_length - low], 0, new_length - low):
            low = middle
        else:
            high = middle - 1
    return low
