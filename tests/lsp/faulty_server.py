"""The real ``mint-lsp`` with failures injected, to show a failing handler never stops the server.

Hover always raises; analysing a text that contains ``INJECTED_FAILURE``
raises, so opening or changing such a document fails inside a notification.
"""

from __future__ import annotations

from mintlang.lsp.cli import main
from mintlang.lsp.features import hover
from mintlang.lsp.workspace import Analyses, Snapshot

INJECTED_FAILURE = "REM inject a failure"


def _failing_hover(*_: object) -> None:
    raise RuntimeError("injected hover failure")


_analyse = Analyses._analyse


def _failing_analyse(self: Analyses, uri: str, text: str, *args: object, **kwargs: object) -> Snapshot:
    if INJECTED_FAILURE in text:
        raise RuntimeError("injected analysis failure")
    return _analyse(self, uri, text, *args, **kwargs)  # type: ignore[arg-type]


if __name__ == "__main__":
    hover.hover_text = _failing_hover  # type: ignore[assignment]
    Analyses._analyse = _failing_analyse  # type: ignore[method-assign]
    main()
