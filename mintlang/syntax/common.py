"""What two versions of a text share at their start and at their end.

Found by halves, comparing whole slices: strings compare at the speed of memory,
so finding where a keystroke changed a file of a megabyte takes a few
comparisons, not a loop over its characters.
"""

from __future__ import annotations


def common_prefix(old: str, new: str) -> int:
    """How many characters ``old`` and ``new`` share at the start: compares halves, not characters."""
    low, high = 0, min(len(old), len(new))
    while low < high:
        middle = (low + high + 1) // 2
        if new.startswith(old[low:middle], low):
            low = middle
        else:
            high = middle - 1
    return low


def common_suffix(old: str, new: str, most: int) -> int:
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
