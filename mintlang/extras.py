"""How to add an optional extra (``plot``) to this installation of mintlang.

mintlang is installed from a checkout (``pip install -e .``) as often as from a
package index, and ``pip install 'mintlang[plot]'`` asks an index for a
distribution it may not have. pip records where a distribution came from in
``direct_url.json`` (PEP 610); the hint names that place.
"""

from __future__ import annotations

import json
from importlib.metadata import PackageNotFoundError, distribution
from pathlib import Path
from urllib.parse import unquote, urlparse

_CHECKOUT = Path(__file__).resolve().parents[1]  # the folder holding pyproject.toml when run from a source tree


def install_command(extra: str, direct_url: str | None) -> str:
    """The pip command that adds ``extra``, for an installation whose ``direct_url.json`` text is ``direct_url``.

    None means installed from an index (or not installed: then from this checkout, if it is one).
    """
    if direct_url is None:
        if (_CHECKOUT / "pyproject.toml").is_file():
            return f"pip install -e '{_CHECKOUT}[{extra}]'"
        return f"pip install 'mintlang[{extra}]'"
    origin = json.loads(direct_url)
    url = origin.get("url", "")
    parsed = urlparse(url)
    if parsed.scheme == "file" and "dir_info" in origin:
        folder = unquote(parsed.path)
        editable = origin["dir_info"].get("editable", False)
        return f"pip install {'-e ' if editable else ''}'{folder}[{extra}]'"
    return f"pip install 'mintlang[{extra}] @ {url}'"


def this_installation(extra: str) -> str:
    """``install_command`` for the mintlang this process runs."""
    try:
        recorded = distribution("mintlang").read_text("direct_url.json")
    except PackageNotFoundError:
        recorded = None
    return install_command(extra, recorded)
