"""A move type the guide names as if it were a keyword is offered the keyword that starts it.

The guide's See-also lists and AXISMODE's table call the hold-to-analog move HOLDTOANALOG (000:6209, 7157,
8929), but no keyword has that name: the move is started by HTA (000:11676), which replaced v3's
HOLDTOANALOGUE (000:11366-11367). A user who writes the list's word gets error 3007 (000:19111-19116), and the
message offers HTA rather than nothing.
"""

from __future__ import annotations

import mintlang


def test_holdtoanalog_is_offered_hta() -> None:
    (found,) = [
        d for d in mintlang.check_application("HOLDTOANALOG.0 = 0\n", dialect="v4").program if d.code == "E3007"
    ]
    assert found.message == "Keyword not defined: 'HOLDTOANALOG' is not a keyword (did you mean 'HTA'?)"
