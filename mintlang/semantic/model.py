"""The semantic model of an application: configuration file plus program file.

Built once per check and shared by every tool: the analyser's rules, the
language server's navigation and the runtime's compiler all read the same
symbol table and block structure, so no tool re-derives them.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass

from mintlang.allocation import without_collector
from mintlang.controllers import ControllerProfile, profile
from mintlang.keyworddb.model import Controller
from mintlang.semantic.blocks import Structure, match_blocks
from mintlang.semantic.index import SyntaxIndex, index_syntax
from mintlang.semantic.symbols import SymbolTable, Unit, build_symbols
from mintlang.syntax.parser import Document


@dataclass(frozen=True, slots=True)
class SemanticModel:
    program: Document
    configuration: Document | None
    controller: ControllerProfile
    symbols: SymbolTable
    structures: Mapping[Unit, Structure]
    index: SyntaxIndex  # every statement, keyword use, element and name, in compile order

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
    structures = {Unit.PROGRAM: match_blocks(program.lines, target)}
    if configuration is not None:
        structures[Unit.CONFIGURATION] = match_blocks(configuration.lines, target)
    documents = [(Unit.CONFIGURATION, configuration)] if configuration is not None else []
    index = index_syntax([*documents, (Unit.PROGRAM, program)])
    symbols = build_symbols(program, configuration, index)
    return SemanticModel(program, configuration, target, symbols, structures, index)
