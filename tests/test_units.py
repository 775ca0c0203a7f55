"""Quantities with units in model files: conversion to SI and messages for wrong input."""

import math

import pytest

from jointplay.units import UnitError, per_time, to_si


@pytest.mark.parametrize("raw, kind, si", [
    ("0.5 mm", "length", 0.5e-3),
    ("5000 rpm", "angular velocity", 5000 * 2 * math.pi / 60),
    ("207 GPa", "pressure", 207e9),
    ("0.034 kg m^2", "inertia", 0.034),
    ("1e-4 kg*m^2", "inertia", 1e-4),
    ("400 cP", "viscosity", 0.4),
    ("24 ms", "time", 0.024),
    ("90 deg", "angle", math.pi / 2),
    ("1 rev", "angle", 2 * math.pi),
    ("60 rpm", "frequency", 1.0),
    ("2 N m", "torque", 2.0),
    ("10 N s/m", "damping", 10.0),
    ("50 N m/rad", "rotational stiffness", 50.0),
    ("50 %", "dimensionless", 0.5),
    (0.3, "mass", 0.3),
    (3, "length", 3.0),
    ("0.25", "length", 0.25),
])
def test_quantities_convert_to_si(raw, kind, si):
    assert to_si(raw, kind) == pytest.approx(si, rel=1e-12)


def test_bare_numbers_are_si_exactly():
    assert to_si(0.0005, "length") == 0.0005
    assert to_si("0.0005 m", "length") == 0.0005


@pytest.mark.parametrize("raw, kind, message", [
    ("5 kg", "length", "must be a length (e.g. \"0.5 mm\"), got '5 kg', which is a mass"),
    ("10 m/s", "length", "must be a length (e.g. \"0.5 mm\"), got '10 m/s', which is a velocity"),
    ("3 foo", "length", "has an unknown unit 'foo', got '3 foo'"),
    ("1 mm +", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '1 mm +'"),
    ("10 Hz", "angular velocity", "Hz is ambiguous for an angular speed; write rpm, rev/s or rad/s, got '10 Hz'"),
    ("3 deg", "dimensionless", "must be a plain number (e.g. \"0.9\"), got an angular quantity '3 deg'"),
    (True, "length", "must be a number or a string with a unit (e.g. \"0.5 mm\"), got true"),
    ([1, 2], "length", "must be a number or a string with a unit (e.g. \"0.5 mm\"), got [1, 2]"),
    ("nan mm", "length", "must be finite, got nan mm"),
    (float("inf"), "length", "must be finite, got inf m"),
])
def test_wrong_quantities_are_refused_with_a_message(raw, kind, message):
    with pytest.raises(UnitError) as info:
        to_si(raw, kind)
    assert str(info.value) == message


def test_nothing_in_a_quantity_is_executed():
    with pytest.raises(UnitError):
        to_si("__import__('os').system('true')", "length")


def test_rates_of_an_angle_are_angular_velocities():
    assert per_time("angle", 1).name == "angular velocity"
    assert to_si("2 rad/s^2", per_time("angle", 2)) == 2.0
    assert to_si("3 N/s", per_time("force", 1)) == 3.0
