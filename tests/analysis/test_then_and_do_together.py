"""``IF a = 1 THEN DO`` is told that THEN and DO are two forms of IF.

IF .. THEN runs the rest of its line (000:1573-1578); IF .. DO opens a block closed by ENDIF
(000:1594-1600). A new user writing both got "'DO' is a reserved keyword and cannot be used as a
variable", about a variable nobody wrote. The error stays the one the line gives (a keyword where a
statement's variable would be, #2006, 000:18935-18944); the message is what changes.
"""

from __future__ import annotations

import mintlang
from tests.analysis.placed import placed

SOURCE = "DIM a\nIF a = 1 THEN DO\n  a = 2\nENDIF\n"


def test_the_message_names_the_two_forms_of_if() -> None:
    assert placed(SOURCE, "code", "line", "column") == [("E2006", 2, 15)]
    (diagnostic,) = mintlang.check(SOURCE)
    assert diagnostic.message.endswith(
        "THEN and DO both follow the condition: IF .. DO opens a block closed by ENDIF, "
        "IF .. THEN runs the rest of its line"
    )
