"""Latency and CPU of ``mint-lsp`` on programs of 5,000 to 50,000 lines, beside a full ``mint check``.

Run: ``.venv/bin/python benchmarks/lsp_latency.py [--lines 5000 20000 50000] [--repeat 15]``

The server runs as a separate process over stdio, as an editor starts it, one per size
(the benchmark lifts its 5,000,000-character limit, so that any size asked for is analysed).
Measured (medians): the wall time from a one-character ``didChange`` to the
``publishDiagnostics`` of that version (debounce set to 0 ms, so the figure is
the server's own work; editors add the configured debounce, 150 ms by
default), for three kinds of typing near the top of the file, where an edit
moves the most text: a character typed into a comment and deleted again, a
digit typed into a number (``WAIT = 174``) and deleted again,
and a character typed into a variable's name in an ``IF`` and deleted again
(the name becomes undeclared, then declared: the symbol table and the
diagnostics change with every keystroke). Also the time to answer
``semanticTokens/full`` once those diagnostics are
in (editors ask for the colours after every edit, and a completion asked
meanwhile waits for them), and the time to answer ``hover`` and
``completion``. The reference is ``mintlang.check_application`` on the same
text in this process with the per-line caches cleared, as ``mint check`` runs
(the grammar and the keyword database already loaded). Beside each edit's wall time is the
server's CPU time for it (read from ``/proc``, so the figure excludes the client and the pipes), as
a share of the reference's CPU time. Targets (issue 14): diagnostics ≤ 50 ms, hover ≤ 10 ms,
completion ≤ 20 ms; server CPU for an edit in a comment or a number ≤ 5 % of the cold check and flat
from 5k to 50k lines, for an edit to a name ≤ 15 % (semantic tokens have none: the figure shows what an
edit costs beyond its diagnostics).
"""

from __future__ import annotations

import argparse
import asyncio
import os
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


# The server with its file-size limit lifted, so that large files are analysed at all.
_SERVER = "import mintlang.lsp.workspace as w; w.MAX_CHARACTERS = 10**9; from mintlang.lsp.cli import main; main()"
_TICKS = os.sysconf("SC_CLK_TCK")
# Even numbers: each block leaves the text as it found it. A name edit costs tens of milliseconds, a
# comment's or a number's one or two: those are read over more edits, at a tenth of a millisecond.
_EDITS_PER_BLOCK = {"comment": 100, "number": 100, "name": 10}
_BLOCKS = 3  # at least, for a spread


