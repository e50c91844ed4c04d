"""The verification report: one data shape for ``--format json`` and the text a person reads.

A place is told as the file it is in: a run's line is a line of the v3 file (the
original) or of the migrated one, which has the same lines as the v4 run (a line
disabled for the run keeps its number), so ``program`` and ``configuration``
become the paths the command line gave.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from typing import Any

from rich.console import Console
from rich.markup import escape

from mintlang.migrate.expected import DIFFERS
from mintlang.migrate.model import ManualItem
from mintlang.migrate.report import plural
from mintlang.migrate.verification.model import Divergence, Place, Stopped, Verdict, Verification
from mintlang.records import record


@record
class Verified:
    """One application's verification, with the paths of its files (None for a file it does not have)."""

    program: str | None
    configuration: str | None
    verification: Verification

    def path(self, place: Place | None) -> str | None:
        if place is None:
            return None
        return self.configuration if place.unit == "configuration" else self.program


def headline(verification: Verification) -> str:
    """``equivalent over 2000 ms``, ``diverges at 120 ms: axis 0 position``, ``incomplete: no difference over
    40 ms, then …``."""
    found = verification.divergence
    verdict = verification.verdict
    if verdict is Verdict.EQUIVALENT:
        return f"equivalent over {verification.compared_ms} ms"
    if verdict is Verdict.INCOMPLETE and verification.compared_ms == 0:
        return f"incomplete: {verification.short}"
    if verdict is Verdict.INCOMPLETE:
        return f"incomplete: no difference over {verification.compared_ms} ms, then {verification.short}"
    assert found is not None, "a divergence, a timing or an explained difference has a first difference"
    if verdict is Verdict.EXPLAINED:
        return f"differs only as {found.explained_by} explains, from {found.time_ms} ms: {found.what}"
    kind = "timing differs (X-GO-TIMING)" if verdict is Verdict.TIMING else "diverges"
    return f"{kind} at {found.time_ms} ms: {found.what}"


# The two runs as the report names them: the original's dialect, then the migration's.
V3_TO_V4 = ("v3", "v4")
V4_TO_MINTMT = ("v4", "mintmt")


def report(
    verified: Iterable[Verified], sides: tuple[str, str] = V3_TO_V4, problems: Iterable[str] = ()
) -> dict[str, Any]:
    """The report as plain data (what ``--verify --format json`` prints), each run's fields named after
    its dialect (``sides``; a ``Verification``'s ``v3`` fields are the original's, ``v4`` the migration's).
    ``problems`` are what kept an application from being verified (a path that cannot be read, a failed
    migration), as standard error words them: a JSON reader sees them without parsing standard error."""
    rows = [_application(item, sides) for item in verified]
    verdicts = Counter(row["verdict"] for row in rows)
    totals = {verdict.value: verdicts[verdict.value] for verdict in Verdict}
    return {"applications": rows, "problems": list(problems), "totals": totals}


def _application(item: Verified, sides: tuple[str, str]) -> dict[str, Any]:
    verification = item.verification
    original, migrated = sides
    return {
        "program": item.program,
        "configuration": item.configuration,
        f"{original}_controller": verification.v3_controller,
        f"{migrated}_controller": verification.v4_controller,
        "verdict": verification.verdict.value,
        "summary": headline(verification),
        "compared_ms": verification.compared_ms,
        "incomplete": verification.short,
        "divergence": _divergence(item, verification.divergence, sides),
        "differences": [_divergence(item, found, sides) for found in verification.differences],
        "stopped": {original: _stopped(item, verification.v3_stop), migrated: _stopped(item, verification.v4_stop)},
        "not_verified": [_manual(item, unit, manual) for unit, manual in verification.not_verified],
        "disabled": [{"file": item.path(place), "line": place.line} for place in verification.disabled],
    }


def _side(item: Verified, value: str, place: Place | None) -> dict[str, Any]:
    return {"value": value, "file": item.path(place), "line": place.line if place is not None else None}


