"""Neovim with the README's snippet on a workspace: one server for two programs and a configuration file.

The workspace is the folder with ``mint.toml``; the programs sit in a folder
below it. ``a.cfg`` declares ``stroke``, which ``a.mnt`` uses; ``b.mnt`` uses
``target``, which ``b.cfg`` (on disk, never opened) declares only once it is
changed, and writes the v3 keyword ``HMSPEED`` (v4: ``HOMESPEED``).
"""

from __future__ import annotations

from tests.lsp.neovim import needs_neovim, run_probe

B = ["DEFINE xAxis = 0", "DIM total = 0", "HMSPEED[xAxis] = 20", "total = target + 1", "PRINT total"]


@needs_neovim
def test_one_server_for_the_workspace_sees_every_file(tmp_path):
    root = tmp_path / "cell"
    src = root / "src"
    src.mkdir(parents=True)
    (root / "mint.toml").write_text("", encoding="utf-8")
    files = {
        "a.mnt": "DIM count = 0\ncount = stroke + 1\nPRINT count\n",
        "a.cfg": "DIM stroke = 5\n",
        "b.mnt": "\n".join(B) + "\n",
        "b.cfg": "REM nothing yet\n",
    }
    for name, text in files.items():
        (src / name).write_text(text, encoding="utf-8")
    result = run_probe(
        "workspace.lua",
        src / "a.mnt",
        tmp_path,
        MINT_A=str(src / "a.mnt"),
        MINT_A_CFG=str(src / "a.cfg"),
        MINT_B=str(src / "b.mnt"),
        MINT_B_CFG=str(src / "b.cfg"),
    )
    assert result.get("error") is None, result["error"]
    assert result["clients"] == 1 and result["root"] == str(root)
    assert result["attached"]["a"] == result["attached"]["a_cfg"] == result["attached"]["b"]

    assert result["before"] == {"a": [], "b": ["E3001", "E3007"]}  # target undeclared, HMSPEED is v3
    # the rename reached the unsaved a.cfg, and a.mnt is checked with it: no false E3001
    assert result["renamed"] == {"a": [], "a_cfg": [], "a_cfg_text": ["DIM maxStroke = 5"]}
    assert (src / "a.cfg").read_text(encoding="utf-8") == "DIM stroke = 5\n"
    assert result["disk_changed"] == {"b": ["E3007"]}  # b.cfg now declares target

    assert result["actions"] == ["Replace v3 keywords"]  # a v4 program: no whole migration
    assert result["b_text"] == [line.replace("HMSPEED", "HOMESPEED") for line in B]
