"""A code's documentation as a Markdown page (``docs/rules/``, and ``mint rule`` on a terminal) and as
a JSON record (``mint rule --format json``)."""

from __future__ import annotations

import re

from mintlang.controllers import profile
from mintlang.manual.places import place
from mintlang.ruledocs.model import Example, FixSafety, RuleDoc

_CITATION = re.compile(r"(v[34]):(\d+)")
_SHOWN_LINES = 12  # a longer example shows its head and tail: the checked text repeats one pattern
_SAFETY = {  # what a fix of each kind is, for the page
    FixSafety.SAFE: "Safe: `mint check --fix` applies it; the program does what it plainly meant to.",
    FixSafety.UNSAFE: "Unsafe: it guesses at the intent or changes what runs. "
    "`--unsafe-fixes` applies it; review the change.",
}


def sections(rule: RuleDoc) -> list[str]:
    """The guides' sections the documentation rests on, as a reader of the printed guides finds them
    (``Mint v4 guide §12.4 Mint Error Codes and Messages``), each once."""
    found: list[str] = []
    for citation in rule.manual:
        dialect, line = _CITATION.fullmatch(citation).groups()  # type: ignore[union-attr]
        where = place(dialect, int(line)).full
        if where not in found:
            found.append(where)
    return found


def _shown(text: str) -> str:
    lines = text.splitlines()
    if len(lines) <= _SHOWN_LINES:
        return text.rstrip("\n")
    head, tail = lines[: _SHOWN_LINES - 4], lines[-3:]
    return "\n".join([*head, f"⋮ ({len(lines) - len(head) - len(tail)} more lines like these)", *tail])


def _example(example: Example | None, code: str) -> list[str]:
    """The example section of a page: the text reported and the text not; none for a code about a file."""
    if example is None:
        return []
    return [
        "## Example",
        *([context] if (context := _context(example)) else []),
        f"Reported as {code}:",
        f"```mint\n{_shown(example.before)}\n```",
        "Not reported:",
        f"```mint\n{_shown(example.after)}\n```",
    ]


def _context(example: Example) -> str:
    checked = []
    if example.controller is not None:
        title = profile(example.controller).title
        checked.append(f"Checked for {title} (`--controller {example.controller}`).")
    if example.with_program is not None:
        program = example.with_program.rstrip("\n")
        checked.append(f"The example is a configuration file, checked with the program `{program}`.")
    return " ".join(checked)


def markdown(rule: RuleDoc, group: str) -> str:
    """The page of ``rule`` (in ``group``)."""
    cited = sections(rule)
    parts = [
        f"# {rule.code}: {rule.title}",
        f"*{rule.severity.capitalize()}* · {group}",
        "## What it catches",
        rule.catches,
        "## Why it matters",
        rule.why,
        *_example(rule.example, rule.code),
        "## Fix",
        *([rule.fix, _SAFETY[rule.safety]] if rule.safety is not FixSafety.NONE else [f"No automatic fix. {rule.fix}"]),
        *(["## In the manual", "\n".join(f"- {where}" for where in cited)] if cited else []),
    ]
    return "\n\n".join(parts) + "\n"


def record(rule: RuleDoc, group: str, url: str | None) -> dict[str, object]:
    """What ``mint rule --format json`` prints for ``rule``."""
    example = rule.example
    return {
        "code": rule.code,
        "title": rule.title,
        "severity": rule.severity,
        "group": group,
        "catches": rule.catches,
        "why": rule.why,
        "example": None
        if example is None
        else {
            "before": example.before,
            "after": example.after,
            "controller": example.controller,
            "with_program": example.with_program,
        },
        "fix": {"description": rule.fix, "safety": rule.safety.value},
        "manual": sections(rule),
        "url": url,
    }
