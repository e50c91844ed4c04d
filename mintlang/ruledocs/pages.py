"""The files of ``docs/rules/``: one page a code, and an index by group (``python -m tools.rule_pages``)."""

from __future__ import annotations

from mintlang.ruledocs.catalogue import GROUPS
from mintlang.ruledocs.render import markdown

INDEX = "README.md"


def pages() -> dict[str, str]:
    """File name -> text, for every documented code and the index."""
    found = {f"{rule.code}.md": markdown(rule, group.name) for group in GROUPS for rule in group.rules}
    return {INDEX: index(), **found}


def index() -> str:
    """The list of codes, group by group, each linked to its page."""
    parts = [
        "# Rules of `mint check`",
        "Generated from `mintlang/ruledocs` by `python -m tools.rule_pages`: edit the catalogue, not "
        "these pages. `mint rule CODE` shows the same text. Errors (E) carry the controller's own "
        "numbers; warnings (W) and hints (I) are the toolchain's. The hints are reported only when "
        "selected (`--select I`).",
    ]
    for group in GROUPS:
        rows = "\n".join(f"| [{rule.code}]({rule.code}.md) | {rule.title} | {rule.severity} |" for rule in group.rules)
        parts += [f"## {group.name}", group.summary, f"| Code | Title | Reported as |\n|---|---|---|\n{rows}"]
    return "\n\n".join(parts) + "\n"
