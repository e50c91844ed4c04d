"""``python -m mintlang.lsp``: the server over stdio, as ``mint-lsp`` runs it."""

from mintlang.lsp.cli import main

main()
