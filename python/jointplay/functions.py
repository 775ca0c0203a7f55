"""Functions of time for drivers and loads, as plain model-description data.

Each helper returns the dictionary the core reads; the value is in SI units
of whatever it prescribes (rad for a joint angle, m for a slider position,
N for a force, N m for a torque).
"""

from __future__ import annotations

import math
from collections.abc import Sequence


def constant(value: float) -> dict:
    """A constant value."""
    return {"kind": "constant", "value": float(value)}


def constant_speed(rate: float, initial: float = 0.0) -> dict:
    """``initial + rate * t``: a crank at constant speed (rate in rad/s) or a slider at constant velocity."""
    return {"kind": "constant_rate", "initial": float(initial), "rate": float(rate)}


def rpm(speed: float) -> float:
    """Revolutions per minute to rad/s."""
    return speed * 2.0 * math.pi / 60.0


def polynomial(coefficients: Sequence[float]) -> dict:
    """``sum c_k t^k``, constant term first."""
    return {"kind": "polynomial", "coefficients": [float(c) for c in coefficients]}


def cubic_step(t_start: float, t_end: float, value_start: float, value_end: float) -> dict:
    """Smooth step ``v0 + (v1 - v0) s^2 (3 - 2 s)``, ``s = (t - t0)/(t1 - t0)``, constant outside."""
    return {"kind": "cubic_step", "t_start": float(t_start), "t_end": float(t_end),
            "value_start": float(value_start), "value_end": float(value_end)}


def sine(amplitude: float, frequency: float, offset: float = 0.0, phase: float = 0.0) -> dict:
    """``offset + amplitude sin(2 pi frequency t + phase)``; frequency in Hz, phase in rad."""
    return {"kind": "sine", "offset": float(offset), "amplitude": float(amplitude),
            "frequency": float(frequency), "phase": float(phase)}


def table(times: Sequence[float], values: Sequence[float]) -> dict:
    """Natural cubic spline through ``(times, values)``; linear beyond the ends."""
    return {"kind": "table", "times": [float(t) for t in times], "values": [float(v) for v in values]}


def as_function(value: float | dict) -> dict:
    """A number becomes a constant function; a function dict is passed through."""
    if isinstance(value, dict):
        return value
    return constant(float(value))
