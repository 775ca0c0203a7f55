"""ISO 286-1 tolerance grades and fits, and the radial clearance they give a clearance joint.

Everything here is in SI: sizes, tolerances, deviations and clearances in metres. The tables (in
micrometres, with their source) are ``iso286_tables``; the theory and the conventions are
``docs/theory/iso-286-fits.md``.

- :func:`tolerance`: the standard tolerance ITn at a nominal size (ISO 286-1:2010 Table 1);
- :func:`limit_deviations`: the lower and upper deviations of a tolerance class such as ``"g6"`` or
  ``"H7"`` (Tables 2 and 3, holes from shafts by the standard's rules);
- :func:`parse_fit`: a fit such as ``"12 H7/g6"``, with its diametral clearances and the radial
  clearance of a clearance joint (:meth:`Fit.radial_clearance`);
- :func:`grade_band`, :func:`grade_range`, :func:`grade_of_clearance`: the diametral clearance
  bands of grades as paper 003 reads them (the sliding fits H(n-1)/h(n-1) to Hn/hn).

Bad input raises :class:`~jointplay.errors.ModelError` naming the value.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..errors import ModelError, Problem
from . import iso286_tables as tables

#: Micrometres per metre (the tables are in micrometres).
UM_PER_M = 1e6
#: Millimetres per metre (nominal sizes are tabulated in millimetres).
MM_PER_M = 1e3
#: Largest nominal size of Table 1 [mm].
LARGEST_NOMINAL_MM = tables.STANDARD_TOLERANCES[-1][0]
#: Nominal sizes are compared with the table's limits after rounding to this many decimals of a mm,
#: so that 0.018 m is 18 mm exactly.
MM_DECIMALS = 9
#: Slack [um] when a clearance is compared with a band's end (float round-off of m -> um).
BAND_SLACK_UM = 1e-6

SHAFT_LETTERS = ("a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h", "js", "k", "m", "n", "p", "r", "s")
HOLE_LETTERS = tuple(letter.upper() for letter in SHAFT_LETTERS)

_FIT = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*(?:mm)?\s*([A-Za-z]{1,2})(\d{1,2})\s*/\s*([A-Za-z]{1,2})(\d{1,2})\s*$")
_CLASS = re.compile(r"^\s*([A-Za-z]{1,2})(\d{1,2})\s*$")
_GRADE = re.compile(r"^\s*IT(\d{1,2})\s*$", re.IGNORECASE)


def _error(where: str, message: str) -> ModelError:
    return ModelError([Problem(where, message)])


# --- grades and nominal sizes ---------------------------------------------------------------------------

def grade_number(grade: str | int, where: str = "grade") -> int:
    """The number n of a standard tolerance grade given as ``"IT7"`` or ``7`` (1 <= n <= 18)."""
    if isinstance(grade, bool):
        raise _error(where, f"must be a grade IT1..IT18 such as \"IT7\", got {grade!r}")
    match = _GRADE.match(grade) if isinstance(grade, str) else None
    if isinstance(grade, int):
        number = grade
    elif match:
        number = int(match.group(1))
    else:
        raise _error(where, f"must be a grade IT1..IT18 such as \"IT7\", got {grade!r}")
    if not tables.GRADES[0] <= number <= tables.GRADES[-1]:
        raise _error(where, f"ISO 286-1 grades run from IT1 to IT18, got IT{number}")
    return number


def _nominal_mm(nominal: float, where: str, up_to_mm: float = LARGEST_NOMINAL_MM) -> float:
    """The nominal size [m] in millimetres, checked to lie in (0, up_to_mm]."""
    try:
        mm = round(float(nominal) * MM_PER_M, MM_DECIMALS)
    except (TypeError, ValueError):
        raise _error(where, f"the nominal size must be a length in metres, got {nominal!r}") from None
    if not 0.0 < mm <= up_to_mm:
        raise _error(where, f"the nominal size must be above 0 and at most {up_to_mm:g} mm, "
                            f"got {mm:g} mm ({nominal!r} m)")
    return mm


def _row(table: tuple, mm: float):
    """The value of a table of ``(upper_mm, value)`` rows for a size ``mm`` (above previous, up to own)."""
    for upper_mm, value in table:
        if mm <= upper_mm:
            return value
    raise ValueError(f"{mm} mm is beyond the table")


def _main_range_upper_mm(mm: float) -> float:
    """The upper limit [mm] of Table 1's size range that holds ``mm``."""
    return next(upper for upper, _ in tables.STANDARD_TOLERANCES if mm <= upper)


