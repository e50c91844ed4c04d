"""In a Mint v3 file, hover and signature help give a keyword's formats as the v3 guide prints them, not as the
v4 guide does: v3's AUXDAC is one output, ``AUXDAC = <expr>`` (001:5927-5931), where v4's addresses a channel,
``AUXDAC.channel = <expression>`` (000:6668)."""

from __future__ import annotations

from mintlang.keyworddb import database
from mintlang.lsp.features.hover import hover_text
from mintlang.lsp.features.signature import signature_help
from mintlang.lsp.workspace import Analyses, Settings

V3 = Settings.from_options({"dialect": "v3"})


def test_the_database_keeps_the_v3_formats() -> None:
    assert database().v3_keywords["AUXDAC"].formats == ("AUXDAC = <expr>", "v = AUXDAC")  # 001:5929-5931
    # 001:11207-11208, under a Format heading without its colon (001:11204)
    assert database().v3_keywords["RAMP"].formats == ("RAMP[axes] = <expression> {,<expression> ...}", "v = RAMP[axis]")


def test_hover_shows_the_v3_formats() -> None:
    analyses = Analyses(read=lambda _: None, settings=V3)
    shown = hover_text(analyses.snapshot("file:///old.mnt", "AUXDAC = 50\n", 1), 1)
    assert shown is not None
    assert "```mint\nAUXDAC = <expr>\nv = AUXDAC\n```" in shown[0]


def test_signature_help_shows_the_v3_formats() -> None:
    found = signature_help("AUXDAC = ", V3)
    assert found is not None
    assert [signature.label for signature in found.signatures] == ["AUXDAC = <expr>", "v = AUXDAC"]


def test_signature_help_knows_a_keyword_only_v3_has() -> None:
    found = signature_help("CURRLIMIT = ", V3)  # 001:7068-7069; v4 has no CURRLIMIT
    assert found is not None
    assert found.signatures[0].label == "CURRLIMIT[axes] = <expression> {,<expression> ...}"
