"""A Mint v3 controller reads host packets only once ``COMMSON`` has run: until then every byte is terminal
input, the ENQ that ends a read being Ctrl-E, which ends the program (001:737, 5856, 13215-13220). mint-run
does not simulate ``COMMSON``, so it has no v3 card to answer a host: a v3 run refuses host packets, from a
scenario or a host port, rather than answer them as a Mint v4 card does (000:2298-2302) with ACK, NAK or data."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.invoking import mint_run, write

REFUSED = "a Mint v3 controller reads host packets only after COMMSON, which mint-run does not simulate"


def test_a_directive_host_packet_is_refused_at_its_line(tmp_path: Path) -> None:
    program = write(tmp_path, "p.mnt", 'WAIT = 20\nREM @sim host write 1 "7" at 10\n')
    result = mint_run("--dialect", "v3", program)
    assert result.exit_code == 2
    assert f"p.mnt:2:5: {REFUSED}" in result.stderr


def test_a_scenario_file_host_packet_is_refused_at_its_table(tmp_path: Path) -> None:
    stimulus = write(tmp_path, "host.toml", "[[host]]\nread = 1\nat_ms = 10\n")
    result = mint_run("--dialect", "v3", write(tmp_path, "p.mnt", "WAIT = 20\n"), "--stimulus", stimulus)
    assert result.exit_code == 2
    assert f"host.toml:1: {REFUSED}" in result.stderr


def test_a_host_port_is_a_usage_error(tmp_path: Path) -> None:
    result = mint_run("--dialect", "v3", write(tmp_path, "p.mnt", "WAIT = 20\n"), "--host-port", "0")
    assert result.exit_code == 2
    assert REFUSED in result.stderr
