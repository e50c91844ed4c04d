"""One span object for every equal span of a line's syntax.

A line's syntax holds a span per node, relative to the line's start, so the
same small spans recur line after line: ``(0, 5)`` is the first word of many.
A span is an immutable value, so one object serves them all, and a file's
trees hold a fraction of the span objects they would otherwise (they were a
tenth of a check's memory). A span reaching ``SHARED_BELOW`` or beyond is made
afresh, so the table stays small whatever the input.
"""

from __future__ import annotations

from mintlang.diagnostics import Span

SHARED_BELOW = 256  # the controller reads 255 characters a line: at most 33,000 spans are shared
_shared: dict[int, Span] = {}
_new = tuple.__new__  # builds Span without its Python-level constructor


def span(start: int, end: int) -> Span:
    """``Span(start, end)``: the same object for every equal span that ends below ``SHARED_BELOW``."""
    if end >= SHARED_BELOW or start < 0:
        return _new(Span, (start, end))
    key = start << 8 | end
    found = _shared.get(key)
    if found is None:
        found = _shared[key] = _new(Span, (start, end))
    return found
