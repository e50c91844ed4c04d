"""Each diagnostic links to its code's page: the base is the user's (``MINT_RULES_URL``, ``mint.rulesUrl``)
or the project's own pages."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main
from mintlang.ruledocs.links import (
    ENVIRONMENT_VARIABLE,
    configured_base,
    default_base,
    pages_in_repository,
    rule_url,
)

DOCS = Path(__file__).resolve().parents[2] / "docs" / "rules"


def test_a_folder_gets_the_page_of_the_code() -> None:
    assert rule_url("W103", "https://example.org/rules/") == "https://example.org/rules/W103.md"
    assert rule_url("W103", "https://example.org/rules") == "https://example.org/rules/W103.md"


def test_a_template_gets_the_code_in_its_place() -> None:
    assert rule_url("W103", "https://example.org/{code}.html") == "https://example.org/W103.html"


def test_no_base_or_an_undocumented_code_gets_no_link() -> None:
    assert rule_url("W103", None) is None and rule_url("W103", "") is None
    assert rule_url("W999", "https://example.org/") is None


def test_by_default_a_checkout_links_its_own_pages() -> None:
    base = default_base()
    assert base is not None
    page = rule_url("W103", base)
    assert page is not None and (page == (DOCS / "W103.md").as_uri() or page.endswith("/docs/rules/W103.md"))


def test_a_distribution_naming_its_repository_links_the_pages_there() -> None:
    urls = ["Homepage, https://example.org/mint", "Repository, https://github.com/example/mintlang/"]
    assert pages_in_repository(urls) == "https://github.com/example/mintlang/blob/main/docs/rules/"
    assert pages_in_repository(["Homepage, https://example.org/mint"]) is None


def test_the_user_sets_the_base_for_the_command_line(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(ENVIRONMENT_VARIABLE, "https://intranet/mint/{code}")
    assert configured_base() == "https://intranet/mint/{code}"
    monkeypatch.delenv(ENVIRONMENT_VARIABLE)
    assert configured_base() == default_base()


def test_sarif_rules_carry_their_help_uri_and_description(tmp_path: Path) -> None:
    program = tmp_path / "spare.mnt"
    program.write_text("DIM spare\nDIM b\nb = 1\nPRINT b\n")
    result = CliRunner(env={ENVIRONMENT_VARIABLE: "https://example.org/mint/"}).invoke(
        main, ["check", "--format", "sarif", str(program)]
    )
    (rule,) = json.loads(result.stdout)["runs"][0]["tool"]["driver"]["rules"]
    assert rule["id"] == "W103" and rule["helpUri"] == "https://example.org/mint/W103.md"
    assert rule["fullDescription"]["text"].startswith("A variable declared with DIM and never used")


def test_mint_rule_json_gives_the_page_of_the_code() -> None:
    result = CliRunner(env={ENVIRONMENT_VARIABLE: "https://example.org/mint/"}).invoke(
        main, ["rule", "E2016", "--format", "json"]
    )
    assert json.loads(result.stdout)["url"] == "https://example.org/mint/E2016.md"
