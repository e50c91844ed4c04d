"""The terminals a keyword addressed by a serial port takes after its dot (COMMSMODE, SERIALBAUD).

The terminal numbers are the _tm constants (000:2033-2042); these keywords apply to the RS232 and RS485 ports
only. A number that names no terminal is #35, a terminal that is not a serial port #36 (000:18637-18646).
``mint check`` reports either where the number is a constant, ``mint-run`` when the line runs.
"""

from __future__ import annotations

from functools import cache

from mintlang.keyworddb import database

SERIAL_PORT_KEYWORDS = frozenset({"COMMSMODE", "SERIALBAUD"})
_SERIAL_TERMINALS = ("_TMRS232", "_TMRS485")


@cache
def _terminals() -> dict[str, int]:
    return {name: int(record.value) for name, record in database().constants.items() if name.startswith("_TM")}


def serial_port_error(keyword: str, terminal: int) -> tuple[int, str] | None:
    """The error number and its cause when ``keyword`` is given ``terminal`` after its dot; None for a serial port."""
    terminals = _terminals()
    if terminal in {terminals[name] for name in _SERIAL_TERMINALS if name in terminals}:
        return None
    if terminal in terminals.values():
        return 36, f"{keyword} applies to the serial terminals (_tmRS232, _tmRS485) only"
    return 35, f"there is no terminal {terminal}"
