"""Generator of ``mintlang/keyworddb/data``: reads the Mint manuals and writes the keyword database.

Run ``python -m tools.keyworddb`` from the repository root; ``--check`` only compares.
"""
