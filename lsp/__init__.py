"""mint-lsp: the Mint language server (``mintlang.lsp``)."""
