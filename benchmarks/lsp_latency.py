"""Latency of ``mint-lsp`` on a 5,000-line program, beside a full ``mint check`` of the same file.

Run: ``.venv/bin/python benchmarks/lsp_latency.py [--lines 5000] [--repeat 15]``

The server runs as a separate process over stdio, as an editor starts it.
Measured (medians): the time from a one-character ``didChange`` to the
``publishDiagnostics`` of that version (debounce set to 0 ms, so the figure is
the server's own work; editors add the configured debounce, 150 ms by
default), the time to answer ``semanticTokens/full`` once those diagnostics are
in (editors ask for the colours after every edit, and a completion asked
meanwhile waits for them), and the time to answer ``hover`` and
``completion``. The reference is ``mintlang.check_application`` on the same
text in this process, warm.
Targets: diagnostics ≤ 50 ms, hover ≤ 10 ms, completion ≤ 20 ms (semantic tokens have none: the
figure shows what an edit costs beyond its diagnostics).
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

sys.path.insert(0, str(Path(__file__).parent))

from programs import mint_program

import mintlang


class _Client(LanguageClient):
    """Wakes the benchmark when the diagnostics of an awaited version arrive."""

    def __init__(self) -> None:
        super().__init__("lsp-latency", "1")
        self.published: dict[int, asyncio.Event] = {}

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def diagnostics(params: types.PublishDiagnosticsParams) -> None:
            if params.version in self.published:
                self.published[params.version].set()


async def _measure(text: str, path: Path, repeat: int) -> dict[str, list[float]]:
    client = _Client()
    await client.start_io(sys.executable, "-m", "mintlang.lsp")
    await client.initialize_async(
        types.InitializeParams(
            capabilities=types.ClientCapabilities(), initialization_options={"mint": {"debounceMs": 0}}
        )
    )
    client.initialized(types.InitializedParams())
    uri = path.as_uri()
    here = types.TextDocumentIdentifier(uri=uri)
    client.published[1] = asyncio.Event()
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            text_document=types.TextDocumentItem(uri=uri, language_id="mint", version=1, text=text)
        )
    )
    await client.published[1].wait()
    lines = text.splitlines()
    comment = next(number for number, line in enumerate(lines) if "REM ---- next station" in line)
    statement = next(number for number, line in enumerate(lines) if line.startswith("  SPEED[0,1]"))
    figures: dict[str, list[float]] = {"diagnostics": [], "semantic tokens": [], "hover": [], "completion": []}
    for version in range(2, repeat + 2):
        client.published[version] = asyncio.Event()
        where = types.Range(
            start=types.Position(line=comment, character=2), end=types.Position(line=comment, character=3)
        )
        start = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(
                text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                content_changes=[types.TextDocumentContentChangePartial(range=where, text="rR"[version % 2])],
            )
        )
        await client.published[version].wait()
        figures["diagnostics"].append(time.perf_counter() - start)
        start = time.perf_counter()
        await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=here))
        figures["semantic tokens"].append(time.perf_counter() - start)
    for _ in range(repeat):
        start = time.perf_counter()
        await client.text_document_hover_async(
            types.HoverParams(text_document=here, position=types.Position(line=statement, character=3))
        )
        figures["hover"].append(time.perf_counter() - start)
        start = time.perf_counter()
        await client.text_document_completion_async(
            types.CompletionParams(text_document=here, position=types.Position(line=statement, character=2))
        )
        figures["completion"].append(time.perf_counter() - start)
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return figures


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, default=5000)
    options.add_argument("--repeat", type=int, default=15)
    arguments = options.parse_args()
    text = mint_program(arguments.lines)
    with tempfile.TemporaryDirectory() as folder:
        figures = asyncio.run(_measure(text, Path(folder) / "benchmark.mnt", arguments.repeat))
    mintlang.check_application(text)  # warm, as the server is
    checks = []
    for _ in range(arguments.repeat):
        start = time.perf_counter()
        mintlang.check_application(text)
        checks.append(time.perf_counter() - start)
    targets = {"diagnostics": 50, "hover": 10, "completion": 20}
    print(f"mint-lsp on a {arguments.lines}-line program, median of {arguments.repeat}")
    print(f"  {'full mint check (reference)':<38}{statistics.median(checks) * 1000:8.1f} ms")
    for name, values in figures.items():
        label = f"{name} (target ≤ {targets[name]} ms)" if name in targets else f"{name} (after an edit)"
        print(f"  {label:<38}{statistics.median(values) * 1000:8.1f} ms")


if __name__ == "__main__":
    main()