def _it_um(number: int, mm: float, where: str) -> float:
    """ITn [um] at a nominal size [mm] (Table 1)."""
    if number >= tables.COARSE_GRADES_FROM and mm <= tables.COARSE_GRADES_ABOVE_MM:
        raise _error(where, f"ISO 286-1 does not use IT{number} (IT14..IT18) for nominal sizes up to "
                            f"{tables.COARSE_GRADES_ABOVE_MM:g} mm, got {mm:g} mm")
    return _row(tables.STANDARD_TOLERANCES, mm)[number - 1]


def tolerance(grade: str | int, nominal: float, where: str = "tolerance") -> float:
    """The standard tolerance [m] of ``grade`` (``"IT7"`` or ``7``) at the ``nominal`` size [m]
    (ISO 286-1:2010 Table 1, nominal sizes up to 3150 mm)."""
    number = grade_number(grade, where)
    return _it_um(number, _nominal_mm(nominal, where), where) / UM_PER_M


# --- tolerance classes ----------------------------------------------------------------------------------

@dataclass(frozen=True)
class Zone:
    """A tolerance class at a nominal size: ``lower`` and ``upper`` deviations [m] from the nominal."""

    symbol: str
    lower: float
    upper: float


def _delta_um(number: int, mm: float) -> float:
    """Δ = ITn - IT(n-1) [um] of the special rule (Table 3); 0 up to 3 mm, where the rule does not apply."""
    if mm <= tables.SPECIAL_RULE_ABOVE_MM or number == 1:
        return 0.0
    row = _row(tables.STANDARD_TOLERANCES, mm)
    return row[number - 1] - row[number - 2]


def _shaft_deviation_um(letter: str, number: int, mm: float, where: str) -> tuple[float, str]:
    """The fundamental deviation [um] of shaft ``letter`` and which limit it is ("es" or "ei")."""
    if letter in tables.NOT_AT_OR_BELOW_1_MM and mm <= 1.0:
        raise _error(where, f"ISO 286-1 does not use {letter} or {letter.upper()} for nominal sizes up to 1 mm, "
                            f"got {mm:g} mm")
    if letter in tables.SHAFT_UPPER_DEVIATIONS:
        value, limit = _row(tables.SHAFT_UPPER_DEVIATIONS[letter], mm), "es"
    elif letter == "k" and number not in tables.K_GRADES:
        value, limit = 0.0, "ei"
    else:
        value, limit = _row(tables.SHAFT_LOWER_DEVIATIONS[letter], mm), "ei"
    if value is None:
        raise _error(where, f"ISO 286-1 tabulates {letter} only up to 10 mm, got {mm:g} mm")
    return float(value), limit


def _shaft_zone_um(letter: str, number: int, mm: float, where: str) -> tuple[float, float]:
    """(ei, es) [um] of shaft class ``letter``+``number`` at ``mm``."""
    it = _it_um(number, mm, where)
    if letter == "js":
        return -it / 2.0, it / 2.0
    deviation, limit = _shaft_deviation_um(letter, number, mm, where)
    return (deviation - it, deviation) if limit == "es" else (deviation, deviation + it)


def _hole_zone_um(letter: str, number: int, mm: float, where: str) -> tuple[float, float]:
    """(EI, ES) [um] of hole class ``letter``+``number`` at ``mm``, from the shafts by ISO 286-1's rules:
    A..H: EI = -es; JS: ±IT/2; K..S: ES = -ei, plus Δ where the special rule applies."""
    it = _it_um(number, mm, where)
    if letter == "JS":
        return -it / 2.0, it / 2.0
    shaft = letter.lower()
    if shaft in tables.SHAFT_UPPER_DEVIATIONS:
        es, _ = _shaft_deviation_um(shaft, number, mm, where)
        return -es, -es + it
    upper = _hole_upper_um(letter, number, mm, where)
    return upper - it, upper