def _cpu_seconds(pid: int) -> float:
    """User plus system CPU time of process ``pid`` so far (Linux ``/proc/<pid>/stat``)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / _TICKS


async def _measure(text: str, path: Path, repeat: int) -> dict[str, list[float]]:
    client = _Client()
    await client.start_io(sys.executable, "-c", _SERVER)
    assert client._server is not None  # pygls keeps the server process there
    pid = client._server.pid
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
    in_comment = lines[comment].index("REM") + len("REM ")  # in the comment's text, not before its REM
    waiting = next(number for number, line in enumerate(lines) if "WAIT = " in line)
    in_number = lines[waiting].index("WAIT = ") + len("WAIT = 1")  # between the number's first digit and the rest
    condition = next(number for number, line in enumerate(lines) if line.startswith("  IF IN"))
    name_end = lines[condition].index(" >")  # after "speed<n>"
    statement = next(number for number, line in enumerate(lines) if line.startswith("  SPEED[0,1]"))
    figures: dict[str, list[float]] = {
        "diagnostics, typing in a comment": [],
        "diagnostics, typing in a number": [],
        "diagnostics, typing in a name": [],
        "server CPU, typing in a comment": [],
        "server CPU, typing in a number": [],
        "server CPU, typing in a name": [],
        "semantic tokens": [],
        "hover": [],
        "completion": [],
    }
    version = 1

    async def edit(line: int, character: int, typed: bool, character_typed: str = "x") -> float:
        """Type (or delete) one character at the place; the wall time until its diagnostics arrive."""
        nonlocal version
        version += 1
        client.published[version] = asyncio.Event()
        at = types.Position(line=line, character=character)
        after = types.Position(line=line, character=character + 1)
        change = types.TextDocumentContentChangePartial(
            range=types.Range(start=at, end=at if typed else after), text=character_typed if typed else ""
        )
        start = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(
                text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                content_changes=[change],
            )
        )
        await client.published[version].wait()
        return time.perf_counter() - start

    # The kernel counts CPU time in ticks of 10 ms, more than an edit takes: the server's CPU is read
    # over blocks of edits (a character typed, then deleted, in turn) and divided by their number.
    for kind, line, character, typing in (
        ("comment", comment, in_comment, "x"),
        ("number", waiting, in_number, "5"),
        ("name", condition, name_end, "x"),
    ):
        name, block = f"diagnostics, typing in a {kind}", _EDITS_PER_BLOCK[kind]
        for _ in range(max(_BLOCKS, repeat // block)):
            cpu = _cpu_seconds(pid)
            figures[name] += [await edit(line, character, number % 2 == 0, typing) for number in range(block)]
            figures[name.replace("diagnostics", "server CPU")].append((_cpu_seconds(pid) - cpu) / block)
    for number in range(repeat):
        await edit(comment, in_comment, typed=number % 2 == 0)
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


def _reference(text: str, repeat: int) -> list[float]:
    """CPU seconds of a cold ``check_application`` of ``text`` in this process, ``repeat`` times."""
    mintlang.check_application(text)  # the grammar and the keyword database loaded, as in the server
    checks = []
    for _ in range(repeat):
        mintlang.clear_caches()  # every line parsed and checked afresh, as by `mint check`
        start = time.process_time()
        mintlang.check_application(text)
        checks.append(time.process_time() - start)
    return checks


_TARGETS = {
    "diagnostics, typing in a comment": "≤ 50 ms",
    "diagnostics, typing in a number": "≤ 50 ms",
    "diagnostics, typing in a name": "≤ 50 ms",
    "server CPU, typing in a comment": "≤ 5 %",
    "server CPU, typing in a number": "≤ 5 %",
    "server CPU, typing in a name": "≤ 15 %",
    "hover": "≤ 10 ms",
    "completion": "≤ 20 ms",
}


def _spread(values: list[float]) -> str:
    return f"{statistics.median(values) * 1000:8.1f} ms ({min(values) * 1000:.1f}-{max(values) * 1000:.1f})"


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--lines", type=int, nargs="+", default=[5000, 20000, 50000])
    options.add_argument("--repeat", type=int, default=15)
    arguments = options.parse_args()
    comment_cpu: dict[int, float] = {}
    number_cpu: dict[int, float] = {}
    for lines in arguments.lines:
        text = mint_program(lines)
        with tempfile.TemporaryDirectory() as folder:
            figures = asyncio.run(_measure(text, Path(folder) / "benchmark.mnt", arguments.repeat))
        reference = statistics.median(_reference(text, arguments.repeat))
        print(f"mint-lsp on a {lines}-line program ({len(text):,} characters), median (min-max) of {arguments.repeat}")
        print(f"  {'full mint check, CPU (reference)':<40}{reference * 1000:8.1f} ms")
        for name, values in figures.items():
            target = f"  (target {_TARGETS[name]})" if name in _TARGETS else ""
            share = f"  = {statistics.median(values) / reference:6.1%} of the reference" if "CPU" in name else ""
            print(f"  {name:<40}{_spread(values)}{share}{target}")
        comment_cpu[lines] = statistics.median(figures["server CPU, typing in a comment"])
        number_cpu[lines] = statistics.median(figures["server CPU, typing in a number"])
    smallest, largest = min(comment_cpu), max(comment_cpu)
    if largest != smallest:
        for kind, cpu in (("comment", comment_cpu), ("number", number_cpu)):
            growth = cpu[largest] / cpu[smallest]
            sizes = f"{largest} lines over {smallest} lines"
            print(f"server CPU for a {kind} edit, {sizes}: {growth:.1f} (target: flat, 1.0)")


if __name__ == "__main__":
    main()
