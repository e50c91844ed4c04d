"""The semantic model of an application: configuration file plus program file.

Built once per check and shared by every tool: the analyser's rules, the
language server's navigation and the runtime's compiler all read the same
symbol table and block structure, so no tool re-derives them. After an edit
that changed no line's meaning (a comment, spaces after the last statement)
it is carried over from the previous model (``mintlang.semantic.carry``).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from functools import cached_property
from typing import TYPE_CHECKING

from mintlang.allocation import without_collector
from mintlang.controllers import ControllerProfile, profile
from mintlang.keyworddb.model import Controller
from mintlang.records import record
from mintlang.semantic.blocks import Structure, match_blocks
from mintlang.semantic.index import IndexedLines, SyntaxIndex, index_syntax
from mintlang.semantic.symbols import SymbolTable, Unit, build_symbols
from mintlang.syntax.parser import Document

if TYPE_CHECKING:
    from mintlang.semantic.carry import Carried


@record(slots=False)  # not slotted: ``index`` is computed on first use
class SemanticModel:
    """Names and blocks resolved.

    ``lines`` and ``structures`` hold the position-free syntax of each line
    (``PlacedLine.span`` places it), which the analyser reads; ``index`` the
    same facts at offsets into the files, made when a tool first asks.
    """

    program: Document
    configuration: Document | None
    controller: ControllerProfile
    structures: Mapping[Unit, Structure]
    carried: Carried | None = None  # how it was carried over from the previous version's model

    @classmethod
    def of(
        cls,
        program: Document,
        configuration: Document | None,
        controller: ControllerProfile,
        structures: Mapping[Unit, Structure],
        *,
        lines: IndexedLines | None,
        carried: Carried | None = None,
    ) -> SemanticModel:
        """A model whose ``lines`` are known already (as matching the blocks needed them); None: made when
        first read."""
        model = cls(program, configuration, controller, structures, carried)
        if lines is not None:
            model.__dict__["lines"] = lines  # what ``cached_property`` would have kept
        return model

    @cached_property
    def lines(self) -> IndexedLines:
        """Every logical line of both files, in compile order, with its index: made when first
        read, for a model carried over an edit (``carried``) that needs none to be checked."""
        return IndexedLines((unit, document.placed) for unit, document in self.documents())

    def lines_if_made(self) -> IndexedLines | None:
        """``lines`` where a pass read them already: the next version's are this one's, edited."""
        return self.__dict__.get("lines")

    @cached_property
    def symbols(self) -> SymbolTable:
        """Made when first read: an edit carried over (``carried``) needs none to be checked."""
        return build_symbols(self.program, self.configuration, self.lines)

    @cached_property
    def index(self) -> SyntaxIndex:
        """Every statement, keyword use, element and name, in compile order."""
        return index_syntax(list(self.documents()))

    def document(self, unit: Unit) -> Document:
        """The file of ``unit``: something found in the configuration means there is one."""
        if unit is Unit.CONFIGURATION:
            assert self.configuration is not None, "no configuration file was analysed"
            return self.configuration
        return self.program

    def documents(self) -> Iterator[tuple[Unit, Document]]:
        """The files in compile order: configuration first."""
        if self.configuration is not None:
            yield Unit.CONFIGURATION, self.configuration
        yield Unit.PROGRAM, self.program


@without_collector
def build_model(
    program: Document,
    configuration: Document | None = None,
    controller: Controller | str = Controller.NEXTMOVE_PCI,
) -> SemanticModel:
    """Resolve names and blocks of a program and its optional configuration file."""
    target = profile(controller)
    configured = [(Unit.CONFIGURATION, configuration)] if configuration is not None else []
    documents = [*configured, (Unit.PROGRAM, program)]  # in compile order
    lines = IndexedLines((unit, document.placed) for unit, document in documents)
    structures = {unit: match_blocks(lines.of(unit), target, program.dialect) for unit, _ in documents}
    return SemanticModel.of(program, configuration, target, structures, lines=lines)
