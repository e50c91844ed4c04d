"""Every code the checker can emit, read from its source: the calls that make a diagnostic.

A call with a literal code (``mint_error(3001, …)``, ``own("W103", …)``), or with a name the
module gives one, names it; a call whose code is a variable is one of the few places listed in
``_TABLES``, which say where that variable's values come from. A new such place fails
``emitted_codes`` until it is listed, so a code cannot appear without the documentation test
noticing.
"""

from __future__ import annotations

import ast
from pathlib import Path

from mintlang import terminals
from mintlang.analysis.rules import addressing, function_domains, keyword_usage, limits
from mintlang.keyworddb import usage
from mintlang.semantic import blocks

CORE = Path(blocks.__file__).parents[1]
_MAKERS = frozenset({"mint_error", "_error", "own"})


def _literals_returned(function: ast.FunctionDef, place: int) -> set[int]:
    """The literals at ``place`` of the tuples ``function`` returns (``return 2006, "…"``: 2006 at 0)."""
    return {
        node.value.elts[place].value
        for node in ast.walk(function)
        if isinstance(node, ast.Return)
        and isinstance(node.value, ast.Tuple)
        and isinstance(node.value.elts[place], ast.Constant)
    }


def _function(module: object, name: str) -> ast.FunctionDef:
    tree = ast.parse(Path(module.__file__).read_text())  # type: ignore[attr-defined]
    return next(node for node in ast.walk(tree) if isinstance(node, ast.FunctionDef) and node.name == name)


def _refusals() -> set[int]:
    """The codes ``mintlang.keyworddb.usage`` refuses a use of a keyword with (``Refusal(2000, …)``), which the
    keyword-usage rule reports."""
    tree = ast.parse(Path(usage.__file__).read_text())
    return {
        call.args[0].value
        for call in ast.walk(tree)
        if isinstance(call, ast.Call)
        and getattr(call.func, "id", "") == "Refusal"
        and isinstance(call.args[0], ast.Constant)
    }


def _over_limits() -> set[int]:
    """The codes ``limits.check`` hands ``_over`` (its third argument)."""
    calls = ast.walk(_function(limits, "check"))
    return {
        call.args[2].value
        for call in calls
        if isinstance(call, ast.Call)
        and getattr(call.func, "id", "") == "_over"
        and isinstance(call.args[2], ast.Constant)
    }


# (module file, function holding the call) -> the codes its variable can hold, read from where they are made
_TABLES = {
    ("semantic/blocks.py", "close"): {code for _, code, *_ in blocks._CLOSERS.values()} | {2013},
    ("semantic/blocks.py", "finish"): {code for _, code in blocks._CLOSING.values()},
    ("analysis/rules/addressing.py", "_channel"): {code for *_, code in addressing._CHANNEL_FAMILIES}
    | _literals_returned(_function(addressing, "_channel_family"), -1),
    ("analysis/rules/addressing.py", "_terminal"): _literals_returned(_function(terminals, "serial_port_error"), 0),
    ("analysis/rules/keyword_usage.py", "each_line"): _literals_returned(_function(keyword_usage, "_verdict"), 0)
    | _refusals(),
    ("analysis/rules/limits.py", "_over"): _over_limits(),
    ("analysis/rules/function_domains.py", "each_line"): _literals_returned(
        _function(function_domains, "_without_value"), 0
    ),
}


def _module_constants(tree: ast.Module) -> dict[str, int | str]:
    """The module's names given a literal code (``UNUSED_SUPPRESSION = "W117"``)."""
    return {
        target.id: statement.value.value
        for statement in tree.body
        if isinstance(statement, ast.Assign) and isinstance(statement.value, ast.Constant)
        for target in statement.targets
        if isinstance(target, ast.Name) and isinstance(statement.value.value, int | str)
    }


class _Calls(ast.NodeVisitor):
    """The calls that make a diagnostic, each with the innermost function holding it."""

    def __init__(self) -> None:
        self.functions: list[str] = ["<module>"]
        self.found: list[tuple[str, ast.expr]] = []

    def visit_FunctionDef(self, node: ast.FunctionDef) -> None:
        self.functions.append(node.name)
        self.generic_visit(node)
        self.functions.pop()

    def visit_Call(self, node: ast.Call) -> None:
        if getattr(node.func, "id", "") in _MAKERS and node.args:
            self.found.append((self.functions[-1], node.args[0]))
        self.generic_visit(node)


def emitted_codes() -> set[int | str]:
    """The controller's error numbers (int) and the toolchain's own codes (str) the checker can report."""
    found: set[int | str] = set()
    for path in sorted(CORE.rglob("*.py")):
        if path.name == "codes.py":  # where the makers are defined
            continue
        tree = ast.parse(path.read_text())
        constants = _module_constants(tree)
        calls = _Calls()
        calls.visit(tree)
        for function, code in calls.found:
            if isinstance(code, ast.Constant):
                found.add(code.value)
                continue
            if isinstance(code, ast.Name) and code.id in constants:
                found.add(constants[code.id])
                continue
            place = (path.relative_to(CORE).as_posix(), function)
            assert place in _TABLES, f"{place}: a diagnostic whose code is a variable; list its values in _TABLES"
            found |= _TABLES[place]
    return found
