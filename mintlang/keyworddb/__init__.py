"""The Mint keyword database: typed records generated from the manuals."""

from mintlang.keyworddb.load import KeywordDatabase, database

__all__ = ["KeywordDatabase", "database"]
