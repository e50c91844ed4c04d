"""The two Mint language generations the toolchain reads."""

from enum import StrEnum


class Dialect(StrEnum):
    V3 = "v3"  # Mint v3 (esMINT / MINT/3.28): read so that it can be migrated
    V4 = "v4"  # Mint v4: the reference guide MN1262 defines it