def _hole_upper_um(letter: str, number: int, mm: float, where: str) -> float:
    """ES [um] of holes K..S (Table 3)."""
    if letter == "K" and number > tables.SPECIAL_RULE_MAX_GRADE["K"]:
        raise _error(where, f"hole K is supported up to IT8 here (ISO 286-1 Table 3 gives K above IT8 no "
                            f"general rule), got K{number}")
    exception = (letter, number, _main_range_upper_mm(mm))
    if exception in tables.HOLE_EXCEPTIONS:
        return tables.HOLE_EXCEPTIONS[exception]
    ei = _row(tables.SHAFT_LOWER_DEVIATIONS[letter.lower()], mm)
    if number <= tables.SPECIAL_RULE_MAX_GRADE[letter]:
        return -ei + _delta_um(number, mm)
    if letter == "N" and mm > tables.SPECIAL_RULE_ABOVE_MM:
        return tables.N_COARSE_UPPER_UM
    return -float(ei)


def limit_deviations(symbol: str, nominal: float, where: str = "tolerance class") -> Zone:
    """The lower and upper deviations [m] of tolerance class ``symbol`` (``"H7"`` a hole, ``"g6"`` a
    shaft) at the ``nominal`` size [m], up to 500 mm."""
    match = _CLASS.match(symbol) if isinstance(symbol, str) else None
    if not match:
        raise _error(where, f"a tolerance class is a letter and a grade such as \"H7\" or \"g6\", got {symbol!r}")
    letter, number = match.group(1), grade_number(int(match.group(2)), where)
    mm = _nominal_mm(nominal, where, tables.DEVIATIONS_UP_TO_MM)
    if letter in SHAFT_LETTERS:
        lower, upper = _shaft_zone_um(letter, number, mm, where)
    elif letter in HOLE_LETTERS:
        lower, upper = _hole_zone_um(letter, number, mm, where)
    else:
        raise _error(where, f"unsupported fundamental deviation {letter!r} in {symbol!r}: supported holes are "
                            f"{', '.join(HOLE_LETTERS)}; shafts {', '.join(SHAFT_LETTERS)}")
    return Zone(symbol=f"{letter}{number}", lower=lower / UM_PER_M, upper=upper / UM_PER_M)


# --- fits -----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Fit:
    """A hole and a shaft at one nominal size [m]: limit deviations and diametral clearances [m].

    A clearance fit has ``clearance_min >= 0``; a transition fit ``clearance_min < 0 < clearance_max``;
    an interference fit ``clearance_max <= 0``. Only a clearance fit gives a clearance joint its
    clearance (:meth:`radial_clearance`)."""

    text: str
    where: str
    nominal: float
    hole: Zone
    shaft: Zone

    @property
    def clearance_min(self) -> float:
        """Smallest diametral clearance [m]: the smallest hole on the largest shaft (EI - es)."""
        return self.hole.lower - self.shaft.upper

    @property
    def clearance_max(self) -> float:
        """Largest diametral clearance [m]: the largest hole on the smallest shaft (ES - ei)."""
        return self.hole.upper - self.shaft.lower

    @property
    def kind(self) -> str:
        """"clearance", "transition" or "interference"."""
        if self.clearance_min >= 0.0:
            return "clearance"
        return "interference" if self.clearance_max <= 0.0 else "transition"

    def diametral_clearance(self, statistic: str) -> float:
        """The diametral clearance [m]: "min", "mean" (midpoint of the limits) or "max"."""
        values = {"min": self.clearance_min, "max": self.clearance_max,
                  "mean": 0.5 * (self.clearance_min + self.clearance_max)}
        if statistic not in values:
            raise _error(self.where, f"the clearance statistic must be one of min, mean, max, got {statistic!r}")
        return values[statistic]

    def radial_clearance(self, statistic: str) -> float:
        """The radial clearance [m] of a clearance joint made with this fit: half the diametral one.
        Refuses a transition or interference fit (a negative smallest clearance)."""
        if self.kind != "clearance":
            raise _error(self.where, f"{self.text!r} is {'an' if self.kind == 'interference' else 'a'} {self.kind} "
                                     f"fit (diametral clearance {self.clearance_min * UM_PER_M:g} to "
                                     f"{self.clearance_max * UM_PER_M:g} um): a clearance joint needs a "
                                     f"clearance fit, whose smallest clearance is >= 0")
        return 0.5 * self.diametral_clearance(statistic)


