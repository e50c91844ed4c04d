"""The hint for a missing extra names where this mintlang came from (issue 17, item 12).

``pip install 'mintlang[plot]'`` asks a package index; an installation from a
checkout must be pointed back at its checkout. ``direct_url.json`` texts below are
written as pip records them (PEP 610).
"""

from __future__ import annotations

import json
from pathlib import Path

from mintlang.extras import install_command, this_installation

ROOT = Path(__file__).resolve().parents[2]


def test_an_editable_install_is_told_to_reinstall_its_checkout_with_the_extra() -> None:
    recorded = json.dumps({"url": "file:///home/ana/mint%20tools", "dir_info": {"editable": True}})
    assert install_command("plot", recorded) == "pip install -e '/home/ana/mint tools[plot]'"


def test_an_install_from_a_folder_is_told_to_install_that_folder_with_the_extra() -> None:
    recorded = json.dumps({"url": "file:///srv/mintlang", "dir_info": {}})
    assert install_command("plot", recorded) == "pip install '/srv/mintlang[plot]'"


def test_an_install_from_an_archive_names_the_archive() -> None:
    url = "https://example.invalid/mintlang-0.1.0.tar.gz"
    recorded = json.dumps({"url": url, "archive_info": {}})
    assert install_command("plot", recorded) == f"pip install 'mintlang[plot] @ {url}'"


def test_this_checkout_is_named_by_the_hint_of_the_installation_the_tests_run() -> None:
    # the tests run from a checkout (CI installs it with pip install -e .)
    hint = this_installation("plot")
    assert hint.endswith(f"'{ROOT}[plot]'")
