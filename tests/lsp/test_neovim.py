"""A new user's first minutes: Neovim with the README's snippet, a program with an error, a hover."""

from __future__ import annotations

from pathlib import Path

from tests.lsp.conftest import corpus
from tests.lsp.neovim import NVIM, needs_neovim, run_probe


@needs_neovim
def test_neovim_shows_diagnostic_and_hover(tmp_path):
    program = tmp_path / "xy.mnt"
    program.write_text(corpus("ch01_l0144_xy_example.mnt").replace("DIM a\n", ""), encoding="utf-8")
    result = run_probe(
        "probe.lua",
        program,
        tmp_path,
        MINT_HOVER_LINE="26",  # MOVEA[0,1] = xpos(a),ypos(a) : GO[0,1]
        MINT_HOVER_CHARACTER="2",
    )
    undeclared = [d for d in result["diagnostics"] if d["code"] == "E3001"]
    assert undeclared and undeclared[0]["message"].startswith("Variable undefined, use DIM")
    assert "**MOVEA**" in result["hover"]


def test_the_readme_snippet_is_the_one_the_editor_tests_run():
    readme = (Path(__file__).parents[2] / "README.md").read_text(encoding="utf-8")
    snippet = (NVIM / "mint.lua").read_text(encoding="utf-8")
    assert f"```lua\n{snippet}```\n" in readme
