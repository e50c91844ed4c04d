"""Carrying a model over an edit: what the edit did not change is the previous version's, moved.

A re-parsed program (``mintlang.syntax.reparse``) names the window of lines its
edit touched. What each line gives on its own (its index, what the line rules
find there) is the previous version's outside the window, moved by the edit's
length: the analyser carries it over whatever the edit was. What is found over the
whole application is carried further only when its input did not change:

* the blocks, when every re-read line has the same block statements at the same
  places (line numbers name them, so no line was added or removed), whatever their
  conditions; an error about one of them lies in the window and is found again;
* every whole-application finding, when every re-read line means the same to
  the whole-application passes (``_meaning``: its statements without their spans,
  and without the values of the literals none of those passes reads) with the
  same label and indentation, uses no macro, and the edit keeps the file's line
  breaks and stops before its end (fixes that add text read how the file breaks
  and ends its lines). Typing in a comment or in a number is such an edit;
  typing in a name is not. A finding that lies in the re-read lines is found
  again, and with it all of them.

Either way the configuration and the controller are the previous ones. A block
diagnostic whose text lies in the window is found again: the blocks are matched
anew. Matching the blocks and building the symbol table cost time in proportion
to the file; a carried edit costs the lines it touched.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence
from dataclasses import fields, is_dataclass

from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Span
from mintlang.records import record
from mintlang.semantic.blocks import BLOCK_STATEMENTS, Structure, block_key, match_blocks
from mintlang.semantic.index import IndexedLines, LineFacts, line_facts
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.change import Change
from mintlang.syntax.parser import Document

Meaning = Callable[[n.PlacedLine, LineFacts], Hashable]  # what a pass reads of a line


@record
class Carried:
    """How a model was carried over from the previous version's."""

    change: Change  # the edit: the lines it touched, where the others moved
    pairs: Sequence[_Pair] | None  # each re-read line before and after, with its facts; None: lines added
    text_kept: bool  # labels, indentation, line breaks, macro uses and the file's end are as they were

    def same_for(self, meaning: Meaning) -> bool:
        """Whether every re-read line means the same as before to a pass that reads ``meaning`` of it:
        then what the pass found is the previous version's, moved."""
        return (
            self.text_kept
            and self.pairs is not None
            and all(meaning(old, old_facts) == meaning(new, new_facts) for old, old_facts, new, new_facts in self.pairs)
        )

    @property
    def same_facts(self) -> bool:
        """Every whole-application finding is the previous one, moved."""
        return self.same_for(_meaning)


def carry_model(
    previous: SemanticModel, program: Document, configuration: Document | None, controller: ControllerProfile
) -> SemanticModel | None:
    """The model of ``program``, re-parsed from ``previous``'s program; None where nothing is carried over."""
    change = program.change
    if change is None or previous.controller != controller or len(previous.program.source) != change.previous_length:
        return None
    configured = previous.configuration
    if (configured.source if configured else None) != (configuration.source if configuration else None):
        return None
    pairs = _window_pairs(previous.program, program, change)
    structure = _carried_structure(previous.structures[Unit.PROGRAM], pairs, change)
    carried = Carried(change, pairs, _text_kept(previous.program, program, change, pairs))
    configured = [(Unit.CONFIGURATION, configuration.placed)] if configuration is not None else []
    files = [*configured, (Unit.PROGRAM, program.placed)]
    previous_lines = previous.lines_if_made()
    lines = previous_lines.edited(files, change) if previous_lines is not None else None
    if structure is None:  # the blocks are matched anew, from the lines
        if lines is None:
            lines = IndexedLines(files)
        structure = match_blocks(lines.of(Unit.PROGRAM), controller, program.dialect)
    structures = {**previous.structures, Unit.PROGRAM: structure}
    return SemanticModel.of(program, configuration, controller, structures, lines=lines, carried=carried)


_Pair = tuple[n.PlacedLine, LineFacts, n.PlacedLine, LineFacts]


def _window_pairs(before: Document, now: Document, change: Change) -> Sequence[_Pair] | None:
    """Each re-read line before and after the edit with its facts; None where lines were added or removed."""
    if change.line_shift or change.old_lines != change.new_lines:
        return None
    first, after = change.first_line, change.first_line + change.old_lines
    return [
        (old, line_facts(Unit.PROGRAM, old), new, line_facts(Unit.PROGRAM, new))
        for old, new in zip(before.placed[first:after], now.placed[first:after], strict=True)
    ]


