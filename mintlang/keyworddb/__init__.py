"""The Mint keyword database: typed records generated from the manuals."""

from typing import TYPE_CHECKING

from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from mintlang.keyworddb.load import KeywordDatabase, database

__all__ = ["KeywordDatabase", "database"]

# Imported when first used: the records of ``model`` (``Controller`` for a command line's choices)
# come without the loader and its JSON.
import_when_used(__name__, dict.fromkeys(__all__, "mintlang.keyworddb.load"))
