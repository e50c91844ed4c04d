"""A program's Startup block runs however the configuration file before it ends (004:128-134, MT-7): the
configuration runs first and the program after it (000:269-270), the program beginning with its Startup block."""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source

PROGRAM = 'Print "main"\nStartup\n  Print "startup"\nEnd Startup\nPrint "end"\n'


@pytest.mark.parametrize(
    "configuration",
    [
        'Print "cfg"\n',  # runs off its end
        'Print "cfg"\nEnd\n',  # ends with END
        'Print "cfg"\nIf 0 Then Print "never"\n',  # its last line's IF skips to the line after it
        'Print "cfg"\nLoop\n  Exit\nEnd Loop\n',  # its last block is left to the line after it
    ],
)
def test_the_startup_block_runs_between_the_configuration_and_the_program(configuration: str) -> None:
    result = run_source(PROGRAM, config=configuration, dialect="mintmt")
    assert result.terminal == "cfg\nstartup\nmain\nend\n"
