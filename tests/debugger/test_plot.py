"""``plot``: at each stop the run so far is drawn to an image, as ``mint-run --plot`` draws a whole run."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from tests.debugger.conftest import Debug
from tests.debugger.test_stepping import MOVING

pytestmark = pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="the plot extra")

PNG = b"\x89PNG\r\n\x1a\n"


def test_each_stop_draws_the_run_so_far(debug: Debug, tmp_path: Path) -> None:
    image = tmp_path / "run.png"
    client = debug(MOVING, breakpoints=(3,), drives="enabled", plot=str(image))
    client.stopped()
    first = image.read_bytes()
    assert first.startswith(PNG)
    client.body("runFor", {"ms": 20})
    client.stopped()
    assert image.read_bytes().startswith(PNG) and image.read_bytes() != first


def test_a_plot_it_cannot_draw_is_refused_at_launch(tmp_path: Path) -> None:
    from tests.debugger.client import DapClient  # noqa: PLC0415

    program = tmp_path / "p.mnt"
    program.write_text("DIM x\n", encoding="utf-8")
    client = DapClient()
    client.body("initialize", {"adapterID": "mint"})
    refused = client.request("launch", {"program": str(program), "plot": str(tmp_path / "run.txt")})
    assert not refused["success"] and "image" in refused["message"]
    client.close()
