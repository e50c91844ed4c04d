"""The three Mint language generations the toolchain reads."""

from enum import StrEnum


class Dialect(StrEnum):
    V3 = "v3"  # Mint v3 (esMINT / MINT/3.28): read so that it can be migrated
    V4 = "v4"  # Mint v4: the reference guide MN1262 defines it
    MINTMT = "mintmt"  # MintMT, the multi-tasking Mint of the newer controllers: mintlang/MINTMT.md

    @property
    def modern(self) -> bool:
        """Whether the dialect is v4 or one built on it (MintMT): v4's keywords, constants and rules apply."""
        return self is not Dialect.V3
