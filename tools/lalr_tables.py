"""Write the parsers' LALR tables and lark's stand-alone runtime into the package: run after changing
grammar.lark or upgrading lark.

``python -m tools.lalr_tables`` writes ``mintlang/syntax/lalr_v4.bin`` and ``lalr_v3.bin`` (MintMT
is read with the v4 grammar), each the grammar it was computed from, the lark version and lark's
serialization of the parser, and ``mintlang/syntax/lark_runtime.py``, lark's stand-alone parser
(``mintlang/syntax/tables.py`` says why). ``mint check`` loads them instead of importing lark and
computing the tables at every start; a test fails when they no longer match the grammar or lark.
"""

from __future__ import annotations

import marshal
from pathlib import Path

import lark

from mintlang.dialect import Dialect
from mintlang.syntax.grammars import grammar_of, grammar_text
from mintlang.syntax.tables import computed, runtime_source

SYNTAX = Path(__file__).resolve().parents[1] / "mintlang" / "syntax"


def main() -> None:
    runtime = SYNTAX / "lark_runtime.py"
    runtime.write_text(runtime_source(), encoding="utf-8")
    print(f"wrote {runtime}")
    for dialect in sorted({grammar_of(dialect) for dialect in Dialect}):
        path = SYNTAX / f"lalr_{dialect.value}.bin"
        tables = {"grammar": grammar_text(dialect), "lark": lark.__version__, "parser": computed(dialect)}
        path.write_bytes(marshal.dumps(tables))  # plain data: read without importing pickle
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
