"""``python -m mintlang.runtime.debugger``: the editor's way to start ``mint-dap`` with a chosen interpreter."""

from mintlang.runtime.debugger.cli import main

main()
