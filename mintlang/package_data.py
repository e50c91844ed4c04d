"""Data files shipped inside the package (the keyword database, the grammar, its parser tables).

Read by the loader that imported the package, through ``get_data`` (what ``pkgutil.get_data``
does), which reads a package installed as files or from a zip archive alike.
``importlib.resources`` would do the same, but importing it imports ``tempfile``, ``shutil``
and ``zipfile``: a twentieth of the start-up of a one-line ``mint check``.
"""

from __future__ import annotations

import os
import sys


def read_bytes(package: str, *parts: str) -> bytes:
    """The file at ``parts`` (a path relative to the folder of ``package``, an imported package)."""
    spec = sys.modules[package].__spec__
    assert spec is not None and spec.origin is not None and spec.loader is not None, f"{package} is not a package"
    return spec.loader.get_data(os.path.join(os.path.dirname(spec.origin), *parts))  # type: ignore[attr-defined,no-any-return]


def read_text(package: str, *parts: str) -> str:
    """``read_bytes`` decoded as UTF-8."""
    return read_bytes(package, *parts).decode("utf-8")
