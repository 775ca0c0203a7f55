"""ISO 286 grades, deviations and fits (jointplay.study.iso286), checked against the standard.

Sources of the expected numbers:
- ISO 286-1:2010 Table 1 (standard tolerances) and its Annex formulas (standard tolerance factor i,
  the fundamental deviation formulas);
- ISO 286-2:2010, tables of limit deviations of holes and shafts (values typed here from the
  standard's tables, independently of the transcription in iso286_tables);
- paper 003 ("A Study on the Dynamic Responses and Joints Clearance Optimization of the Planar
  Operating Mechanism of High-Voltage Circuit Breaker") section 4.4 and Table 3 for the grade bands.
"""

from __future__ import annotations

import math

import pytest

from jointplay.errors import ModelError
from jointplay.study import iso286
from jointplay.study import iso286_tables as tables

UM = 1e-6
MM = 1e-3


# --- standard tolerances ---------------------------------------------------------------------------------

# (grade, nominal mm, IT um) from ISO 286-1:2010 Table 1; ranges are "above a up to and including b".
TABLE_1_VALUES = [
    ("IT6", 12, 11), ("IT7", 12, 18), ("IT8", 12, 27),
    ("IT1", 2, 0.8), ("IT5", 100, 15), ("IT9", 50, 62), ("IT10", 60, 120), ("IT11", 250, 290),
    ("IT12", 400, 570), ("IT13", 1000, 1400), ("IT14", 3150, 5400), ("IT18", 3150, 33000),
    ("IT16", 700, 5000), ("IT3", 1200, 24), ("IT7", 18, 18), ("IT7", 18.001, 21), (4, 30, 6),
]


@pytest.mark.parametrize(("grade", "nominal_mm", "it_um"), TABLE_1_VALUES)
def test_tolerance_matches_iso_286_1_table_1(grade, nominal_mm, it_um):
    assert iso286.tolerance(grade, nominal_mm * MM) == pytest.approx(it_um * UM, rel=1e-12)


def test_each_grade_from_it6_is_ten_times_the_grade_five_below():
    """ISO 286-1 Annex: from IT6 upwards the standard tolerances are multiplied by 10 at each fifth step.
    Table 1 keeps one departure: above 3 up to 6 mm, IT6 = 8 um but IT11 = 75 um."""
    departures = {(upper, n) for upper, row in tables.STANDARD_TOLERANCES for n in range(6, 14)
                  if row[n + 5 - 1] != 10 * row[n - 1]}
    assert departures == {(6, 6)}


def test_tolerances_grow_with_grade_and_size():
    rows = [row for _, row in tables.STANDARD_TOLERANCES]
    for row in rows:
        assert all(a < b for a, b in zip(row, row[1:]))
    for finer, coarser in zip(rows, rows[1:]):
        assert all(a <= b for a, b in zip(finer, coarser))


def test_table_agrees_with_the_tolerance_factor_formula():
    """ISO 286-1 Annex: ITn = k i, i = 0.45 D^(1/3) + 0.001 D [um], D the geometric mean of the range [mm],
    k = 7, 10, 16, 25, 40, 64, 100 for IT5..IT11. The tabulated values are rounded and smoothed: above 3 mm
    and up to 500 mm each lies within max(1 um, 3 %) of k i. (The first range, up to 3 mm, departs by up to
    15 % and is left out, see docs/theory/iso-286-fits.md.)"""
    multipliers = {5: 7, 6: 10, 7: 16, 8: 25, 9: 40, 10: 64, 11: 100}
    lower = 0.0
    for upper, row in tables.STANDARD_TOLERANCES:
        if 3 < upper <= 500:
            mean = math.sqrt(lower * upper)
            factor = 0.45 * mean ** (1 / 3) + 0.001 * mean
            for n, k in multipliers.items():
                assert abs(row[n - 1] - k * factor) <= max(1.0, 0.03 * k * factor), (upper, n)
        lower = upper


# --- fundamental deviations --------------------------------------------------------------------------------

