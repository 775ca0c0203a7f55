"""Functions of time for drivers and loads, as plain model-description data.

Each helper returns the dictionary the core reads. A value is a number in SI
units of whatever it prescribes (rad for a joint angle, m for a slider
position, N for a force, N m for a torque), or a string with a unit or a pint
Quantity (``constant_speed("5000 rpm")``, ``cubic_step("0 ms", "30 ms", 0,
"90 deg")``): those are kept as written and converted when the function is
attached to a driver or a load, where the kind of the prescribed quantity is
known (the builder validates them as a model file's function table).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from . import parameters as p

_RATE, _SINE = p.FUNCTIONS["constant_rate"], p.FUNCTIONS["sine"]


def _value(x: Any) -> Any:
    """A number as a float (SI); a string with a unit or a pint Quantity as it is, for the builder."""
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return float(x)
    return x


def constant(value: float) -> dict:
    """A constant value."""
    return {"kind": "constant", "value": _value(value)}


def constant_speed(rate: float, initial: float = _RATE.default("initial")) -> dict:
    """``initial + rate * t``: a crank at constant speed (rate in rad/s) or a slider at constant velocity."""
    return {"kind": "constant_rate", "initial": _value(initial), "rate": _value(rate)}


def rpm(speed: float) -> float:
    """Revolutions per minute to rad/s."""
    return speed * 2.0 * math.pi / 60.0


def polynomial(coefficients: Sequence[float]) -> dict:
    """``sum c_k t^k``, constant term first."""
    return {"kind": "polynomial", "coefficients": [_value(c) for c in coefficients]}


def cubic_step(t_start: float, t_end: float, value_start: float, value_end: float) -> dict:
    """Smooth step ``v0 + (v1 - v0) s^2 (3 - 2 s)``, ``s = (t - t0)/(t1 - t0)``, constant outside."""
    return {"kind": "cubic_step", "t_start": _value(t_start), "t_end": _value(t_end),
            "value_start": _value(value_start), "value_end": _value(value_end)}


def sine(amplitude: float, frequency: float, offset: float = _SINE.default("offset"),
         phase: float = _SINE.default("phase")) -> dict:
    """``offset + amplitude sin(2 pi frequency t + phase)``; frequency in Hz, phase in rad."""
    return {"kind": "sine", "offset": _value(offset), "amplitude": _value(amplitude),
            "frequency": _value(frequency), "phase": _value(phase)}


def table(times: Sequence[float], values: Sequence[float]) -> dict:
    """Natural cubic spline through ``(times, values)``; linear beyond the ends."""
    return {"kind": "table", "times": [_value(t) for t in times], "values": [_value(v) for v in values]}


def speed_ramp(final_rate: float, ramp_time: float) -> dict:
    """A spin-up: at rest until t = 0, the rate rises smoothly to ``final_rate`` (value per second) over
    ``ramp_time`` [s] and stays there (Simo and Vu-Quoc 1986)."""
    return {"kind": "speed_ramp", "ramp_time": _value(ramp_time), "final_rate": _value(final_rate)}


def as_function(value: Any) -> dict:
    """A number (or a string with a unit, or a pint Quantity) becomes a constant function; a function
    dict is passed through."""
    if isinstance(value, dict):
        return value
    return constant(value)
