"""``python -m tools.keyworddb [--seeds DIR] [--check]``: regenerate the keyword database."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from tools.keyworddb.build import build
from tools.keyworddb.write import differing, write_all

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "mintlang" / "keyworddb" / "data"
DEFAULT_SEEDS = REPO.parent / "shared" / "seeds"
DEFAULT_SPEC = REPO.parent / "shared" / "spec"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tools.keyworddb", description=__doc__)
    parser.add_argument("--seeds", type=Path, default=DEFAULT_SEEDS, help="directory of the manual seeds")
    parser.add_argument("--spec", type=Path, default=DEFAULT_SPEC, help="directory of the migration specs")
    parser.add_argument("--check", action="store_true", help="exit 1 if the committed data is out of date")
    args = parser.parse_args(argv)
    outputs = build(args.seeds, args.spec)
    if args.check:
        stale = differing(outputs, DATA)
        for name in stale:
            print(f"out of date: {name}", file=sys.stderr)
        return 1 if stale else 0
    write_all(outputs, DATA)
    return 0


if __name__ == "__main__":
    sys.exit(main())
