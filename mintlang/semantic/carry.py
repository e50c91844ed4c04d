"""Carrying a model over an edit that changed no line's meaning.

Typing in a comment, or spaces after a line's last statement, leaves every line's
index (``LineFacts``) and label as they were: the blocks, the symbol table and
every whole-application finding are the previous version's, moved by the edit's
length. Matching the blocks and building the symbol table again would cost time
in proportion to the file on every keystroke; carrying them costs the lines the
edit touched.

Carried only when nothing the whole-application passes read can have changed:
the same configuration and controller, the same physical lines (line numbers
name the blocks), each re-read line with the same facts and label, no macro
used there, the same line breaks, and a window that stops before the end of the
file (fixes that add text at the end read how it ends). A block diagnostic
whose text lies in the window is found again: the model is built anew.
"""

from __future__ import annotations

from mintlang.controllers import ControllerProfile
from mintlang.semantic.blocks import Structure
from mintlang.semantic.index import line_facts
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax.change import Change
from mintlang.syntax.parser import Document


def carry_model(
    previous: SemanticModel, program: Document, configuration: Document | None, controller: ControllerProfile
) -> SemanticModel | None:
    """The model of ``program``, re-parsed from ``previous``'s program, carried over; None where it cannot be."""
    change = program.change
    if change is None or not _unchanged_beside(previous, program, configuration, controller, change):
        return None
    first, after = change.first_line, change.first_line + change.old_lines
    old = previous.program.placed
    new = program.placed
    for before, now in zip(old[first:after], new[first:after], strict=True):
        if before.number != now.number or before.syntax.label != now.syntax.label:
            return None
        if line_facts(Unit.PROGRAM, before) != line_facts(Unit.PROGRAM, now):
            return None
    structure = previous.structures[Unit.PROGRAM]
    diagnostics = tuple(map(change.diagnostic, structure.diagnostics))
    if None in diagnostics:
        return None
    structures = dict(previous.structures)
    structures[Unit.PROGRAM] = Structure(structure.blocks, diagnostics)  # type: ignore[arg-type]
    return SemanticModel(program, configuration, controller, structures, change)


def _unchanged_beside(
    previous: SemanticModel,
    program: Document,
    configuration: Document | None,
    controller: ControllerProfile,
    change: Change,
) -> bool:
    """Nothing the edit did reaches beyond the lines it touched."""
    before = previous.program
    if previous.controller != controller or len(before.source) != change.previous_length:
        return False
    configured = previous.configuration
    if (configured.source if configured else None) != (configuration.source if configuration else None):
        return False
    if change.line_shift or change.old_lines != change.new_lines or change.reaches_end:
        return False
    old_text = before.source[change.start : change.old_end]
    new_text = program.source[change.start : change.new_end]
    if old_text.count("\r\n") != new_text.count("\r\n"):
        return False  # fixes write the line breaks the file uses
    return not any(
        change.start <= expansion.span.start < end
        for document, end in ((before, change.old_end), (program, change.new_end))
        for expansion in document.expansions
    )
