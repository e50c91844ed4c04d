"""The controller's longest line (W111): a v4 controller accepts 255 characters a line (000:255),
a v3 one 127 from an off-line editor, its compiler stopping on a longer one with "Line too long"
(001:5144, 001:12999-13001).

Every physical line counts, a comment's too, without its line break. What a
line gets depends on nothing else, so after an edit only the lines it touched
are measured again.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.codes import own
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Diagnostic, Span
from mintlang.dialect import Dialect
from mintlang.syntax.lexer import PhysicalLines

V3_LINE_LENGTH = 127


def longest_line(controller: ControllerProfile, dialect: Dialect) -> int:
    """How many characters a line may have in ``dialect`` on ``controller``."""
    return V3_LINE_LENGTH if dialect is Dialect.V3 else controller.max_line_length


def each_text_line(
    lines: PhysicalLines, indices: range, controller: ControllerProfile, dialect: Dialect
) -> Iterator[Diagnostic]:
    """What lines ``indices`` of ``lines`` get, at offsets into their file."""
    limit = longest_line(controller, dialect)
    offsets = lines.offsets
    for index in indices:
        length = lines.lexed(index).content_end
        if length > limit:
            detail = f"line has {length} characters; the controller accepts {limit}"
            offset = offsets[index]
            yield own("W111", Span(offset + limit, offset + length), detail)
