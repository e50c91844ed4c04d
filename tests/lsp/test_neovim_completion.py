"""Neovim with the README's snippet: completion after a keyword's dot offers the controller's axes."""

from __future__ import annotations

from tests.lsp.neovim import needs_neovim, run_probe


@needs_neovim
def test_neovim_completes_the_axes_after_a_dot(tmp_path):
    program = tmp_path / "axes.mnt"
    program.write_text("DEFINE xAxis = 0\nDIM a\n", encoding="utf-8")
    result = run_probe("complete.lua", program, tmp_path)
    assert "." in result["triggers"]
    assert result["labels"] == [*(str(axis) for axis in range(12)), "xAxis"]  # NextMove PCI: axes 0 to 11
