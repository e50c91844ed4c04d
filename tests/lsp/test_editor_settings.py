"""The editor's ``mint.*`` settings are read with the types the extension's schema gives them
(``vscode-ext/package.json``): a value of another type, hand-written in settings.json, keeps the setting
as it was, as the extension itself does, rather than being converted into something else."""

from __future__ import annotations

import pytest

from mintlang.lsp.workspace import Settings

BEFORE = Settings.from_options({"mint": {"debounceMs": 300, "rulesUrl": "https://example.org/{code}"}})


@pytest.mark.parametrize(
    ("options", "attribute", "expected"),
    [
        pytest.param({"debounceMs": 0}, "debounce_ms", 0, id="debounce-zero-checks-at-once"),
        pytest.param({"debounceMs": 250}, "debounce_ms", 250, id="debounce-whole-milliseconds"),
        pytest.param({"debounceMs": 250.0}, "debounce_ms", 250, id="debounce-whole-number-written-as-float"),
        pytest.param({"debounceMs": True}, "debounce_ms", 300, id="debounce-true-is-not-1ms"),
        pytest.param({"debounceMs": -5}, "debounce_ms", 300, id="debounce-below-the-schema-minimum-0"),
        pytest.param({"debounceMs": 1.5}, "debounce_ms", 300, id="debounce-fraction-is-not-an-integer"),
        pytest.param({"debounceMs": "200"}, "debounce_ms", 300, id="debounce-string-is-not-an-integer"),
        pytest.param({"rulesUrl": ["https://x"]}, "rules_url", "https://example.org/{code}", id="rules-url-list"),
        pytest.param({"rulesUrl": 5}, "rules_url", "https://example.org/{code}", id="rules-url-number"),
        pytest.param({"configPairing": 5}, "config_pairing", "<name>.cfg", id="pairing-number"),
        pytest.param({"configPairing": ""}, "config_pairing", "", id="pairing-empty-means-none"),
    ],
)
def test_a_setting_is_read_with_its_schema_type(options: dict[str, object], attribute: str, expected: object) -> None:
    assert getattr(Settings.from_options({"mint": options}, BEFORE), attribute) == expected
