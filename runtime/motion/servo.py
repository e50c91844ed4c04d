"""The NextMove PIDVFA servo law (spec SL-1..SL-7), run once per servo tick on each closed-loop axis.

Demand = KP·e + KD·Δe - KV·v + KF·V + KI·Σe + KA·a, in percent of DAC full
scale (spec SL-3 RC), then clamped to ±DACLIMITMAX. Every quantity is per
servo sample, as the manual defines them: ``e`` and ``Σe`` in counts, ``Δe``,
``v`` and ``V`` in counts/sample, ``a`` in counts/sample².
"""

from __future__ import annotations

from enum import IntEnum

from mintlang.records import record


class KintMode(IntEnum):
    """When the integrator accumulates (``KINTMODE``, spec SL-5 RC)."""

    NEVER = 0
    ALWAYS = 1
    AT_REST = 2  # only while the demand velocity is 0
    SMART = 3  # only at constant, non-zero demand velocity


@record
class ServoGains:
    """One axis's loop parameters, defaulted as the ``DEFAULT`` keyword leaves them (spec SL-2, SL-4, SL-6)."""

    kprop: float = 0.0
    kint: float = 0.0
    kintlimit: float = 100.0
    kintmode: int = KintMode.ALWAYS
    kderiv: float = 0.0
    kvel: float = 0.0
    kvelff: float = 0.0
    kaccel: float = 0.0
    daclimitmax: float = 100.0


DEFAULT_GAINS = ServoGains()


class ServoLoop:
    """The per-axis state of the law: the error sum and the previous error.

    ``gains`` is replaced whole when a gain keyword is written, so the
    integrator and derivative history survive retuning during a move.
    """

    __slots__ = ("_error_sum", "_previous_error", "gains")

    def __init__(self, gains: ServoGains = DEFAULT_GAINS) -> None:
        self.gains = gains
        self._error_sum = 0.0
        self._previous_error = 0.0

    @property
    def integral(self) -> float:
        """The integral term KI·Σe currently applied, within ±KINTLIMIT."""
        gains = self.gains
        return max(-gains.kintlimit, min(gains.kintlimit, gains.kint * self._error_sum))

    def reset(self) -> None:
        """Forget the history, as when servoing (re)starts with demand = measured (spec SL-10)."""
        self._error_sum = 0.0
        self._previous_error = 0.0

    def step(
        self,
        demand_position: float,
        demand_velocity: float,
        demand_acceleration: float,
        measured_position: float,
        measured_velocity: float,
    ) -> float:
        """Run one servo sample and return the DAC command in percent of full scale.

        The integrator is cleared while KINT or KINTMODE is 0, so re-enabling
        it starts from nothing; in the conditional modes it holds its value
        while the condition is false, so a load it carries (gravity) is not
        dropped during motion. The error sum is clamped so that KI·Σe never
        exceeds KINTLIMIT (anti-windup, spec SL-4 RC).
        """
        gains = self.gains
        error = demand_position - measured_position
        kint = gains.kint
        integral = 0.0
        if kint == 0.0 or gains.kintmode == KintMode.NEVER:
            self._error_sum = 0.0
        else:
            mode = gains.kintmode
            if (
                mode == KintMode.ALWAYS
                or (mode == KintMode.AT_REST and demand_velocity == 0.0)
                or (mode == KintMode.SMART and demand_velocity != 0.0 and demand_acceleration == 0.0)
            ):
                bound = gains.kintlimit / kint
                self._error_sum = max(-bound, min(bound, self._error_sum + error))
            integral = self.integral
        demand = (
            gains.kprop * error
            + gains.kderiv * (error - self._previous_error)
            - gains.kvel * measured_velocity
            + gains.kvelff * demand_velocity
            + gains.kaccel * demand_acceleration
            + integral
        )
        self._previous_error = error
        limit = gains.daclimitmax
        return max(-limit, min(limit, demand))

    def settled(self, demand_position: float, measured_position: float, output: float) -> bool:
        """Whether every sample from now on, with demand and axis at rest at these positions, outputs ``output``
        and leaves the history as it is: only then may the simulator skip samples.

        On a stalled axis the derivative and the integrator keep acting on a steady error for a while. The
        answer comes from ``step`` itself, run on a copy, so it cannot drift from the law: one sample that
        changes nothing means none ever will.
        """
        probe = ServoLoop(self.gains)
        probe._error_sum, probe._previous_error = self._error_sum, self._previous_error
        return (
            probe.step(demand_position, 0.0, 0.0, measured_position, 0.0) == output
            and probe._error_sum == self._error_sum
            and probe._previous_error == self._previous_error
        )
