"""Talking to a host: the comms array (``array``), host packets (``packets``) and the TCP host port (``server``).

``PortUnavailable`` is here rather than in ``server`` so that ``mint-run`` can report it without importing
the server's sockets and thread, which only a run with a host port uses.
"""


class PortUnavailable(Exception):
    """The host port cannot be opened; the message says which port and why."""


V3_READS_NO_HOST = "a Mint v3 controller reads host packets only after COMMSON, which mint-run does not simulate"
"""Why a v3 run takes no host packets: before COMMSON they are terminal input, and a read's ENQ is the Ctrl-E
that ends the program (001:737, 5856, 13215-13220)."""
