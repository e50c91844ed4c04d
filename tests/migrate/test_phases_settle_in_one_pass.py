"""The phases the engine runs once (``engine.SETTLED_IN_ONE_PASS``) reach their fixed point in
one pass: running them again on what they wrote asks for nothing, so skipping that confirming
pass changes no migration. Checked on every v3 corpus program (alone and with its
configuration file), the migration corpus (with and without the optional rules, which insert
too), and every keyword of both dialects written bare,
assigned (an AND and an OR), read, in a condition, with axes
and called, for a four-axis NextMove PCI and a one-axis
MintDrive."""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.migrate import engine, migrate
from mintlang.migrate.model import MigrationResult, Phase
from mintlang.migrate.rules import RULES
from tests.migrate.helpers import every_word

CORPUS = Path(__file__).parents[1] / "corpus"
OPTIONAL = tuple(rule.id for rule in RULES if rule.optional)


def _corpus() -> list[tuple[str, str | None]]:
    programs = sorted((CORPUS / "v3" / "programs").glob("*.mnt"))
    found: list[tuple[str, str | None]] = [(path.read_text(encoding="utf-8"), None) for path in programs]
    found += [
        (path.read_text(encoding="utf-8"), path.with_suffix(".cfg").read_text(encoding="utf-8"))
        for path in programs
        if path.with_suffix(".cfg").exists()
    ]
    for case in sorted(path for path in (CORPUS / "migrate").iterdir() if path.is_dir()):
        program, configuration = case / "input.mnt", case / "input.cfg"
        found.append(
            (
                program.read_text(encoding="utf-8") if program.exists() else "",
                configuration.read_text(encoding="utf-8") if configuration.exists() else None,
            )
        )
    return found


def _forms(word: str) -> str:
    """One program writing ``word`` in the places a rule of these phases looks at."""
    lines = (
        word,
        f"{word} = 1",
        f"{word} = a AND b OR c",
        f"x = {word}",
        f"IF {word} > 1 THEN {word} = {word} + 1",
        f"{word}.1 = 2 : y = {word}[0,1]",
        f"PRINT {word}(INT(a))",
    )
    return "".join(f"{line}\n" for line in lines)


def _confirmed(monkeypatch: pytest.MonkeyPatch, source: str, **options: object) -> MigrationResult:
    """The migration with every phase confirming its fixed point in a second pass."""
    with monkeypatch.context() as patched:
        patched.setattr(engine, "SETTLED_IN_ONE_PASS", frozenset())
        return migrate(source, **options)  # type: ignore[arg-type]


def test_the_one_pass_phases_are_the_word_rewriting_and_inserting_ones() -> None:
    assert frozenset({Phase.ABBREVIATIONS, Phase.RENAMES, Phase.INSERTIONS}) == engine.SETTLED_IN_ONE_PASS


@pytest.mark.parametrize("opt_in", [(), OPTIONAL], ids=["default rules", "optional rules too"])
@pytest.mark.parametrize(("program", "configuration"), _corpus())
def test_a_confirming_pass_changes_no_corpus_migration(
    monkeypatch: pytest.MonkeyPatch, program: str, configuration: str | None, opt_in: tuple[str, ...]
) -> None:
    once = migrate(program, config=configuration, opt_in=opt_in)
    assert once == _confirmed(monkeypatch, program, config=configuration, opt_in=opt_in)


@pytest.mark.parametrize("controller", ["nextmove-pci", "mintdrive"])
def test_a_confirming_pass_changes_no_keyword_form(monkeypatch: pytest.MonkeyPatch, controller: str) -> None:
    for word in every_word():
        source = _forms(word)
        once = migrate(source, controller=controller)
        assert once == _confirmed(monkeypatch, source, controller=controller), f"{word!r} on {controller}"


def test_the_context_phase_needs_its_confirming_pass(monkeypatch: pytest.MonkeyPatch) -> None:
    # S-ACCEL copies a value that M-PREC then brackets
    source = "ACCEL = a AND b OR c\n"
    confirmed = _confirmed(monkeypatch, source)
    monkeypatch.setattr(engine, "SETTLED_IN_ONE_PASS", engine.SETTLED_IN_ONE_PASS | {Phase.CONTEXT})
    assert migrate(source) != confirmed
