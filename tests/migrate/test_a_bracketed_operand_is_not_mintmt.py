"""A v3 program writing ``LOCATE (col + 1), 2`` is migrated, not left alone as MintMT.

``LOCATE x, y`` and ``LINE n, ...`` take expressions (001:9826-9846, 001:9730-9767) and no axes, so a
first operand in brackets is plain v3 (and v4, 000:13675, 000:13630). MintMT's round brackets after a
keyword give its axes or channel (``MOVER(0) = 10``, mintlang/MINTMT.md); after a keyword that has
none they are no MintMT form. Taken for one, they made the whole application "already mintmt":
nothing migrated, exit 0, and ``--check`` passed on Mint v3.
"""

from __future__ import annotations

from mintlang.migrate import migrate

SOURCE = 'col = 5\nLOCATE (col + 1), 2\nLINE (2), "speed ", SP.0\n'


def test_the_program_is_migrated_as_v3() -> None:
    result = migrate(SOURCE, only=["M-ABBR", "M-DIM"])
    assert not result.already_mintmt
    assert result.text == 'DIM col\ncol = 5\nLOCATE (col + 1), 2\nLINE (2), "speed ", SPEED.0\n'


def test_round_bracket_axes_still_show_mintmt() -> None:
    assert migrate("col = 5\nMOVER(0) = col\n").already_mintmt
