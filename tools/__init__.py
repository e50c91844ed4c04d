"""Developer tools of the Mint toolchain (not shipped with the package)."""