def parse_fit(text: str, where: str = "fit") -> Fit:
    """A fit written ``"<nominal in mm> <hole class>/<shaft class>"``, e.g. ``"12 H7/g6"``.

    Any fit is returned (clearance, transition or interference: see :attr:`Fit.kind`); its
    :meth:`Fit.radial_clearance` refuses those that are not clearance fits."""
    match = _FIT.match(text) if isinstance(text, str) else None
    if not match:
        raise _error(where, f"a fit is written \"<nominal mm> <hole>/<shaft>\" such as \"12 H7/g6\", got {text!r}")
    nominal = float(match.group(1)) / MM_PER_M
    hole_symbol, shaft_symbol = match.group(2) + match.group(3), match.group(4) + match.group(5)
    if hole_symbol[0].islower() or shaft_symbol[0].isupper():
        raise _error(where, f"a fit names the hole first in capitals and the shaft second in small letters, "
                            f"such as \"12 H7/g6\", got {text!r}")
    hole = limit_deviations(hole_symbol, nominal, where)
    shaft = limit_deviations(shaft_symbol, nominal, where)
    return Fit(text=text.strip(), where=where, nominal=nominal, hole=hole, shaft=shaft)


# --- grade bands (paper 003) ----------------------------------------------------------------------------

def grade_band(grade: str | int, nominal: float, where: str = "grade") -> tuple[float, float]:
    """The diametral clearance band (low, high) [m] of ``grade`` at the ``nominal`` size [m]:
    (2 IT(n-1), 2 ITn), the largest clearances of the sliding fits H(n-1)/h(n-1) and Hn/hn, as paper 003
    reads the grades (at 12 mm: IT6 16-22 um, IT7 22-36 um, IT8 36-54 um). IT1's band starts at 0."""
    number = grade_number(grade, where)
    mm = _nominal_mm(nominal, where)
    low = 2.0 * _it_um(number - 1, mm, where) if number > 1 else 0.0
    return low / UM_PER_M, 2.0 * _it_um(number, mm, where) / UM_PER_M


def grade_range(grade_from: str | int, grade_to: str | int, nominal: float,
                where: str = "grades") -> tuple[float, float]:
    """The diametral clearances (low, high) [m] spanned by the bands of ``grade_from`` to ``grade_to``
    at the ``nominal`` size [m]: the low end of the first band and the high end of the last."""
    first, last = grade_number(grade_from, where), grade_number(grade_to, where)
    if first > last:
        raise _error(where, f"the grades must run from the finer to the coarser, got IT{first} to IT{last}")
    return grade_band(first, nominal, where)[0], grade_band(last, nominal, where)[1]


def grade_of_clearance(diametral: float, nominal: float, where: str = "clearance") -> str:
    """The grade (``"IT7"``) whose band holds the ``diametral`` clearance [m] at the ``nominal`` size [m].

    Bands are (2 IT(n-1), 2 ITn]: a clearance on a band's lower end belongs to the lower grade
    (22 um at 12 mm is IT6). Raises ModelError outside every band (negative, or above 2 IT18)."""
    mm = _nominal_mm(nominal, where)
    value_um = float(diametral) * UM_PER_M
    if value_um >= -BAND_SLACK_UM:
        for number in tables.GRADES:
            if number >= tables.COARSE_GRADES_FROM and mm <= tables.COARSE_GRADES_ABOVE_MM:
                break
            if value_um <= 2.0 * _it_um(number, mm, where) + BAND_SLACK_UM:
                return f"IT{number}"
    raise _error(where, f"a diametral clearance of {value_um:g} um at {mm:g} mm lies in no grade band "
                        f"(0 to 2 IT18)")
