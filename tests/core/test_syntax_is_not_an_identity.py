"""Equal lines share one syntax object, so no tool may use a syntax object to name a place.

The parser gives every line of the same text one ``LineSyntax``, statements and
expressions included, and frozen nodes compare and hash by value: a map keyed
by a node or by its ``id()`` merges equal lines (the runtime's block links once
broke every program with two ``NEXT`` lines so). The tools name a statement by
its place and find what encloses an expression with ``mintlang.syntax.parents``,
which compares nodes with ``is``: that is right only because ``Document.lines``
holds a node of its own at every place, which the last tests hold it to.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from dataclasses import fields, is_dataclass
from pathlib import Path

import pytest

import mintlang
from mintlang.diagnostics import Span
from tests.corpus_files import CorpusCase, cases

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("mintlang", "lsp", "migrate", "runtime")
REPEATED = (
    "DIM table(3) = 1, 2, 3\n"
    'x = SIN(table(1) + 2) * -3 AND (b OR c) : PRINT #1, "x"; x, HEX y : SPEED[0,1] = 10, 20;\n'
    'x = SIN(table(1) + 2) * -3 AND (b OR c) : PRINT #1, "x"; x, HEX y : SPEED[0,1] = 10, 20;\n'
    "#here\n"
    "IF x = 1 THEN MOVEA.0 = 5 : GO.0\n"
    "IF x = 1 THEN MOVEA.0 = 5 : GO.0\n"
    "FOR i = 1 TO 10 STEP 2 : NEXT\n"
    "FOR i = 1 TO 10 STEP 2 : NEXT\n"
    "GOSUB here\n"
    "GOSUB here\n"
)


def _id_calls(path: Path) -> Iterator[str]:
    for found in ast.walk(ast.parse(path.read_text("utf-8"), str(path))):
        if isinstance(found, ast.Call) and isinstance(found.func, ast.Name) and found.func.id == "id":
            yield f"{path.relative_to(ROOT)}:{found.lineno}"


# A snapshot of the simulation walks its object graph once, each object once: ``id()`` marks the
# objects walked, names no place, and walks frozen syntax without saving any of it.
_WALKS_OBJECTS = frozenset({ROOT / "runtime" / "snapshot.py"})


def test_no_module_calls_id() -> None:
    """``id()`` of a shared syntax object names every line of its text at once; nothing needs ``id()`` else."""
    modules = [path for package in PACKAGES for path in sorted((ROOT / package).rglob("*.py"))]
    calls = [call for path in modules if path not in _WALKS_OBJECTS for call in _id_calls(path)]
    assert calls == []


def _nodes(value: object) -> Iterator[object]:
    """Every node with a span inside ``value`` (spans themselves are values, not nodes)."""
    if isinstance(value, tuple) and not isinstance(value, Span):
        for item in value:
            yield from _nodes(item)
    elif is_dataclass(value) and hasattr(value, "span"):
        yield value
        for field in fields(value):
            yield from _nodes(getattr(value, field.name))


def _assert_a_node_per_place(document: mintlang.Document) -> None:
    nodes = list(_nodes(document.lines))  # kept alive while their ids are compared
    assert len({id(node) for node in nodes}) == len(nodes)


def test_equal_lines_share_their_syntax() -> None:
    """What the rest guards against: without the copy, equal lines hold the very same statements."""
    placed = mintlang.parse(REPEATED).placed
    assert placed[1].syntax is placed[2].syntax
    assert placed[1].syntax.statements[0] is placed[2].syntax.statements[0]


def test_document_lines_hold_a_node_of_their_own_at_every_place() -> None:
    _assert_a_node_per_place(mintlang.parse(REPEATED))


@pytest.mark.parametrize("case", cases("v4/valid") + cases("v3/programs"), ids=lambda case: case.name)
def test_every_corpus_program_written_twice_has_a_node_per_place(case: CorpusCase) -> None:
    source = case.source if case.source.endswith("\n") else case.source + "\n"
    _assert_a_node_per_place(mintlang.parse(source * 2, case.dialect))