def _divergence(item: Verified, found: Divergence | None, sides: tuple[str, str]) -> dict[str, Any] | None:
    if found is None:
        return None
    return {
        "time_ms": found.time_ms,
        "what": found.what,
        "detail": found.detail,
        "timing_only": found.timing_only,
        "explained_by": found.explained_by,
        "what_if": found.what_if,
        sides[0]: _side(item, found.v3, found.v3_line),
        sides[1]: _side(item, found.v4, found.v4_line),
    }


def _stopped(item: Verified, stop: Stopped) -> dict[str, Any]:
    where = stop.line
    return {
        "reason": stop.reason,
        "time_ms": stop.time_ms,
        "file": item.path(where),
        "line": where.line if where is not None else None,
        "message": stop.message,
    }


def _manual(item: Verified, unit: str, manual: ManualItem) -> dict[str, Any]:
    return {
        "file": item.path(Place(unit, manual.line)),
        "migrated_line": manual.line,
        "original_line": manual.original_line,
        "note": manual.note,
        "rule": manual.rule,
        "reason": manual.reason,
    }


def render_text(
    data: Mapping[str, Any], console: Console, *, quiet: bool = False, sides: tuple[str, str] = V3_TO_V4
) -> None:
    """Per application: the verdict, the first difference with each run's line, what was not verified (not
    when ``quiet``); then the totals (not when ``quiet``). ``sides`` names the runs, as ``report`` did."""
    migrated = sides[1]
    for row in data["applications"]:
        name = escape(row["program"] or row["configuration"])
        # an incomplete run's differences are all explained: each is listed below, none is its headline's
        found = row["divergence"] if row["verdict"] != Verdict.INCOMPLETE else None
        detail = f" ({escape(found['detail'])})" if found is not None and found["detail"] else ""
        console.print(f"{name}: [bold]{escape(row['summary'])}[/bold]{detail}")
        for side in sides if found is not None else ():
            console.print(f"  {side}: {escape(found[side]['value'])}  {_where(found[side], side == migrated)}")
        if found is not None and found["what_if"]:
            console.print(f"  ({migrated}: {escape(found['what_if'])})")
        for other in (other for other in row["differences"] if other != found):
            values = ", ".join(f"{side} {escape(other[side]['value'])}" for side in sides)
            timing = ", timing only" if other["timing_only"] else ""
            why = f", explained by {other['explained_by']}" if other["explained_by"] else ""
            console.print(f"  also differs: {escape(other['what'])} at {other['time_ms']} ms ({values}{timing}{why})")
        for rule in dict.fromkeys(other["explained_by"] for other in row["differences"] if other["explained_by"]):
            console.print(f"  explained: [bold]{rule}[/bold] {escape(DIFFERS[rule])}")
        if quiet:
            continue
        for manual in row["not_verified"]:
            where = _manual_place(manual) + (" (note)" if manual["note"] else "")
            reason = escape(manual["reason"])
            console.print(f"  not verified: {where}: [bold]{manual['rule']}[/bold] {reason}", style="dim")
        for place in row["disabled"]:
            where = f"{escape(place['file'])}:{place['line']}"
            console.print(f"  disabled for the {migrated} run: {where} (migrated)", style="dim")
    if not quiet:
        console.print(summary(data["totals"]))


def _manual_place(manual: Mapping[str, Any]) -> str:
    """``demo.mnt:3`` at the original's line, else ``migrated demo.mnt:12`` (a note the migrator added)."""
    if manual["original_line"] is not None:
        return f"{escape(manual['file'])}:{manual['original_line']}"
    return f"migrated {escape(manual['file'])}:{manual['migrated_line']}"


def _where(told: Mapping[str, Any], migrated: bool) -> str:
    """``at demo.mnt:7`` for the original file, ``at migrated demo.mnt:9`` for the migrated one."""
    if told["line"] is None:
        return ""
    return f"at {'migrated ' if migrated else ''}{escape(told['file'])}:{told['line']}"


def summary(totals: Mapping[str, int]) -> str:
    """``3 applications verified: 2 equivalent, 1 diverges``."""
    counts = ", ".join(f"{count} {verdict}" for verdict, count in totals.items() if count)
    return f"{plural(sum(totals.values()), 'application')} verified" + (f": {counts}" if counts else "")
