"""What ``mint test`` writes: a line per test and a summary on a terminal, or JUnit XML, or JSON."""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Sequence
from dataclasses import asdict
from pathlib import Path
from xml.etree import ElementTree

from rich.console import Console
from rich.table import Table
from rich.text import Text

from mintlang.runtime.testing.coverage import FileCoverage, handlers_run, lines_run, outcomes_seen
from mintlang.runtime.testing.discovery import TestCase
from mintlang.runtime.testing.running import Check, TestResult, Verdict

_STYLE = {Verdict.PASSED: "green", Verdict.FAILED: "bold red", Verdict.ERROR: "bold yellow"}


def summary(results: Sequence[TestResult], seconds: float, deselected: int = 0) -> str:
    """``3 passed, 1 failed, 1 error, 2 deselected in 2.41 s``, the verdicts in a fixed order, only those that
    occur, then the tests ``-k`` left out, as pytest counts them."""
    counts = Counter(result.verdict for result in results)
    parts = [f"{counts[verdict]} {_word(verdict, counts[verdict])}" for verdict in Verdict if counts[verdict]]
    parts += [f"{deselected} deselected"] if deselected else []
    return f"{', '.join(parts) or 'no tests ran'} in {seconds:.2f} s"


def _word(verdict: Verdict, count: int) -> str:
    return "errors" if verdict is Verdict.ERROR and count != 1 else verdict.value


def text(
    results: Sequence[TestResult],
    seconds: float,
    console: Console,
    *,
    deselected: int = 0,
    quiet: bool = False,
    verbose: bool = False,
) -> None:
    """A line per test, and under it what failed; ``quiet``: the tests that did not pass alone, and no
    closing count; ``verbose``: every expectation under its test, held or not; ``deselected``: the tests
    ``-k`` left out, counted in the closing line."""
    for result in results:
        if quiet and result.verdict is Verdict.PASSED:
            continue
        line = Text(f"{result.verdict.value.upper():6} ", style=_STYLE[result.verdict])
        line.append(result.case.name)
        if result.verdict is not Verdict.PASSED:
            line.append(f"  {_why(result)}", style="dim")
        console.print(line, highlight=False)
        for detail in _details(result, verbose=verbose):
            console.print(f"    {detail}", highlight=False, markup=False)
    if not quiet:
        console.print(Text(summary(results, seconds, deselected), style="bold"), highlight=False)


def _why(result: TestResult) -> str:
    if result.verdict is Verdict.ERROR:
        return _error(result)
    failed = sum(not check.held for check in result.checks)
    if failed:
        return f"{failed} of {len(result.checks)} expectations failed"
    return _stop(result)


def _error(result: TestResult) -> str:
    """Why a test is an error, where it is: each directive or scenario mistake at its own place (its column
    too), or the message after the place the run stopped at."""
    if result.problems:
        return "\n".join(str(problem) for problem in result.problems)
    return f"{result.place}: {result.message}" if result.place else result.message


def _stop(result: TestResult) -> str:
    where = f" at {result.place}" if result.place else ""
    return f"stopped {result.stopped}{where}" + (f": {result.message}" if result.message else "")


def junit(results: Sequence[TestResult], seconds: float) -> str:
    """The JUnit XML CI servers read: one testsuite, a testcase per program (classname its folder)."""
    counts = Counter(result.verdict for result in results)
    suites = ElementTree.Element("testsuites")
    suite = ElementTree.SubElement(
        suites,
        "testsuite",
        name="mint test",
        tests=str(len(results)),
        failures=str(counts[Verdict.FAILED]),
        errors=str(counts[Verdict.ERROR]),
        skipped="0",
        time=f"{seconds:.3f}",
    )
    for result in results:
        program = result.case.program
        case = ElementTree.SubElement(
            suite, "testcase", classname=str(program.parent), name=program.name, time=f"{result.seconds:.3f}"
        )
        if result.verdict is Verdict.FAILED:
            failure = ElementTree.SubElement(case, "failure", message=_why(result), type="expectation")
            failure.text = "\n".join(_check_lines(result, held_too=False))
        elif result.verdict is Verdict.ERROR:
            ElementTree.SubElement(case, "error", message=_why(result), type="error")
        if result.ignored_directives:
            warned = "".join(f"warning: {note}\n" for note in result.ignored_directives)  # as on standard error
            ElementTree.SubElement(case, "system-err").text = warned
    ElementTree.indent(suites)
    return ElementTree.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


