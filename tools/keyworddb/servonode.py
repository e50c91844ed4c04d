"""A ServoNode 51 row for a keyword whose entry lists ServoNode 51 but whose attributes table prints none.

Twenty-eight entries tick ServoNode 51 under "Controllers Supported" and then print table rows for NextMove
and MintDrive only (WAIT, 000:17319-17333); without a row the tools knew neither the keyword's access nor its
range there. The row takes what the printed rows say alike, which is the keyword's rather than a
controller's:

- access and scaling (Read, Write, Command, Scaled), as the 89 tables naming both MintDrive and ServoNode 51
  agree on them (86 in one row); a table whose rows disagree gives no row (AUXENCODERWRAP ticks Scaled on
  MintDrive's row only, 000:6847-6848);
- the default, where the rows give the same number (1.0 and 1 for SCALE, 000:15783-15784);
- the range, where the rows print the same one, or the entry's text ties ServoNode 51 to MintDrive's
  (``_RANGE_AS_MINTDRIVE``). Ranges that follow a controller's inputs, outputs or word size (IMASK's
  0 ≤ x ≤ 262143 is MintDrive's 18 inputs, and ServoNode 51 has 6, 000:11900, 11931-11932) stay unknown.

Three tables print only a MintDrive row, for keywords only the two MME controllers have: TEMPERATURE,
which is read only, and AUXDAC and SPEEDDEMAND, whose values the entries give in percent of the output
and of the motor's rated speed (000:6686, 16259), whatever the controller. The flags the
tools do not read (Multi-Axis) are MintDrive's, the other controller with one axis (000:5613).
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Controller, Keyword

_SN51 = Controller.SERVONODE51

_RANGE_AS_MINTDRIVE = frozenset(
    {
        # The text gives MintDrive and ServoNode 51 one minimum, 40 ms (000:16807), MintDrive's row's;
        # the maximum, 8,000,000, is NextMove's too (000:16786-16787).
        "TIMEREVENT",
    }
)


def _number(default: str | None) -> float | str | None:
    """A default as a number where it is one, so that "1.0" and "1" agree."""
    try:
        return float(default.replace(",", "")) if default is not None else None
    except ValueError:
        return default


def _alike(values: list[object]) -> bool:
    return all(value == values[0] for value in values)


def _row(keyword: Keyword) -> Attributes | None:
    """The row ServoNode 51 takes from the printed ones, or None where their access disagrees."""
    rows = keyword.attributes
    mintdrive = keyword.attributes_for(Controller.MINTDRIVE)
    if mintdrive is None or not _alike([(row.read, row.write, row.command, row.scaled) for row in rows]):
        return None
    ranges = [row.range for row in rows]
    return replace(
        mintdrive,
        controllers=(_SN51,),
        default=mintdrive.default if _alike([_number(row.default) for row in rows]) else None,
        range=mintdrive.range if _alike(ranges) or keyword.name in _RANGE_AS_MINTDRIVE else None,
    )


def _with_row(keyword: Keyword) -> Keyword:
    """``keyword`` with its ServoNode 51 row, joined to a printed row it equals as the guide joins them."""
    if _SN51 not in keyword.controllers or not keyword.attributes or keyword.attributes_for(_SN51) is not None:
        return keyword
    row = _row(keyword)
    if row is None:
        return keyword
    rows = [
        replace(old, controllers=(*old.controllers, _SN51)) if replace(old, controllers=row.controllers) == row else old
        for old in keyword.attributes
    ]
    return replace(keyword, attributes=tuple(rows) if rows != list(keyword.attributes) else (*rows, row))


def with_servonode_rows(keywords: dict[str, Keyword]) -> dict[str, Keyword]:
    """Keywords ServoNode 51 has whose table prints no row for it, with the row the printed ones give."""
    return {name: _with_row(keyword) for name, keyword in keywords.items()}
