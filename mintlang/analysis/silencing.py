"""Silencing every finding of a text with suppression comments: ``mint check --add-ignore``, ruff's ``--add-noqa``.

A program that has run on its machines for years is adopted by the checker as it stands: each line's findings
get one ``REM mint: ignore[...]`` comment (``suppression_fix``, the editor's "Ignore" quick fix, with every code
of the line), so that only new findings are reported from then on. The comment never makes a line longer than
the controller reads (``longest_line``), nor goes where it would not be a comment (v3's ``PROTECT abc``): such a
line keeps its findings. Unused suppressions (W117) are not silenced but removed by their own fix.
"""

from __future__ import annotations

from collections.abc import Sequence

from mintlang.analysis.rules.line_length import longest_line
from mintlang.analysis.suppression import UNUSED_SUPPRESSION, suppression_fix
from mintlang.diagnostics import Diagnostic, Edit, with_edits
from mintlang.records import record
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax.parser import Document


@record
class Silenced:
    """A text with the comments added; the findings they silence, and those left where none could go, placed in the
    new text."""

    text: str
    silenced: tuple[Diagnostic, ...]
    left: tuple[Diagnostic, ...]


def silence(model: SemanticModel, diagnostics: Sequence[Diagnostic], unit: Unit = Unit.PROGRAM) -> Silenced:
    """The text of ``unit`` (the program, or the configuration file) with each line holding ``diagnostics`` (that
    file's) given a comment naming their codes, in order."""
    document = model.document(unit)
    limit = longest_line(model.controller, document.dialect)
    by_line: dict[int, list[Diagnostic]] = {}
    left: list[Diagnostic] = []
    for diagnostic in diagnostics:
        if diagnostic.code == UNUSED_SUPPRESSION:
            left.append(diagnostic)
        else:
            by_line.setdefault(document.physical_between(diagnostic.span.start, diagnostic.span.start)[0], []).append(
                diagnostic
            )
    edits, silenced = [], []
    for index, found in by_line.items():
        codes = ", ".join(sorted({diagnostic.code for diagnostic in found}))
        fix = suppression_fix(document, found[0].span.start, codes)
        if fix is None or _longer(document, index, fix.edits) > limit:
            left.extend(found)
        else:
            edits.extend(fix.edits)
            silenced.extend(found)
    return Silenced(with_edits(document.source, edits), tuple(silenced), tuple(_placed(left, edits)))


def _placed(diagnostics: Sequence[Diagnostic], edits: Sequence[Edit]) -> list[Diagnostic]:
    """``diagnostics`` moved on by what the comments added before them grew the text."""
    return [
        diagnostic.shifted(
            sum(
                len(edit.text) - (edit.span.end - edit.span.start)
                for edit in edits
                if edit.span.end <= diagnostic.span.start
            )
        )
        for diagnostic in diagnostics
    ]


def _longer(document: Document, index: int, edits: Sequence[Edit]) -> int:
    """How long line ``index`` is once ``edits`` are made on it."""
    grown = sum(len(edit.text) - (edit.span.end - edit.span.start) for edit in edits)
    return document.physical.lexed(index).content_end + grown
