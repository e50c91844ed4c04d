"""The analyser: rules over the semantic model that produce diagnostics."""
