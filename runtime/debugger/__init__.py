"""``mint-dap``: a Debug Adapter Protocol server that debugs Mint programs on the simulator, forwards and backwards.

One module per job: ``framing`` (Content-Length messages), ``launch`` (the
program, its configuration and scenario), ``breakpoints``, ``stepping`` (the
points of a run and the plans that stop at one), ``checkpoints`` (the states
going back restores), ``history`` (what a re-run repeats), ``execution`` (the
simulation thread), ``variables`` and
``evaluation`` (what the editor shows of the paused controller), ``session``
(the requests) and ``cli``.
"""
