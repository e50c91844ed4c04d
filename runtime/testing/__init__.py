"""``mint test``: find the Mint programs that carry their own checks, run each in the simulator, report.

A test is a program with ``REM @expect`` lines, or one with a scenario file
beside it (``cell.scenario.toml`` for ``cell.mnt``). Each runs as ``mint-run
--expect`` would (its configuration file paired as everywhere), in parallel,
and passes when ``mint-run`` would exit 0.
"""
