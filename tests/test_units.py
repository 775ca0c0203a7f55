"""Quantities with units in model files: conversion to SI and messages for wrong input."""

import math
import subprocess
import sys

import pytest

from jointplay.units import UnitError, declare_unit, model_file_units, per_time, registry, to_si


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
    ("20 cm^2", "area", 20e-4),
    ("3117 mm^2", "area", 3117e-6),
    ("0.1 L", "volume", 1e-4),
    ("250 cm^3", "volume", 250e-6),
    ("10 L/min", "volume flow", 10e-3 / 60),
    ("3 m^3/h", "volume flow", 3 / 3600),
    ("200 bar", "pressure", 200e5),
    ("1.5 GPa", "pressure", 1.5e9),
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
    ("20 bar", "area", "must be an area (e.g. \"20 cm^2\"), got '20 bar', which is a pressure"),
    ("1 L", "area", "must be an area (e.g. \"20 cm^2\"), got '1 L', which is a volume"),
    ("10 L", "volume flow", "must be a volume flow (e.g. \"10 L/min\"), got '10 L', which is a volume"),
    ("3 foo", "length", "has an unknown unit 'foo', got '3 foo'"),
    ("1 mm +", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '1 mm +'"),
    ("10 Hz", "angular velocity", "Hz is ambiguous for an angular speed; write rpm, rev/s or rad/s, got '10 Hz'"),
    ("3 deg", "dimensionless", "must be a plain number (e.g. \"0.9\"), got an angular quantity '3 deg'"),
    (True, "length", "must be a number or a string with a unit (e.g. \"0.5 mm\"), got true"),
    ([1, 2], "length", "must be a number or a string with a unit (e.g. \"0.5 mm\"), got [1, 2]"),
    ("nan mm", "length", "must be finite, got nan mm"),
    (float("inf"), "length", "must be finite, got inf"),
    (float("nan"), "length", "must be finite, got nan"),
    ("1e999 m", "length", "must be finite, got 1e999 m"),
    (10**400, "mass", "must be finite, got 100000000000... (an integer of 401 digits)"),
    ("9" * 400 + " kg", "mass", "must be finite, got '9999999999999999999999999999999999999999'... (403 characters)"),
    ("10**10**8 kg", "mass", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '10**10**8 kg'"),
    ("2 m**99**99**99", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '2 m**99**99**99'"),
    ("1 m^100", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '1 m^100'"),
    ("2 * 3 mm", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '2 * 3 mm'"),
    ("1 mm; 2", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '1 mm; 2'"),
    ("mm", "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got 'mm'"),
    ("1 m" + " m" * 60, "length", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), "
                                  "got '1 m m m m m m m m m m m m m m m m m m m '... (123 characters)"),
    ("x" * 1200, "length", "is too long to be a quantity (1200 characters), "
                           "got 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx'... (1200 characters)"),
])
def test_wrong_quantities_are_refused_with_a_message(raw, kind, message):
    with pytest.raises(UnitError) as info:
        to_si(raw, kind)
    assert str(info.value) == message


@pytest.mark.parametrize("raw, kind, si", [
    ("1 kg m**2", "inertia", 1.0),
    ("3 1/s", "frequency", 3.0),
    ("2 (N m)/rad", "rotational stiffness", 2.0),
    ("-4.5E-3 m", "length", -4.5e-3),
    ("+.5 mm", "length", 0.5e-3),
    ("5 \u00b5m", "length", 5e-6),
])
def test_unit_text_allows_products_quotients_powers_and_parentheses(raw, kind, si):
    assert to_si(raw, kind) == pytest.approx(si, rel=1e-12)


def test_pint_quantities_are_converted_from_any_registry():
    import pint

    other = pint.UnitRegistry()
    assert to_si(other.Quantity(0.5, "mm"), "length") == pytest.approx(5e-4, rel=1e-12)
    assert to_si(registry().Quantity(2, "rpm"), "angular velocity") == pytest.approx(4 * math.pi / 60, rel=1e-12)
    with pytest.raises(UnitError, match="must be a length .* which is a mass"):
        to_si(other.Quantity(1, "kg"), "length")


def test_bare_numbers_in_a_model_file_need_a_unit_unless_declared_or_zero():
    with model_file_units({}):
        with pytest.raises(UnitError) as info:
            to_si(10, "length")
        assert str(info.value) == 'a bare number needs a unit, e.g. "10 mm" (or declare [units] length = "mm"), got 10'
        with pytest.raises(UnitError, match=r'e.g. "0.5 kg" \(or declare \[units\] mass = "kg"\), got 0.5'):
            to_si("0.5", "mass")
        with pytest.raises(UnitError, match=r'^a bare number needs a unit, e.g. "2 N/s\^1", got 2$'):
            to_si(2, per_time("force", 1))  # a rate of a force: no [units] key
        assert to_si(0, "length") == 0.0
        assert to_si(0.9, "dimensionless") == 0.9
    with model_file_units({"length": declare_unit("length", "mm"), "angle": declare_unit("angle", "deg")}):
        assert to_si(10, "length") == pytest.approx(0.01, rel=1e-12)
        assert to_si(90, "angle") == pytest.approx(math.pi / 2, rel=1e-12)
        assert to_si("3 m", "length") == 3.0
        with pytest.raises(UnitError, match="declare \\[units\\] velocity"):
            to_si(1, "velocity")  # a declared length and time do not make a velocity
        with pytest.raises(UnitError, match='e.g. "2 cm\\^2" \\(or declare \\[units\\] area = "cm\\^2"\\)'):
            to_si(2, "area")  # nor a length an area
    hydraulic = {"area": declare_unit("area", "cm^2"), "volume": declare_unit("volume", "L"),
                 "volume_flow": declare_unit("volume_flow", "L/min")}
    with model_file_units(hydraulic):
        assert to_si(20, "area") == pytest.approx(20e-4, rel=1e-12)
        assert to_si(0.1, "volume") == pytest.approx(1e-4, rel=1e-12)
        assert to_si(10, "volume flow") == pytest.approx(10e-3 / 60, rel=1e-12)
    assert to_si(10, "length") == 10.0  # outside a model file: SI


@pytest.mark.parametrize("key, unit, message", [
    ("length", "kg", "must be a length (e.g. \"0.5 mm\"), got 'kg', which is a mass"),
    ("length", "2 mm", "must be a unit without a number, e.g. \"mm\", got '2 mm'"),
    ("length", 3, "must be a unit of length as a string, e.g. \"mm\", got 3"),
    ("length", "m**2**40", "cannot be read as a number with a unit (e.g. \"0.5 mm\"), got 'm**2**40'"),
])
def test_declared_units_are_checked(key, unit, message):
    with pytest.raises(UnitError) as info:
        declare_unit(key, unit)
    assert str(info.value) == message


def test_import_jointplay_does_not_import_pint():
    code = "import sys, jointplay; print('pint' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_nothing_in_a_quantity_is_executed():
    with pytest.raises(UnitError):
        to_si("__import__('os').system('true')", "length")


def test_rates_of_an_angle_are_angular_velocities():
    assert per_time("angle", 1).name == "angular velocity"
    assert to_si("2 rad/s^2", per_time("angle", 2)) == 2.0
    assert to_si("3 N/s", per_time("force", 1)) == 3.0
