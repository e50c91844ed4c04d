"""mintlang: the language core of the Mint toolchain.

One parser and one semantic model, shared by ``mint check``, the migrator,
the language server and the runtime::

    import mintlang
    document = mintlang.parse(source)                 # lossless: tokens join back to source
    diagnostics = mintlang.check(source, controller="nextmove-bx")
"""

from __future__ import annotations

from typing import TYPE_CHECKING

__version__ = "0.1.0"  # the distribution's (pyproject.toml reads it here)

from mintlang.allocation import without_collector
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from collections.abc import Mapping

    from mintlang.analysis.analyser import Analysis, analyse
    from mintlang.diagnostics import Diagnostic, Edit, Fix, LineIndex, Position, Severity, Span
    from mintlang.semantic.model import SemanticModel, build_model
    from mintlang.syntax.lines import MacroDefinition
    from mintlang.syntax.parser import Document, parse

__all__ = [
    "Analysis",
    "Controller",
    "Diagnostic",
    "Dialect",
    "Document",
    "Edit",
    "Fix",
    "LineIndex",
    "Position",
    "SemanticModel",
    "Severity",
    "Span",
    "analyse",
    "build_model",
    "check",
    "check_application",
    "clear_caches",
    "parse",
]


def clear_caches() -> None:
    """Forget every line lexed, parsed, indexed and checked: the next check runs as in a fresh process."""
    from mintlang.analysis.analyser import clear_cache as clear_findings_cache  # noqa: PLC0415 - see import_when_used
    from mintlang.semantic.index import clear_cache as clear_index_cache  # noqa: PLC0415
    from mintlang.syntax.parser import clear_caches as clear_syntax_caches  # noqa: PLC0415

    clear_syntax_caches()
    clear_index_cache()
    clear_findings_cache()


@without_collector  # one pause for the three steps: each would otherwise end with a collection of the last
def check_application(
    source: str,
    *,
    dialect: Dialect | str = Dialect.V4,
    controller: Controller | str = Controller.NEXTMOVE_PCI,
    config: str | None = None,
    select: tuple[str, ...] | None = None,
    ignore: tuple[str, ...] = (),
    config_ignore: tuple[str, ...] | None = None,
    previous: Analysis | None = None,
    suppressions: bool = True,
) -> Analysis:
    """Parse and analyse a program with its optional configuration file; diagnostics per file.

    ``select`` and ``ignore`` take codes or their prefixes; without ``select`` the errors and
    warnings are reported and the hints (I…) are not. ``config_ignore`` is the configuration
    file's own ``ignore`` (None: the program's). ``previous`` is the analysis of an
    earlier version of the same application (the language server's, before a keystroke):
    what the edit did not change is read from it, and the result is the same as without it.
    ``suppressions`` False leaves the ``mint: ignore`` comments unread, as the controller's compiler does."""
    from mintlang.analysis.analyser import analyse  # noqa: PLC0415 - see import_when_used
    from mintlang.controllers import profile  # noqa: PLC0415
    from mintlang.semantic.carry import carry_model  # noqa: PLC0415
    from mintlang.semantic.model import build_model  # noqa: PLC0415
    from mintlang.syntax.parser import parse  # noqa: PLC0415
    from mintlang.syntax.reparse import reparse  # noqa: PLC0415

    def read(text: str, before: Document | None, macros: Mapping[str, MacroDefinition] | None) -> Document:
        if before is None:
            return parse(text, dialect, macros=macros, controller=controller)
        return reparse(before, text, dialect, macros=macros, controller=controller)

    before = previous.model if previous is not None else None
    configuration = None
    if config is not None:
        configuration = read(config, before.configuration if before else None, None)
    program = read(source, before.program if before else None, configuration.macros if configuration else None)
    model = carry_model(before, program, configuration, profile(controller)) if before is not None else None
    if model is None:
        model, previous = build_model(program, configuration, controller), None
    return analyse(
        model, select=select, ignore=ignore, config_ignore=config_ignore, previous=previous, suppressions=suppressions
    )


def check(
    source: str,
    *,
    dialect: Dialect | str = Dialect.V4,
    controller: Controller | str = Controller.NEXTMOVE_PCI,
    config: str | None = None,
) -> list[Diagnostic]:
    """The diagnostics of a program (those of its configuration file are not included)."""
    return list(check_application(source, dialect=dialect, controller=controller, config=config).program)


# The public names this module does not define are imported when first used, so a tool that
# imports one submodule (``mint --version`` imports ``mintlang.cli``) does not pay for the parser,
# the rules and the keyword database.
import_when_used(
    __name__,
    {
        "Analysis": "mintlang.analysis.analyser",
        "analyse": "mintlang.analysis.analyser",
        "Diagnostic": "mintlang.diagnostics",
        "Edit": "mintlang.diagnostics",
        "Fix": "mintlang.diagnostics",
        "LineIndex": "mintlang.diagnostics",
        "Position": "mintlang.diagnostics",
        "Severity": "mintlang.diagnostics",
        "Span": "mintlang.diagnostics",
        "SemanticModel": "mintlang.semantic.model",
        "build_model": "mintlang.semantic.model",
        "Document": "mintlang.syntax.parser",
        "parse": "mintlang.syntax.parser",
    },
)