def warnings(results: Sequence[TestResult]) -> list[str]:
    """What the runs warn of, each once: a configuration file shared by several programs is one warning."""
    return list(dict.fromkeys(note for result in results for note in result.ignored_directives))


def _check_lines(result: TestResult, *, held_too: bool) -> list[str]:
    """The expectations that did not hold (all of them with ``held_too``), then the stop when it failed the test
    too: a run ended by an error shows the error, not only the values it left."""
    lines = [_held(check) if check.held else _failure(check) for check in result.checks if held_too or not check.held]
    return [*lines, _stop(result)] if result.stop_failed else lines


def _failure(check: Check) -> str:
    """An expectation that did not hold, in one line: what, when, expected and seen, why, and where it is."""
    detail = f" ({check.detail})" if check.detail else ""
    return f"{check.what} at {check.when}: expected {check.expected}, got {check.actual}{detail} [{check.origin}]"


def _details(result: TestResult, *, verbose: bool) -> list[str]:
    """The lines under a test's: its failed expectations (every one with ``verbose``), then the stop when it
    failed the test too. Without a failed expectation, the test's line already says how the run stopped."""
    if all(check.held for check in result.checks):
        return [_held(check) for check in result.checks] if verbose else []
    return _check_lines(result, held_too=verbose)


def _held(check: Check) -> str:
    """An expectation that held, in one line: what, when, the value seen, and where it is."""
    return f"{check.what} at {check.when}: {check.actual}, as expected [{check.origin}]"


def collected(cases: Sequence[TestCase], *, as_json: bool) -> str:
    """The tests ``--collect-only`` found: a program a line (with its scenario file), or JSON for the editors."""
    if as_json:
        tests = [{"program": str(case.program), "scenario": _optional(case.scenario)} for case in cases]
        return json.dumps({"tests": tests}, indent=2) + "\n"
    return "".join(f"{case.name}{f' ({case.scenario})' if case.scenario else ''}\n" for case in cases)


def _optional(path: Path | None) -> str | None:
    return str(path) if path is not None else None


def as_json(results: Sequence[TestResult], seconds: float) -> str:
    tests = [
        {
            "program": str(result.case.program),
            "scenario": _optional(result.case.scenario),
            "verdict": result.verdict.value,
            "stopped": result.stopped,
            "message": result.message,
            "place": result.place,
            "stop_failed": result.stop_failed,
            "simulated_ms": result.simulated_ms,
            "seconds": round(result.seconds, 3),
            "checks": [asdict(check) for check in result.checks],
            "ignored_directives": list(result.ignored_directives),
        }
        for result in results
    ]
    counts = Counter(result.verdict.value for result in results)
    body = {"summary": {verdict.value: counts[verdict.value] for verdict in Verdict}, "tests": tests}
    return json.dumps({**body, "seconds": round(seconds, 3)}, indent=2) + "\n"


def coverage_table(files: Sequence[FileCoverage], console: Console) -> None:
    """Lines, branch outcomes and event handlers run, per file and in total."""
    table = Table("file", "lines", "branches", "handlers", title="coverage")
    table.columns[0].overflow = "fold"
    totals = [0, 0, 0, 0, 0, 0]
    for file in files:
        counts = (
            lines_run(file),
            len(file.lines),
            outcomes_seen(file),
            2 * len(file.branches),
            handlers_run(file),
            len(file.handlers),
        )
        totals = [total + count for total, count in zip(totals, counts, strict=True)]
        table.add_row(file.path, *_ratios(counts))
    if len(files) > 1:
        table.add_row("total", *_ratios(tuple(totals)), style="bold")
    console.print(table)


def _ratios(counts: Sequence[int]) -> list[str]:
    return [_ratio(counts[index], counts[index + 1]) for index in range(0, len(counts), 2)]


def _ratio(hit: int, total: int) -> str:
    return f"{hit}/{total} ({100 * hit / total:.0f} %)" if total else "-"
