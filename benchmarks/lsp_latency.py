"""Latency of ``mint-lsp`` on a 5,000-line program, beside a full ``mint check`` of the same file.

Run: ``.venv/bin/python benchmarks/lsp_latency.py [--lines 5000] [--repeat 15]``

The server runs as a separate process over stdio, as an editor starts it.
Measured (medians): the time from a one-character ``didChange`` to the
``publishDiagnostics`` of that version (debounce set to 0 ms, so the figure is
the server's own work; editors add the configured debounce, 150 ms by
default), for two kinds of typing near the top of the file, where an edit
moves the most text: a character typed into a comment and deleted again,
and a character typed into a variable's name in an ``IF`` and deleted again
(the name becomes undeclared, then declared: the symbol table and the
diagnostics change with every keystroke). Also the time to answer
``semanticTokens/full`` once those diagnostics are
in (editors ask for the colours after every edit, and a completion asked
meanwhile waits for them), and the time to answer ``hover`` and
``completion``. The reference is ``mintlang.check_application`` on the same
text in this process with the per-line caches cleared, as ``mint check`` runs
(the grammar and the keyword database already loaded).
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
    condition = next(number for number, line in enumerate(lines) if line.startswith("  IF IN"))
    name_end = lines[condition].index(" >")  # after "speed<n>"
    statement = next(number for number, line in enumerate(lines) if line.startswith("  SPEED[0,1]"))
    figures: dict[str, list[float]] = {
        "diagnostics, typing in a comment": [],
        "diagnostics, typing in a name": [],
        "semantic tokens": [],
        "hover": [],
        "completion": [],
    }
    version = 1
    for round_ in range(repeat):
        for name, line, character in (
            ("diagnostics, typing in a comment", comment, 2),
            ("diagnostics, typing in a name", condition, name_end),
        ):
            version += 1
            client.published[version] = asyncio.Event()
            at = types.Position(line=line, character=character)
            after = types.Position(line=line, character=character + 1)
            typed = round_ % 2 == 0  # type a character, then delete it in the next round
            change = types.TextDocumentContentChangePartial(
                range=types.Range(start=at, end=at if typed else after), text="x" if typed else ""
            )
            start = time.perf_counter()
            client.text_document_did_change(
                types.DidChangeTextDocumentParams(
                    text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                    content_changes=[change],
                )
            )
            await client.published[version].wait()
            figures[name].append(time.perf_counter() - start)
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
    mintlang.check_application(text)  # the grammar and the keyword database loaded, as in the server
    checks = []
    for _ in range(arguments.repeat):
        mintlang.clear_caches()  # every line parsed and checked afresh, as by `mint check`
        start = time.perf_counter()
        mintlang.check_application(text)
        checks.append(time.perf_counter() - start)
    targets = {
        "diagnostics, typing in a comment": 50,
        "diagnostics, typing in a name": 50,
        "hover": 10,
        "completion": 20,
    }
    print(f"mint-lsp on a {arguments.lines}-line program, median of {arguments.repeat}")
    print(f"  {'full mint check (reference)':<44}{statistics.median(checks) * 1000:8.1f} ms")
    for name, values in figures.items():
        label = f"{name} (target ≤ {targets[name]} ms)" if name in targets else f"{name} (after an edit)"
        print(f"  {label:<44}{statistics.median(values) * 1000:8.1f} ms")


if __name__ == "__main__":
    main()
