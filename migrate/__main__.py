"""``python -m mintlang.migrate``: the same as ``mint-migrate``."""

from mintlang.migrate.cli import main

main()
