"""The controller's longest line (W111): it accepts 255 characters a line.

Every physical line counts, a comment's too, without its line break. What a
line gets depends on nothing else, so after an edit only the lines it touched
are measured again.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.codes import own
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic, Span
from mintlang.syntax.lexer import PhysicalLines


def each_text_line(lines: PhysicalLines, indices: range, controller: ControllerProfile) -> Iterator[Diagnostic]:
    """What lines ``indices`` of ``lines`` get, at offsets into their file."""
    limit = controller.max_line_length
    offsets = lines.offsets
    for index in indices:
        length = lines.lexed(index).content_end
        if length > limit:
            detail = f"line has {length} characters; the controller accepts {limit}"
            offset = offsets[index]
            yield own("W111", Span(offset + limit, offset + length), detail)
