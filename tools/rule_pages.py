"""Write ``docs/rules/``, one page a code and an index, from the catalogue in ``mintlang/ruledocs``.

``python -m tools.rule_pages`` rewrites the pages and removes those of codes no longer
documented; run it after changing the catalogue. A test fails while the committed pages
differ from what the catalogue gives.
"""

from __future__ import annotations

from pathlib import Path

from mintlang.ruledocs.pages import pages

DOCS = Path(__file__).resolve().parents[1] / "docs" / "rules"


def main() -> None:
    DOCS.mkdir(parents=True, exist_ok=True)
    wanted = pages()
    for stale in sorted({path.name for path in DOCS.glob("*.md")} - wanted.keys()):
        (DOCS / stale).unlink()
        print(f"removed {DOCS / stale}")
    for name, text in wanted.items():
        (DOCS / name).write_text(text, encoding="utf-8")
    print(f"wrote {len(wanted)} pages in {DOCS}")


if __name__ == "__main__":
    main()
