"""The parsers' LALR tables and the lark runtime that reads them, made with the installed lark.

``mint`` parses with ``lark_runtime.py``, lark's own stand-alone parser (what
``python -m lark.tools.standalone`` writes: lark's LALR parser, lexer interface and
trees, without its grammar compiler, Earley parsers, caches and logging), over tables
computed here from ``grammar.lark``. Importing lark itself and loading its
tables took a fifth of a one-line ``mint check``; ``python -m tools.lalr_tables``
writes both files again after grammar.lark changes or lark is upgraded, and
``tests/core/test_shipped_parser_tables.py`` fails until it is run.
"""

from __future__ import annotations

import io
import marshal
from collections.abc import Iterator
from typing import Any

import lark
from lark import Lark
from lark.grammar import Rule
from lark.lexer import Lexer, TerminalDef
from lark.tools.standalone import gen_standalone

from mintlang.dialect import Dialect
from mintlang.syntax.grammars import grammar_text

Serialized = dict[str, Any]


class _PresetTokens(Lexer):
    """Hands lark the tokens our own lexer made, as ``grammar._PresetTokens`` hands them to the runtime,
    whose class the runtime's parser is given when it loads the tables (they depend on the terminals only)."""

    def __init__(self, lexer_conf: object) -> None:  # lark's Lexer interface
        del lexer_conf

    def lex(self, data: list[lark.Token]) -> Iterator[lark.Token]:  # type: ignore[override]
        return iter(data)


def build_parser(dialect: Dialect) -> Lark:
    """lark's parser made from the grammar, reading the tokens our lexer made (its LALR tables take a tenth
    of a second to compute)."""
    # strict: a shift/reduce conflict is an error, not resolved silently. propagate_positions gives
    # every subtree the positions of its first and last token, which here are token indices:
    # computed once per cached tree, they make node spans O(1).
    return Lark(grammar_text(dialect), parser="lalr", lexer=_PresetTokens, strict=True, propagate_positions=True)


def computed(dialect: Dialect) -> Serialized:
    """lark's serialization of the parser of ``dialect`` (what ``Lark.save`` pickles), with the class of
    its lexer left out: ``grammar.load_parser`` gives the runtime its own. Each state of the parse table
    is marshalled apart, so that a start reads only those its lines visit (``grammar._StatesDecodedOnUse``):
    reading and decoding all 359 was a third of loading the tables."""
    data, memo = build_parser(dialect).memo_serialize([TerminalDef, Rule])
    data["options"] = {name: value for name, value in data["options"].items() if name != "lexer"}
    del data["parser"]["lexer_conf"]["lexer_type"]
    table = data["parser"]["parser"]
    table["states"] = {state: marshal.dumps(actions) for state, actions in table["states"].items()}
    return {"data": data, "memo": memo}


# lark's logger, which its module sets to CRITICAL and which lark never logs at: every message is dropped.
_LARK_LOGGER = """import logging
from dataclasses import dataclass
from typing import Generic, AnyStr

logger: logging.Logger = logging.getLogger("lark")
logger.addHandler(logging.StreamHandler())
##

##

logger.setLevel(logging.CRITICAL)
"""
_SILENT_LOGGER = """from dataclasses import dataclass
from typing import Generic, AnyStr


class _SilentLogger:
    def _drop(self, *args: Any, **kwargs: Any) -> None:
        pass

    debug = info = warning = exception = _drop


logger = _SilentLogger()
"""

# Serialize.deserialize builds its class's namespace before it looks for a reference to an object already
# made; the parse table's 2,589 reduce actions are such references (to their rules).
_NAMESPACE_FIRST = """        namespace = getattr(cls, '__serialize_namespace__', [])
        namespace = {c.__name__:c for c in namespace}

        fields = getattr(cls, '__serialize_fields__')

        if '@' in data:
            return memo[data['@']]
"""
_REFERENCE_FIRST = """        if '@' in data:
            return memo[data['@']]

        namespace = getattr(cls, '__serialize_namespace__', [])
        namespace = {c.__name__:c for c in namespace}

        fields = getattr(cls, '__serialize_fields__')
"""

# The generated module's first statement, before which the future import goes.
_VERSION = "\n__version__ = "
_LAZY_ANNOTATIONS = "\nfrom __future__ import annotations\n"


def runtime_source() -> str:
    """lark's stand-alone parser module as the installed lark's generator writes it, up to its tables,
    with a logger that drops every message in place of lark's.

    The tables section begins with ``import pickle, zlib, base64``, which only its own tables need:
    ``grammar.load_parser`` gives the runtime its tables as data, so it never reads a pickle
    (``Lark.save`` and ``Lark.load`` of a file are the parts of the runtime left without it).
    lark's logger is set to CRITICAL and lark logs nothing at that level, so its messages are dropped
    without importing ``logging``, a twentieth of a one-line ``mint check``. A reference to an object
    already deserialized is looked up before anything else is done (``_REFERENCE_FIRST``). Its annotations
    are left unevaluated (``from __future__ import annotations``): nothing reads them, and building their
    ``typing`` forms (``Optional[...]``, ``Dict[str, Any]``) at each definition was a quarter of the
    module's import.
    """
    generated = io.StringIO()
    gen_standalone(build_parser(Dialect.V4), out=generated)
    code, found, _ = generated.getvalue().partition("\nimport pickle, zlib, base64\nDATA = (\n")
    assert found, "lark's stand-alone generator no longer begins its tables with import pickle, zlib, base64"
    assert code.count(_LARK_LOGGER) == 1, "lark's stand-alone generator no longer sets up its logger as it did"
    assert code.count(_NAMESPACE_FIRST) == 1, "lark's Serialize.deserialize no longer begins as it did"
    assert code.count(_VERSION) == 1, "lark's stand-alone generator no longer begins with its version"
    code = code.replace(_VERSION, _LAZY_ANNOTATIONS + _VERSION)
    return code.replace(_LARK_LOGGER, _SILENT_LOGGER).replace(_NAMESPACE_FIRST, _REFERENCE_FIRST) + "\n"
