"""Where a code's page is, for the links of diagnostics (LSP ``codeDescription``, SARIF ``helpUri``).

A user may point them elsewhere (a fork, an intranet copy): ``MINT_RULES_URL`` on the
command line, ``mint.rulesUrl`` in the editor. The value is the folder of the pages, or a
template with ``{code}`` (``https://example.org/mint/{code}.html``). By default the pages
are those of the repository the distribution names (its ``Repository`` project URL), else
the ``docs/rules`` folder of a checkout; with neither there is no link.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from functools import cache
from importlib.metadata import PackageNotFoundError, metadata
from pathlib import Path

ENVIRONMENT_VARIABLE = "MINT_RULES_URL"
_CHECKOUT_PAGES = Path(__file__).resolve().parents[2] / "docs" / "rules"
_REPOSITORY_LABELS = frozenset({"repository", "source", "source code"})


@cache
def default_base() -> str | None:
    """The project's own pages: in the repository it names, else in this checkout."""
    try:
        urls = metadata("mintlang").get_all("Project-URL") or []
    except PackageNotFoundError:
        urls = []
    in_repository = pages_in_repository(urls)
    if in_repository is not None:
        return in_repository
    return _CHECKOUT_PAGES.as_uri() + "/" if _CHECKOUT_PAGES.is_dir() else None


def pages_in_repository(project_urls: Iterable[str]) -> str | None:
    """The ``docs/rules/`` folder on the default branch of the repository named among a distribution's
    ``Project-URL`` entries (``"Repository, https://…"``), if one is."""
    for entry in project_urls:
        label, _, url = entry.partition(",")
        if label.strip().lower() in _REPOSITORY_LABELS:
            return f"{url.strip().rstrip('/')}/blob/main/docs/rules/"
    return None


def configured_base() -> str | None:
    """The base the user set for the command line (``MINT_RULES_URL``), else the default."""
    return os.environ.get(ENVIRONMENT_VARIABLE) or default_base()


def rule_url(code: str, base: str | None) -> str | None:
    """The page of ``code`` under ``base`` (a folder, or a template with ``{code}``); None for a code
    without a page."""
    from mintlang.ruledocs import find  # noqa: PLC0415 - the catalogue is read only when a link is made

    if not base or find(code) is None:
        return None
    if "{code}" in base:
        return base.replace("{code}", code)
    return f"{base.rstrip('/')}/{code}.md"
