"""mint-run: the reference runtime that executes Mint programs against simulated axes, I/O and a host."""