def _formula_cases():
    """(letter, ISO 286-1 Annex formula of the deviation [um] from D [mm], sizes it is checked over)."""
    return [
        ("d", lambda d: -16 * d ** 0.44, 3), ("e", lambda d: -11 * d ** 0.41, 3),
        ("f", lambda d: -5.5 * d ** 0.41, 3), ("g", lambda d: -2.5 * d ** 0.34, 3),
        ("n", lambda d: 5 * d ** 0.34, 3),
        ("a", lambda d: -(265 + 1.3 * d) if d <= 120 else -3.5 * d, 0),
        ("b", lambda d: -(140 + 0.85 * d) if d <= 160 else -1.8 * d, 0),
        ("c", lambda d: -(95 + 0.8 * d), 40),
    ]


@pytest.mark.parametrize(("letter", "formula", "above_mm"), _formula_cases())
def test_shaft_deviations_agree_with_the_annex_formulas(letter, formula, above_mm):
    """Each tabulated deviation lies within max(1 um, 5 %) of its formula at the range's geometric mean
    (the first range uses D from 1 mm, as the standard does)."""
    table = tables.SHAFT_UPPER_DEVIATIONS.get(letter) or tables.SHAFT_LOWER_DEVIATIONS[letter]
    lower = 0.0
    for upper, value in table:
        if upper > above_mm:
            expected = formula(math.sqrt(max(lower, 1.0) * upper))
            assert abs(value - expected) <= max(1.0, 0.05 * abs(expected)), (letter, upper)
        lower = upper


def test_shaft_m_is_the_difference_of_it7_and_it6():
    # ISO 286-1 Annex: ei of m = IT7 - IT6 above 3 mm (up to 3 mm the table gives +2 um).
    for upper, value in tables.SHAFT_LOWER_DEVIATIONS["m"][1:]:
        row = dict(tables.STANDARD_TOLERANCES)[upper]
        assert value == row[6] - row[5]
    assert tables.SHAFT_LOWER_DEVIATIONS["m"][0] == (3, 2)


# (class, nominal mm, lower um, upper um) from the tables of ISO 286-2:2010.
ISO_286_2_VALUES = [
    ("g6", 12, -17, -6), ("f7", 25, -41, -20), ("e8", 50, -89, -50), ("h6", 10, -9, 0),
    ("p6", 12, 18, 29), ("c11", 12, -205, -95), ("d9", 40, -142, -80), ("js7", 12, -9, 9),
    ("k6", 20, 2, 15), ("m6", 20, 8, 21), ("n6", 20, 15, 28), ("r6", 20, 28, 41), ("s6", 20, 35, 48),
    ("k9", 20, 0, 52), ("a11", 12, -400, -290), ("b11", 100, -440, -220), ("cd6", 5, -54, -46),
    ("H7", 12, 0, 18), ("F7", 25, 20, 41), ("G7", 12, 6, 24), ("E8", 50, 50, 89), ("D9", 40, 80, 142),
    ("A11", 12, 290, 400), ("JS7", 12, -9, 9),
    ("K7", 12, -12, 6), ("K6", 8, -7, 2), ("K8", 12, -19, 8), ("K7", 2, -10, 0),
    ("M7", 12, -18, 0), ("M8", 12, -25, 2), ("M7", 2, -12, -2), ("M6", 300, -41, -9),
    ("N7", 12, -23, -5), ("N9", 12, -43, 0), ("N7", 2, -14, -4),
    ("P6", 12, -26, -15), ("P7", 12, -29, -11), ("R7", 12, -34, -16), ("S7", 12, -39, -21), ("P8", 12, -45, -18),
]


@pytest.mark.parametrize(("symbol", "nominal_mm", "lower_um", "upper_um"), ISO_286_2_VALUES)
def test_limit_deviations_match_iso_286_2(symbol, nominal_mm, lower_um, upper_um):
    zone = iso286.limit_deviations(symbol, nominal_mm * MM)
    assert zone.lower == pytest.approx(lower_um * UM, abs=1e-12)
    assert zone.upper == pytest.approx(upper_um * UM, abs=1e-12)


