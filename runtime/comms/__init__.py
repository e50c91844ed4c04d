"""Talking to a host: the comms array (``array``), host packets (``packets``) and the TCP host port (``server``).

``PortUnavailable`` is here rather than in ``server`` so that ``mint-run`` can report it without importing
the server's sockets and thread, which only a run with a host port uses.
"""


class PortUnavailable(Exception):
    """The host port cannot be opened; the message says which port and why."""
