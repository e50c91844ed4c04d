"""``python -m mintlang``: the same as ``mint`` (``python -m mintlang test`` is ``mint test``)."""

from mintlang.cli import main

main()
