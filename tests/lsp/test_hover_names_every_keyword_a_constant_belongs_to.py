"""A constant's hover names every keyword whose entry lists it among its values: the guide gives one constant
to several keywords, and naming only the first (``_emCRASH_STOP`` "of LIMITMODE" on a ``SOFTLIMITMODE`` line)
tells the reader it belongs elsewhere."""

from __future__ import annotations

import pytest

from mintlang.dialect import Dialect
from mintlang.lsp.describe import constant


@pytest.mark.parametrize(
    ("name", "hover"),
    [
        pytest.param(
            "_emCRASH_STOP",
            "**_emCRASH_STOP** = `2` — predefined constant of LIMITMODE and SOFTLIMITMODE",
            id="a limit mode: LIMITMODE's table (000:13486) and SOFTLIMITMODE's (000:16050)",
        ),
        pytest.param(
            "_emSMART_MODE",
            "**_emSMART_MODE** = `4` — predefined constant of SOFTLIMITMODE",
            id="a mode only SOFTLIMITMODE's table gives (000:16057)",
        ),
        pytest.param(
            "_RELAY0",
            "**_RELAY0** = `1000` — predefined constant of DRIVEENABLEOUTPUT and GLOBALERROROUTPUT",
            id="the relay: DRIVEENABLEOUTPUT's table (000:9362) and GLOBALERROROUTPUT's (000:11007)",
        ),
        pytest.param(
            "_erABORT",
            "**_erABORT** = `1` — predefined constant of AXISERROR and AXISSTATUS",
            id="bit 0 of AXISERROR's table (000:6980) and of AXISSTATUS's (000:7221)",
        ),
        pytest.param(
            "_tmRS232",
            "**_tmRS232** = `1` — predefined constant of INKEY, SERIALBAUD and TERMINAL",
            id="a port: INKEY's table (000:12155), SERIALBAUD's, constant first (000:15851), TERMINAL's (000:16695)",
        ),
    ],
)
@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.MINTMT], ids=str)
def test_a_constant_is_shown_with_every_keyword_that_lists_it(name: str, hover: str, dialect: Dialect) -> None:
    assert constant(name, dialect) == hover