@pytest.mark.parametrize("letter", ["K", "M", "N", "P", "R", "S"])
def test_special_rule_makes_hole_and_shaft_basis_fits_alike(letter):
    """ISO 286-1: Δ is chosen so that Hn/x(n-1) and Xn/h(n-1) give the same clearances."""
    for nominal_mm in (5, 12, 40, 100, 200, 450):
        # K's rule pairs with k4..k7, the grades for which shaft k has its tabulated ei.
        for n in range(5 if letter == "K" else 4, tables.SPECIAL_RULE_MAX_GRADE[letter] + 1):
            if (letter, n) == ("M", 6) and 250 < nominal_mm <= 315:
                continue
            hole_basis = iso286.parse_fit(f"{nominal_mm} H{n}/{letter.lower()}{n - 1}")
            shaft_basis = iso286.parse_fit(f"{nominal_mm} {letter}{n}/h{n - 1}")
            assert shaft_basis.clearance_min == pytest.approx(hole_basis.clearance_min, abs=1e-12)
            assert shaft_basis.clearance_max == pytest.approx(hole_basis.clearance_max, abs=1e-12)


# --- fits --------------------------------------------------------------------------------------------------

# (fit, hole lower/upper um, shaft lower/upper um, clearance min/max um), ISO 286-2:2010.
FITS = [
    ("12 H7/g6", (0, 18), (-17, -6), (6, 35)),
    ("25 H7/f7", (0, 21), (-41, -20), (20, 62)),
    ("50 H8/e8", (0, 39), (-89, -50), (50, 128)),
    ("10 H7/h6", (0, 15), (-9, 0), (0, 24)),
]


@pytest.mark.parametrize(("text", "hole", "shaft", "clearance"), FITS)
def test_clearance_fits(text, hole, shaft, clearance):
    fit = iso286.parse_fit(text, "joints.E.fits")
    assert (fit.hole.lower, fit.hole.upper) == pytest.approx((hole[0] * UM, hole[1] * UM), abs=1e-12)
    assert (fit.shaft.lower, fit.shaft.upper) == pytest.approx((shaft[0] * UM, shaft[1] * UM), abs=1e-12)
    assert (fit.clearance_min, fit.clearance_max) == pytest.approx((clearance[0] * UM, clearance[1] * UM), abs=1e-12)
    assert fit.kind == "clearance"
    assert fit.radial_clearance("min") == pytest.approx(clearance[0] * UM / 2, abs=1e-12)
    assert fit.radial_clearance("max") == pytest.approx(clearance[1] * UM / 2, abs=1e-12)
    assert fit.radial_clearance("mean") == pytest.approx((clearance[0] + clearance[1]) * UM / 4, abs=1e-12)


def test_fit_text_variants():
    assert iso286.parse_fit("12H7/g6").clearance_max == pytest.approx(35 * UM)
    assert iso286.parse_fit(" 12 mm H7 / g6 ").clearance_min == pytest.approx(6 * UM)
    assert iso286.parse_fit("12.5 H7/g6").nominal == pytest.approx(12.5 * MM)


def test_interference_fit_is_refused_as_a_clearance():
    fit = iso286.parse_fit("12 H7/p6", "joints.E.fits")
    assert (fit.clearance_min, fit.clearance_max) == pytest.approx((-29 * UM, 0.0), abs=1e-12)
    assert fit.kind == "interference"
    with pytest.raises(ModelError) as info:
        fit.radial_clearance("mean")
    problem = info.value.problems[0]
    assert problem.location == "joints.E.fits"
    assert "'12 H7/p6' is an interference fit" in problem.message
    assert "a clearance joint needs a clearance fit" in problem.message


def test_transition_fit_is_refused_as_a_clearance():
    fit = iso286.parse_fit("12 H7/k6")  # shaft +1/+12: clearance -12..+17 um
    assert fit.kind == "transition"
    with pytest.raises(ModelError, match="is a transition fit"):
        fit.radial_clearance("max")


# --- grade bands (paper 003) -------------------------------------------------------------------------------

def test_grade_bands_read_as_paper_003_at_12_mm():
    # paper 003 section 4.4: at 12 mm "IT6 16-22 um, IT7 22-36 um, IT8 36-54 um".
    assert iso286.grade_band("IT6", 12 * MM) == pytest.approx((16 * UM, 22 * UM))
    assert iso286.grade_band("IT7", 12 * MM) == pytest.approx((22 * UM, 36 * UM))
    assert iso286.grade_band("IT8", 12 * MM) == pytest.approx((36 * UM, 54 * UM))
    assert iso286.grade_range("IT6", "IT8", 0.012) == pytest.approx((16e-6, 54e-6))
    assert iso286.grade_band("IT1", 12 * MM) == pytest.approx((0.0, 2.4 * UM))


