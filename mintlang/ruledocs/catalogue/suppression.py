"""The checker's own comments: suppressions that silence nothing."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

GROUP = Group(
    "Suppression comments",
    "A REM comment can silence codes the author has looked at: `REM mint: ignore[W103]` on its line, "
    "`REM mint: ignore-file[W103]` in its file (in MintMT, `' mint: ignore[W103]` too). A suppression that "
    "silences nothing hides the next real "
    "finding, so it is reported.",
    (
        RuleDoc(
            "W117",
            catches="A code named in a suppression comment that silences nothing on its line (or, for "
            "ignore-file, in its file): the finding is gone, the code is not checked, or it is no code; and a "
            "comment that names no code at all (`ignore[]`, or a list no `]` closes, `ignore[W103`).",
            why="A suppression outlives the finding it was written for; left in place, it would silence "
            "the next such finding on that line without anyone looking at it.",
            example=Example(
                before="DIM count : REM mint: ignore[W1O3]\ncount = 1\nPRINT count\n",  # a letter O: no code
                after="DIM count\ncount = 1\nPRINT count\n",
            ),
            manual=("v4:15497",),
            fix="Remove the code from the comment, or the comment when it names no other code. For a code "
            "the run does not check (a hint, without --select I) the removal is unsafe: the comment may serve a "
            "wider selection, such as the editor's. A list left open has no fix: only its author knows where it ends.",
            safety=FixSafety.SAFE,
        ),
    ),
)
