"""``mint rule``: what a code means, as its page in ``docs/rules/`` says it.

Exit status: 0, or 2 for a code the checker never reports (one line, with the code it
resembles) or no code at all.
"""

from __future__ import annotations

import json
import sys
from typing import TYPE_CHECKING

import click

from mintlang.cli.options import HELP_OPTIONS, format_option, version_option

if TYPE_CHECKING:
    from mintlang.ruledocs import RuleDoc

_USAGE_ERROR = 2


# The documentation and rich (for Markdown on a terminal) are imported when a code is asked for:
# they cost a third of mint's start-up, which every other command would pay.


def _documented(code: str, command: str) -> RuleDoc:
    """The documentation of ``code``; an unknown code ends ``command`` (the one the user ran) with exit 2."""
    from mintlang.analysis.suggestions import closest, did_you_mean  # noqa: PLC0415 - see above
    from mintlang.ruledocs import find, rules  # noqa: PLC0415

    found = find(code)
    if found is not None:
        return found
    meant = closest(code.strip().upper(), [rule.code for rule in rules()], likeness=0.6)
    hint = f" ({did_you_mean(meant)})" if meant is not None else " (mint rule --all lists them)"
    click.echo(f"{command}: '{code}' is not a code the checker reports{hint}", err=True)
    sys.exit(_USAGE_ERROR)


@click.command(context_settings=HELP_OPTIONS)
@click.argument("codes", nargs=-1)
@click.option("--all", "every", is_flag=True, help="Every code the checker reports, group by group.")
@format_option(["text", "json"], "Markdown text (formatted on a terminal) or JSON.")
@version_option("mint rule")
def rule(codes: tuple[str, ...], every: bool, output_format: str) -> None:
    """Explain codes (E2016, E2, W103): what each catches, why it matters, an example before and after,
    the guides' sections and its fix."""
    if not codes and not every:
        raise click.UsageError("name a code (mint rule E2016) or give --all")
    from mintlang.ruledocs import rules  # noqa: PLC0415 - see above

    chosen = rules() if every else tuple(_documented(code, "mint rule") for code in codes)
    _show(chosen, output_format, single=len(chosen) == 1 and not every)


def explain(code: str, command: str) -> None:
    """What ``mint rule CODE`` prints, for another command (``mint check --explain``) that names itself in an error."""
    _show((_documented(code, command),), "text", single=True)


def _show(chosen: tuple[RuleDoc, ...], output_format: str, *, single: bool) -> None:
    """The pages of ``chosen`` (Markdown, formatted on a terminal) or their JSON records; one alone unlisted."""
    from mintlang.ruledocs import group_of  # noqa: PLC0415 - see above
    from mintlang.ruledocs.links import configured_base, rule_url  # noqa: PLC0415
    from mintlang.ruledocs.render import markdown, record  # noqa: PLC0415

    if output_format == "json":
        base = configured_base()
        records = [record(rule, group_of(rule).name, rule_url(rule.code, base)) for rule in chosen]
        click.echo(json.dumps(records[0] if single else records, indent=2, ensure_ascii=False))
        return
    pages = [markdown(rule, group_of(rule).name) for rule in chosen]
    from rich.console import Console  # noqa: PLC0415 - see above
    from rich.markdown import Markdown  # noqa: PLC0415

    console = Console(highlight=False)
    if console.is_terminal:
        for page in pages:
            console.print(Markdown(page))
    else:
        click.echo("\n".join(pages), nl=False)
