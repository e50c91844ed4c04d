"""Every message the adapter sends, checked against the protocol's published JSON schema.

``schema/debugAdapterProtocol.json`` is microsoft/debug-adapter-protocol's
schema (commit e34479c, MIT licence in ``schema/LICENSE``): a response is
checked against ``<Command>Response`` (``ErrorResponse`` when it failed), an
event against ``<Name>Event``.
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path
from typing import Any

from jsonschema import Draft4Validator

_SCHEMA = Path(__file__).with_name("schema") / "debugAdapterProtocol.json"


@cache
def _definitions() -> dict[str, Any]:
    return json.loads(_SCHEMA.read_text(encoding="utf-8"))["definitions"]


@cache
def _validator(name: str) -> Draft4Validator:
    return Draft4Validator({"$ref": f"#/definitions/{name}", "definitions": _definitions()})


def definition_of(message: dict[str, Any]) -> str:
    """The schema definition a message must match."""
    kind = message.get("type")
    if kind == "response":
        if not message.get("success"):
            return "ErrorResponse"
        command = str(message.get("command", ""))
        name = command[:1].upper() + command[1:] + "Response"
        return name if name in _definitions() else "Response"
    if kind == "event":
        event = str(message.get("event", ""))
        name = event[:1].upper() + event[1:] + "Event"
        return name if name in _definitions() else "Event"
    return "ProtocolMessage"


def problems(message: dict[str, Any]) -> list[str]:
    """Where ``message`` departs from the schema, one line per mistake (none when it conforms)."""
    name = definition_of(message)
    return [
        f"{name}: {error.message} at {list(error.absolute_path)}" for error in _validator(name).iter_errors(message)
    ]
