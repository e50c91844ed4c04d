"""One module per LSP feature; each exposes ``register(server)``."""

from mintlang.lsp.features import (
    call_hierarchy,
    code_actions,
    completion,
    diagnostics,
    folding,
    formatting,
    hover,
    inlay_hints,
    navigation,
    reference_lenses,
    rename,
    semantic_tokens,
    settings,
    signature,
    simulator,
    symbols,
)

FEATURES = (
    settings,
    diagnostics,
    hover,
    completion,
    signature,
    navigation,
    rename,
    symbols,
    folding,
    semantic_tokens,
    formatting,
    code_actions,
    inlay_hints,
    simulator,
    call_hierarchy,
    reference_lenses,
)
