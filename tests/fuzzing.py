"""How hard the generated-input tests try: ``MINT_FUZZ_SCALE=10`` runs ten times more cases."""

from __future__ import annotations

import os


def examples(count: int) -> int:
    return count * int(os.environ.get("MINT_FUZZ_SCALE", "1"))
