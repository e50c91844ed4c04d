"""A diagnostic together with the file of the application it concerns."""

from __future__ import annotations

from mintlang.codes import mint_error, own
from mintlang.diagnostics import Diagnostic
from mintlang.records import record
from mintlang.semantic.symbols import Unit

__all__ = ["Finding", "mint_error", "own"]


@record
class Finding:
    unit: Unit
    diagnostic: Diagnostic
