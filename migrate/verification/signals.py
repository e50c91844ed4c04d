"""The outputs and the axes of the two runs, compared at every millisecond within a tube.

A sample of one run matches when the other run shows that value (within the
tolerance) somewhere up to ``tolerance.TIME_MS`` either side. A run that ended
holds its last state; an axis one controller lacks stands still at 0. Besides
the first sample outside the tube, each signal says whether it shows the same
values in the same order (for an axis: it comes to rest at the same positions),
in which case the difference is one of timing only.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Sequence

from mintlang.migrate.verification import tolerance
from mintlang.migrate.verification.model import Divergence
from mintlang.migrate.verification.runs import AxisTrace, Recording

_STILL = AxisTrace()  # an axis the controller does not have


def _at(series: Sequence[float], t: int) -> float:
    """The sample at ``t``; a run that stopped holds its last one, one that never ran shows 0."""
    return series[min(t, len(series) - 1)] if series else 0.0


def _window(series: Sequence[float], t: int) -> list[float]:
    return [_at(series, u) for u in range(max(0, t - tolerance.TIME_MS), t + tolerance.TIME_MS + 1)]


Close = Callable[[float, float, int], bool]  # (v3 value, v4 value, time): within the tolerance


def _outside(v3: Sequence[float], v4: Sequence[float], until: int, close: Close) -> int | None:
    """The first millisecond at which either run's sample lies outside the other's tube."""
    for t in range(until + 1):
        a, b = _at(v3, t), _at(v4, t)
        if close(a, b, t):
            continue
        low3, high3 = min(window := _window(v3, t)), max(window)
        low4, high4 = min(window := _window(v4, t)), max(window)
        if not (close(min(max(b, low3), high3), b, t) and close(a, min(max(a, low4), high4), t)):
            return t
    return None


def _checked(v3: Recording, v4: Recording, until: int) -> int:
    """The last millisecond whose tube is known: a run cut off at ``until`` says nothing of the milliseconds
    after it, so its last ``TIME_MS`` samples have only half a window and are not held against the other's."""
    return until if v3.closed and v4.closed else until - tolerance.TIME_MS


def _changes(series: Sequence[int], until: int) -> list[int]:
    """The values a word takes in turn, from the 0 both controllers power up with."""
    values = [0]
    for t in range(min(until, len(series) - 1) + 1):
        if series[t] != values[-1]:
            values.append(series[t])
    return values


def _plateaus(series: Sequence[float], until: int, close: Callable[[float, float], bool]) -> list[float]:
    """The values the signal holds (within ``close``) for longer than the time tolerance, in order: where an
    axis rests, the speeds it cruises at."""
    held: list[float] = []
    start = 0
    last = min(until, len(series) - 1)
    for t in range(last + 2):
        if t <= last and close(series[start], series[t]):
            continue
        if t - start > 2 * tolerance.TIME_MS and (not held or not close(held[-1], series[start])):
            held.append(series[start])
        start = t
    return held


def _same_order(v3: list[float], v4: list[float], close: Callable[[float, float], bool]) -> bool:
    return len(v3) == len(v4) and all(close(a, b) for a, b in zip(v3, v4, strict=True))


def _divergence(what: str, v3: Recording, v4: Recording, t: int, shown: tuple[str, str], **extra: object) -> Divergence:
    return Divergence(
        time_ms=t,
        what=what,
        v3=shown[0],
        v4=shown[1],
        v3_line=v3.places[min(t, v3.last)] if v3.last >= 0 else None,
        v4_line=v4.places[min(t, v4.last)] if v4.last >= 0 else None,
        **extra,  # type: ignore[arg-type]
    )


def _word(
    name: str, v3: Recording, v4: Recording, words: tuple[array[int], array[int]], until: int
) -> list[Divergence]:
    """OUT (a bit at a time) or the relay."""
    series3, series4 = words
    t = _outside(series3, series4, _checked(v3, v4, until), lambda a, b, _: a == b)
    if t is None:
        return []
    a, b = int(_at(series3, t)), int(_at(series4, t))
    timing_only = _changes(series3, until) == _changes(series4, until)
    if name == "relay":
        return [_divergence("relay", v3, v4, t, (str(a), str(b)), timing_only=timing_only)]
    bit = ((a ^ b) & -(a ^ b)).bit_length() - 1 if a != b else 0
    shown = (str(a >> bit & 1), str(b >> bit & 1))
    return [_divergence(f"OUT bit {bit}", v3, v4, t, shown, detail=f"OUT {a} / {b}", timing_only=timing_only)]


def _axis(number: int, v3: Recording, v4: Recording, until: int) -> list[Divergence]:
    trace3 = v3.axes[number] if number < len(v3.axes) else _STILL
    trace4 = v4.axes[number] if number < len(v4.axes) else _STILL
    reference = trace3 if trace3.scale else trace4

    def scale(t: int) -> float:
        return _at(reference.scale, t) or 1.0

    def near(a: float, b: float, t: int) -> bool:
        return abs(a - b) <= tolerance.position(scale(t))

    def near_velocity(a: float, b: float, t: int) -> bool:
        return abs(a - b) <= tolerance.velocity(a, b, scale(t))

    def same_order(series: str, close: Close) -> bool:
        def held(a: float, b: float) -> bool:
            return close(a, b, until)

        left, right = getattr(trace3, series), getattr(trace4, series)
        return _same_order(_plateaus(left, until, held), _plateaus(right, until, held), held)

    found = []
    for quantity, close, series in (("position", near, "pos"), ("velocity", near_velocity, "vel")):
        t = _outside(getattr(trace3, series), getattr(trace4, series), _checked(v3, v4, until), close)
        if t is not None:
            shown = (f"{_at(getattr(trace3, series), t):.10g}", f"{_at(getattr(trace4, series), t):.10g}")
            found.append((t, quantity, shown))
    if not found:
        return []
    t, quantity, shown = min(found)
    timing_only = same_order("pos", near) and same_order("vel", near_velocity)
    return [_divergence(f"axis {number} {quantity}", v3, v4, t, shown, timing_only=timing_only)]


def differences(v3: Recording, v4: Recording, until: int) -> list[Divergence]:
    """The first difference of OUT, of the relay and of each axis's position or velocity, up to ``until``."""
    found = _word("OUT", v3, v4, (v3.outputs, v4.outputs), until)
    found += _word("relay", v3, v4, (v3.relay, v4.relay), until)
    for number in range(max(len(v3.axes), len(v4.axes))):
        found += _axis(number, v3, v4, until)
    return found
