"""The committed JSON is exactly what the generator makes from the manuals."""

from __future__ import annotations

from pathlib import Path

import pytest

from tools.keyworddb.__main__ import DEFAULT_SEEDS, DEFAULT_SPEC, main
from tools.keyworddb.build import build
from tools.keyworddb.seeds import V4_GUIDE
from tools.keyworddb.summaries import SUMMARIES
from tools.keyworddb.write import render

pytestmark = pytest.mark.skipif(
    not DEFAULT_SEEDS.is_dir() or not DEFAULT_SPEC.is_dir(),
    reason=f"manual seeds not available at {DEFAULT_SEEDS} (needed to regenerate the keyword database)",
)


def test_committed_data_is_up_to_date() -> None:
    assert main(["--check"]) == 0, "run: python -m tools.keyworddb"


def test_generation_is_deterministic() -> None:
    first = {name: render(value) for name, value in build(DEFAULT_SEEDS, DEFAULT_SPEC).items()}
    second = {name: render(value) for name, value in build(DEFAULT_SEEDS, DEFAULT_SPEC).items()}
    assert first == second


def test_check_reports_stale_data(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("tools.keyworddb.__main__.DATA", tmp_path)
    assert main(["--check"]) == 1
    assert main([]) == 0
    assert main(["--check"]) == 0


def test_summaries_are_not_copied_from_the_guide() -> None:
    """Hover text is our own wording: no summary, nor any 7 words of one, appears in the guide."""
    guide = " ".join((DEFAULT_SEEDS / V4_GUIDE).read_text(encoding="utf-8").split()).lower()
    copied = []
    for name, summary in SUMMARIES.items():
        words = summary.rstrip(".").lower().split()
        windows = [" ".join(words[i : i + 7]) for i in range(max(1, len(words) - 6))]
        copied += [name for window in windows if window in guide][:1]
    assert copied == []
