"""The lexer, parser and analyser never raise, whatever they are given.

A Mint user's file can be anything: a half-typed line in the editor, a binary
file opened by mistake, a generated program with a megabyte on one line.
Every run must end with diagnostics whose ranges lie inside the source.
CI runs three thousand generated cases; ``MINT_FUZZ_SCALE=10`` runs more.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mintlang
from mintlang.source import decode
from tests.core.test_lossless_round_trip import MINT_FRAGMENTS
from tests.fuzzing import examples

CONTROLLERS = ["nextmove-pci", "nextmove-pc", "nextmove-bx", "mintdrive", "servonode51"]


def _check_everything(source: str, dialect: str = "v4", controller: str = "nextmove-pci") -> None:
    analysis = mintlang.check_application(source, dialect=dialect, controller=controller, config=source)
    for diagnostic in (*analysis.program, *analysis.configuration):
        assert 0 <= diagnostic.span.start <= diagnostic.span.end <= len(source)
        for fix in diagnostic.fixes:
            for edit in fix.edits:
                assert 0 <= edit.span.start <= edit.span.end <= len(source)


@settings(max_examples=examples(2000))
@given(st.lists(MINT_FRAGMENTS, max_size=60).map("".join), st.sampled_from(CONTROLLERS))
def test_mint_like_input_never_raises(source: str, controller: str) -> None:
    _check_everything(source, "v4", controller)
    _check_everything(source, "v3", controller)


@settings(max_examples=examples(500))
@given(st.binary(max_size=2000))
def test_binary_junk_never_raises(data: bytes) -> None:
    _check_everything(decode(data)[0])


@settings(max_examples=examples(500))
@given(st.text(max_size=300))
def test_arbitrary_text_never_raises(source: str) -> None:
    _check_everything(source)


@pytest.mark.parametrize(
    "source",
    [
        "a = " + "1+" * 500_000 + "1\n",  # a megabyte on one line
        "a = " + "(" * 3000 + "1" + ")" * 3000 + "\n",
        "a = " + "-" * 3000 + "1\n",
        "IF " + " AND ".join(["IN1"] * 3000) + " THEN GO\n",
        "FOR a = 1 TO 2\n" * 300 + "NEXT\n" * 300,
        "#x\n" * 400 + "GOSUB x\n",
        "\x00\x01\x02" * 1000,
    ],
    ids=["1MB line", "deep brackets", "unary chain", "long condition", "deep FOR", "many labels", "control bytes"],
)
def test_extreme_input_gives_diagnostics_not_exceptions(source: str) -> None:
    _check_everything(source)


def test_a_dot_parameter_written_as_an_invalid_binary_number_is_a_syntax_error() -> None:
    # found by the fuzz test: "05" after a dot was taken as a number without checking it
    assert [d.code for d in mintlang.check("SPEED..05 = 1\n")] == ["E2003"]