@pytest.mark.parametrize(("clearance_um", "grade"), [(26.7, "IT7"), (18.9, "IT6"), (29.5, "IT7"), (17.6, "IT6")])
def test_grade_of_paper_003_table_3_clearances(clearance_um, grade):
    # paper 003 Table 3: optimal clearances of joints E, F, G, H and their assembly tolerance levels.
    assert iso286.grade_of_clearance(clearance_um * UM, 12 * MM) == grade


def test_band_ends_belong_to_the_lower_grade():
    assert iso286.grade_of_clearance(22 * UM, 12 * MM) == "IT6"
    assert iso286.grade_of_clearance(22.001 * UM, 12 * MM) == "IT7"
    assert iso286.grade_of_clearance(2 * 11e-6, 0.012) == "IT6"
    assert iso286.grade_of_clearance(0.0, 12 * MM) == "IT1"
    assert iso286.grade_of_clearance(2 * 2700 * UM, 12 * MM) == "IT18"


def test_grade_of_clearance_outside_every_band():
    with pytest.raises(ModelError, match="lies in no grade band"):
        iso286.grade_of_clearance(-1 * UM, 12 * MM)
    with pytest.raises(ModelError, match="lies in no grade band"):
        iso286.grade_of_clearance(5401 * UM, 12 * MM)


# --- errors ------------------------------------------------------------------------------------------------

def _message(call) -> str:
    with pytest.raises(ModelError) as info:
        call()
    return str(info.value)


def test_bad_grades():
    assert "grades run from IT1 to IT18, got IT19" in _message(lambda: iso286.tolerance("IT19", 12 * MM))
    assert "got IT0" in _message(lambda: iso286.grade_band("IT0", 12 * MM))
    assert "such as \"IT7\", got 'IT7.5'" in _message(lambda: iso286.tolerance("IT7.5", 12 * MM))
    assert "got True" in _message(lambda: iso286.tolerance(True, 12 * MM))
    assert "from the finer to the coarser, got IT8 to IT6" in _message(
        lambda: iso286.grade_range("IT8", "IT6", 12 * MM))
    assert "does not use IT14" in _message(lambda: iso286.tolerance("IT14", 1 * MM))


def test_bad_nominal_sizes():
    assert "above 0 and at most 3150 mm, got 0 mm" in _message(lambda: iso286.tolerance("IT7", 0.0))
    assert "got -12 mm" in _message(lambda: iso286.grade_band("IT7", -0.012))
    assert "got 3151 mm" in _message(lambda: iso286.tolerance("IT7", 3.151))
    assert iso286.tolerance("IT7", 3.15) == pytest.approx(210 * UM)
    assert "at most 500 mm, got 600 mm" in _message(lambda: iso286.parse_fit("600 H7/g6"))


def test_bad_fit_texts():
    message = _message(lambda: iso286.parse_fit("12 H7-g6", "joints.E.fits"))
    assert message.startswith("joints.E.fits: ")
    assert "such as \"12 H7/g6\", got '12 H7-g6'" in message
    assert "hole first in capitals" in _message(lambda: iso286.parse_fit("12 g6/H7"))
    assert "got 'H7/g6'" in _message(lambda: iso286.parse_fit("H7/g6"))


def test_unsupported_letters_list_the_supported_ones():
    message = _message(lambda: iso286.parse_fit("12 H7/u6"))
    assert "unsupported fundamental deviation 'u'" in message
    assert "shafts a, b, c, cd, d, e, ef, f, fg, g, h, js, k, m, n, p, r, s" in message
    assert "holes are A, B, C, CD, D, E, EF, F, FG, G, H, JS, K, M, N, P, R, S" in message
    assert "unsupported fundamental deviation 'J'" in _message(lambda: iso286.limit_deviations("J7", 12 * MM))
    assert "K is supported up to IT8" in _message(lambda: iso286.limit_deviations("K9", 12 * MM))
    assert "only up to 10 mm" in _message(lambda: iso286.limit_deviations("cd6", 12 * MM))
    assert "does not use a or A" in _message(lambda: iso286.limit_deviations("a11", 1 * MM))


def test_bad_clearance_statistic():
    assert "one of min, mean, max, got 'median'" in _message(
        lambda: iso286.parse_fit("12 H7/g6").radial_clearance("median"))
