"""``python -m tools.keyworddb [--seeds DIR] [--check] [--compact]``: regenerate the keyword database
(``--compact``: only ``database.bin``, from the committed JSON, after MintMT's files are edited by hand)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from tools.keyworddb.build import build
from tools.keyworddb.write import differing, write_all, write_compact

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "mintlang" / "keyworddb" / "data"
DEFAULT_SEEDS = REPO.parent / "shared" / "seeds"
DEFAULT_SPEC = REPO.parent / "shared" / "spec"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tools.keyworddb", description=__doc__)
    parser.add_argument("--seeds", type=Path, default=DEFAULT_SEEDS, help="directory of the manual seeds")
    parser.add_argument("--spec", type=Path, default=DEFAULT_SPEC, help="directory of the migration specs")
    parser.add_argument("--check", action="store_true", help="exit 1 if the committed data is out of date")
    parser.add_argument("--compact", action="store_true", help="write only database.bin from the committed JSON")
    args = parser.parse_args(argv)
    if args.compact:
        write_compact(DATA)
        return 0
    try:
        outputs = build(args.seeds, args.spec)
    except OSError as error:  # a checkout not beside ../shared: say which file, not a traceback
        parser.error(f"cannot read {error.filename}: {error.strerror} (give --seeds DIR and --spec DIR)")
    if args.check:
        stale = differing(outputs, DATA)
        for name in stale:
            print(f"out of date: {name}", file=sys.stderr)
        return 1 if stale else 0
    write_all(outputs, DATA)
    return 0


if __name__ == "__main__":
    sys.exit(main())
