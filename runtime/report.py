"""The end-of-run report: one JSON object a CI job or a host program can read."""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

from mintlang.runtime.run import RunResult


def as_json(result: RunResult) -> dict[str, Any]:
    stop = result.stop
    return {
        "time_ms": stop.time_ms,
        "stopped": stop.reason.value,
        "message": stop.message,
        "unit": stop.unit,
        "line": stop.line,
        "statement": stop.statement,
        "err": result.err,
        "erl": result.erl,
        "outputs": result.outputs,
        "relay": result.relay,
        "axes": {str(number): asdict(state) for number, state in enumerate(result.axes)},
        "inert_settings": list(result.inert_settings),
        "read_leniently": list(result.read_leniently),
        "ignored_directives": list(result.ignored_directives),
        "not_run": list(result.not_run),
        "host_replies": [{"time_ms": time_ms, "bytes": data.hex(" ")} for time_ms, data in result.host_replies],
        "expectations": [
            {
                "what": outcome.expectation.what,
                "at_ms": outcome.expectation.at_ms,
                "expected": outcome.expectation.expected,
                "held": outcome.held,
                "actual": outcome.actual,
                "detail": outcome.detail,
            }
            for outcome in result.outcomes
        ],
    }
