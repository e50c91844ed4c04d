"""Read syntax facts off an entry's "Format" and "Dot Parameters" sections.

The format lines are the only place the guide shows how a keyword is written,
so addressing, the glued channel form (``INx``) and the bracketed parameters
are all derived from them here.
"""

from __future__ import annotations

import re

from mintlang.keyworddb.model import Addressing

_PROSE = re.compile(r"^(?:[A-Z][a-z]*\s+[a-z]{2,}|[A-Z][a-z]+[ ,.:]|[a-z]{2,}(?! =)\b)")
_CONNECTOR = re.compile(r"^or\b")
_WHERE = re.compile(r"\s*\(where [^)]*\)")
_AXIS_FORMAT = re.compile(r"\[\s*(?:axes|axis)|\.axis\b")
_CHANNEL_FORMAT = re.compile(r"\.(?:channel|terminal|source|x)\b|\[\s*(?:bank|channel)\b")


def clean_formats(lines: list[str]) -> tuple[str, ...]:
    """The syntax lines of a Format section, stopping where explanatory prose begins."""
    formats: list[str] = []
    for line in lines:
        if _CONNECTOR.match(line):
            continue
        if _PROSE.match(line) and not line.startswith(("v =", "value =", "angle =")):
            break
        if formats and formats[-1].count("{") > formats[-1].count("}"):
            formats[-1] = f"{formats[-1]} {line}"
        else:
            formats.append(line)
    return tuple(_WHERE.sub("", line).strip() for line in formats)


def addressing(names: tuple[str, ...], formats: tuple[str, ...], dot: list[str]) -> Addressing:
    """Axis when the syntax takes ``[axes]``/``.axis``; channel for ``.channel`` or ``KWx``."""
    first_dot = dot[0].lower() if dot else ""
    if first_dot.startswith("ax") or any(_AXIS_FORMAT.search(f) for f in formats):
        return Addressing.AXIS
    if (
        first_dot.startswith(("channel", "terminal", "source"))
        or any(_CHANNEL_FORMAT.search(f) for f in formats)
        or channel_suffix(names, formats)
    ):
        return Addressing.CHANNEL
    return Addressing.NONE


def channel_suffix(names: tuple[str, ...], formats: tuple[str, ...]) -> bool:
    """True when a format glues the channel number to the name (``ADCx``, ``#INx``)."""
    return any(re.search(rf"(?<![\w#]){re.escape(name)}x\b", f) for name in names for f in formats)


def _parameter_name(text: str, optional: bool) -> str:
    name = re.sub(r"\s+", "_", text.strip().strip("<>").strip()).lower()
    return f"{name}?" if optional else name


def parameters(names: tuple[str, ...], formats: tuple[str, ...]) -> tuple[str, ...]:
    """Names of the bracketed arguments, ``name?`` for the ones the format puts in braces."""
    pattern = re.compile(r"(?<![\w#])(?:" + "|".join(map(re.escape, names)) + r")\s*\((?P<args>[^)]*)\)")
    for line in formats:
        if match := pattern.search(line):
            result: list[str] = []
            for part in re.finditer(r"\{(?P<opt>[^}]*)\}|(?P<req>[^,{}]+)", match["args"]):
                optional = part["opt"] is not None
                for item in (part["opt"] if optional else part["req"]).split(","):
                    if item.strip():
                        result.append(_parameter_name(item, optional))
            return tuple(result)
    return ()


def writes_keyword(names: tuple[str, ...], formats: tuple[str, ...]) -> bool:
    """True when a format assigns to the keyword (``KW[axes] = ...``, ``COMMS(...) = ...``)."""
    pattern = re.compile(r"^(?:" + "|".join(map(re.escape, names)) + r")\b(?:\s*[\[(.][^=]*)?\s*=(?!=)")
    return any(pattern.match(f) for f in formats)


def reads_keyword(names: tuple[str, ...], formats: tuple[str, ...]) -> bool:
    """True when a format reads the keyword as a value (``v = KW...``)."""
    pattern = re.compile(r"=\s*(?:" + "|".join(map(re.escape, names)) + r")\b")
    return any(pattern.search(f) for f in formats)


def is_function(names: tuple[str, ...], formats: tuple[str, ...]) -> bool:
    """A value-returning call with bracketed arguments that is never assigned to."""
    call = re.compile(r"(?:=|PRINT)\s*(?:" + "|".join(map(re.escape, names)) + r")\s*\(")
    return any(call.search(f) for f in formats) and not writes_keyword(names, formats)
