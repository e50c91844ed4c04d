"""What the rules read: the semantic model and its syntax index.

The index is built once with the model (``mintlang.semantic.index``); the
rules only filter it.
"""

from __future__ import annotations

from dataclasses import dataclass

from mintlang.semantic.index import KeywordUse, NameUse, Use
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

__all__ = ["Facts", "KeywordUse", "Use", "gather"]


@dataclass(frozen=True, slots=True)
class Facts:
    """The model and the parts of its index the rules ask for."""

    model: SemanticModel
    statements: tuple[tuple[Unit, n.Line, n.Statement], ...]
    keyword_uses: tuple[KeywordUse, ...]
    elements: tuple[tuple[Unit, n.ElementRef], ...]
    names: tuple[tuple[Unit, n.Name], ...]  # user words written, read, or standing alone


def gather(model: SemanticModel) -> Facts:
    index = model.index
    names = tuple((event.unit, event.name) for event in index.names if event.use is not NameUse.DECLARE)
    return Facts(model, index.statements, index.keyword_uses, index.elements, names)
