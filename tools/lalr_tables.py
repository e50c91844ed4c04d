"""Compute the parsers' LALR tables and write them into the package: run after changing grammar.lark.

``python -m tools.lalr_tables`` writes ``mintlang/syntax/lalr_v4.bin`` and
``lalr_v3.bin`` (MintMT is read with the v4 grammar): a line naming the grammar and lark they were made from, then
lark's own serialization. ``mint check`` loads them instead of computing the
tables at every start; a test fails when they no longer match the grammar.
"""

from __future__ import annotations

from pathlib import Path

from mintlang.dialect import Dialect
from mintlang.syntax.grammar import build_parser, fingerprint, grammar_of

SYNTAX = Path(__file__).resolve().parents[1] / "mintlang" / "syntax"


def main() -> None:
    for dialect in sorted({grammar_of(dialect) for dialect in Dialect}):
        path = SYNTAX / f"lalr_{dialect.value}.bin"
        with path.open("wb") as stream:
            stream.write(f"{fingerprint(dialect)}\n".encode("ascii"))
            build_parser(dialect).save(stream)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
