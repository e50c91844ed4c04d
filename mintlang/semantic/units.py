"""The files of an application."""

from __future__ import annotations

from enum import StrEnum


class Unit(StrEnum):
    """Which file of an application a name lives in."""

    CONFIGURATION = "configuration"
    PROGRAM = "program"