def _blocks_of(line: n.PlacedLine, facts: LineFacts) -> tuple[tuple[int, Hashable], ...]:
    """What the block matcher reads of a line, but for where its statements are (``block_key``)."""
    if facts.kinds.isdisjoint(BLOCK_STATEMENTS):
        return ()
    statements = enumerate(facts.statements)
    return tuple((at, block_key(item, line.syntax)) for at, item in statements if type(item) in BLOCK_STATEMENTS)


def _carried_structure(structure: Structure, pairs: Sequence[_Pair] | None, change: Change) -> Structure | None:
    """The previous blocks, moved, where no re-read line changed a block statement or moved a line."""
    if pairs is None:
        return None
    for old, old_facts, new, new_facts in pairs:
        if old.number != new.number or _blocks_of(old, old_facts) != _blocks_of(new, new_facts):
            return None
    diagnostics = tuple(map(change.diagnostic, structure.diagnostics))
    if None in diagnostics:
        return None
    return Structure(structure.blocks, diagnostics)  # type: ignore[arg-type]


def _text_kept(before: Document, now: Document, change: Change, pairs: Sequence[_Pair] | None) -> bool:
    """Nothing a whole-application pass reads of the text beside the lines' meanings changed."""
    if pairs is None or change.reaches_end:
        return False
    if any(_label(old) != _label(new) or _indentation(old) != _indentation(new) for old, _, new, _ in pairs):
        return False
    old_text = before.source[change.start : change.old_end]
    new_text = now.source[change.start : change.new_end]
    if old_text.count("\r\n") != new_text.count("\r\n"):
        return False  # fixes write the line breaks the file uses
    return not any(
        change.start <= expansion.span.start < end
        for document, end in ((before, change.old_end), (now, change.new_end))
        for expansion in document.expansions
    )


def _label(line: n.PlacedLine) -> str | None:
    label = line.syntax.label
    return label.text if label is not None else None


def _indentation(line: n.PlacedLine) -> str:
    """What comes before a line's first word: a DIM added above a use copies it."""
    return line.syntax.text[: line.syntax.span.start]


# What the whole-application passes read the values of: a DIM's size and values (the symbol table, arrays,
# memory), an element's index (arrays), the condition of a WHILE or an UNTIL (flow: is the loop endless).
_VALUED = (n.Dim, n.While, n.Until)
_LITERALS = (n.Number, n.CharConstant, n.StringLiteral)


def _meaning(line: n.PlacedLine, facts: LineFacts) -> Hashable:
    """A line's statements as the whole-application passes read them: without their spans, and
    without the values of their literals where no pass reads them. What could not be parsed is
    its text (the words in it count as uses of those names)."""
    return _statements(line, facts, names=True)


def control_meaning(line: n.PlacedLine, facts: LineFacts) -> Hashable:
    """A line as the passes that follow the control flow read it (flow, calls, events, AUTO): its
    statements without the names of variables, whose uses and declarations they do not read."""
    return _statements(line, facts, names=False)


def _statements(line: n.PlacedLine, facts: LineFacts, *, names: bool) -> Hashable:
    text = line.syntax.text
    return tuple(
        (n.SyntaxError_, statement.opens, statement.closes, text[statement.span.start : statement.span.end])
        if isinstance(statement, n.SyntaxError_)
        else _shape(statement, keep=isinstance(statement, _VALUED), names=names)
        for statement in facts.statements
    )


def _shape(value: object, *, keep: bool, names: bool) -> Hashable:
    if isinstance(value, Span):
        return None
    if isinstance(value, tuple):
        return tuple(_shape(item, keep=keep, names=names) for item in value)
    if not is_dataclass(value):
        return value  # type: ignore[return-value]
    kind = type(value)
    if isinstance(value, _LITERALS) and not keep:
        return kind
    if isinstance(value, n.Name) and not names:
        return kind
    if isinstance(value, n.Jump):  # where it goes: a label's name, whichever names are read
        return kind, value.word, value.label.text
    if isinstance(value, n.EventBlock):  # the event it handles
        return kind, value.name.text
    if isinstance(value, n.ElementRef):
        return kind, _shape(value.name, keep=keep, names=names), _shape(value.index, keep=True, names=names)
    return (kind, *(_shape(getattr(value, field.name), keep=keep, names=names) for field in fields(value)))
