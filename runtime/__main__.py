"""``python -m mintlang.runtime``: the same as ``mint-run``."""

from mintlang.runtime.cli import main

main()
