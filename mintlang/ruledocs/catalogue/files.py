"""Paths ``mint check`` could not check: a finding about a file, not about its text."""

from __future__ import annotations

from mintlang.ruledocs.model import FixSafety, Group, RuleDoc

GROUP = Group(
    "Files",
    "A path that `mint check` was given or found below a directory, and could not check. It is said on "
    "standard error and the check exits with 2 whatever the format; the machine-readable reports (json, "
    "sarif, github) also list it as a finding, as ruff lists E902.",
    (
        RuleDoc(
            "W120",
            catches="A path that was not checked: it does not exist, it cannot be read or listed (permission "
            "denied, a link loop, a dangling link), it is not Mint text (a NUL byte, placed where it is), or "
            "it is a program whose configuration file could not be read. The message is the reason.",
            why="This is not an error of the controller, and nothing in the program caused it: the file was "
            "never read as a program, so whatever it holds went unchecked. A report that left it out would "
            "look like a clean file.",
            example=None,
            manual=(),
            fix="Name a path that exists, make it readable, or leave the file out. `--select` and `--ignore` "
            "can leave W120 out of the report, as ruff's selection does E902; the path is still said on "
            "standard error and the exit status is still 2. No suppression comment reaches it: the file was "
            "not read as a program.",
            safety=FixSafety.NONE,
        ),
    ),
)
