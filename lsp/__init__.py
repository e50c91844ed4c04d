"""mint-lsp: the Mint language server (``mintlang.lsp``)."""

__version__ = "0.1.0"
