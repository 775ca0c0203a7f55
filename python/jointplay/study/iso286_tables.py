"""ISO 286-1 tables as data: standard tolerances and fundamental deviations, in micrometres.

Source: ISO 286-1:2010, *Geometrical product specifications (GPS) - ISO code system for tolerances on
linear sizes - Part 1: Basis of tolerances, deviations and fits*:

- Table 1, values of standard tolerance grades IT1 to IT18 for nominal sizes up to 3150 mm
  (:data:`STANDARD_TOLERANCES`);
- Table 2, fundamental deviations of shafts a to js (upper deviations ``es``,
  :data:`SHAFT_UPPER_DEVIATIONS`), and Table 3, fundamental deviations of shafts k to zc (lower
  deviations ``ei``, :data:`SHAFT_LOWER_DEVIATIONS`), for nominal sizes up to 500 mm, transcribed
  here for the letters a, b, c, cd, d, e, ef, f, fg, g, h, k, m, n, p, r, s;
- Tables 2 and 3 give the holes' deviations from the shafts' by the general rule ``EI = -es``
  (A to H) and ``ES = -ei`` (K to ZC), with the correction Δ = ITn - IT(n-1) (the "special rule");
  ``jointplay.study.iso286`` applies those rules instead of a second copy of the tables. The one
  tabulated exception to the rules is :data:`HOLE_EXCEPTIONS`.

Layout: a table is a tuple of ``(upper_mm, value)`` rows; a row holds for nominal sizes ABOVE the
previous row's ``upper_mm`` UP TO AND INCLUDING its own (the first row from 0). ``None`` marks a size
the standard gives no value for (cd, ef and fg are tabulated up to 10 mm only). Values are in
micrometres, signed as in the standard.
"""

from __future__ import annotations

#: Grades of Table 1, in the order of the values in each row of :data:`STANDARD_TOLERANCES`.
GRADES = tuple(range(1, 19))

#: ISO 286-1:2010 Table 1: (upper_mm, (IT1, ..., IT18)) in micrometres. The standard prints IT14 to
#: IT18 in millimetres; they are converted to micrometres here.
STANDARD_TOLERANCES: tuple[tuple[float, tuple[float, ...]], ...] = (
    (3, (0.8, 1.2, 2, 3, 4, 6, 10, 14, 25, 40, 60, 100, 140, 250, 400, 600, 1000, 1400)),
    (6, (1, 1.5, 2.5, 4, 5, 8, 12, 18, 30, 48, 75, 120, 180, 300, 480, 750, 1200, 1800)),
    (10, (1, 1.5, 2.5, 4, 6, 9, 15, 22, 36, 58, 90, 150, 220, 360, 580, 900, 1500, 2200)),
    (18, (1.2, 2, 3, 5, 8, 11, 18, 27, 43, 70, 110, 180, 270, 430, 700, 1100, 1800, 2700)),
    (30, (1.5, 2.5, 4, 6, 9, 13, 21, 33, 52, 84, 130, 210, 330, 520, 840, 1300, 2100, 3300)),
    (50, (1.5, 2.5, 4, 7, 11, 16, 25, 39, 62, 100, 160, 250, 390, 620, 1000, 1600, 2500, 3900)),
    (80, (2, 3, 5, 8, 13, 19, 30, 46, 74, 120, 190, 300, 460, 740, 1200, 1900, 3000, 4600)),
    (120, (2.5, 4, 6, 10, 15, 22, 35, 54, 87, 140, 220, 350, 540, 870, 1400, 2200, 3500, 5400)),
    (180, (3.5, 5, 8, 12, 18, 25, 40, 63, 100, 160, 250, 400, 630, 1000, 1600, 2500, 4000, 6300)),
    (250, (4.5, 7, 10, 14, 20, 29, 46, 72, 115, 185, 290, 460, 720, 1150, 1850, 2900, 4600, 7200)),
    (315, (6, 8, 12, 16, 23, 32, 52, 81, 130, 210, 320, 520, 810, 1300, 2100, 3200, 5200, 8100)),
    (400, (7, 9, 13, 18, 25, 36, 57, 89, 140, 230, 360, 570, 890, 1400, 2300, 3600, 5700, 8900)),
    (500, (8, 10, 15, 20, 27, 40, 63, 97, 155, 250, 400, 630, 970, 1550, 2500, 4000, 6300, 9700)),
    (630, (9, 11, 16, 22, 32, 44, 70, 110, 175, 280, 440, 700, 1100, 1750, 2800, 4400, 7000, 11000)),
    (800, (10, 13, 18, 25, 36, 50, 80, 125, 200, 320, 500, 800, 1250, 2000, 3200, 5000, 8000, 12500)),
    (1000, (11, 15, 21, 28, 40, 56, 90, 140, 230, 360, 560, 900, 1400, 2300, 3600, 5600, 9000, 14000)),
    (1250, (13, 18, 24, 33, 47, 66, 105, 165, 260, 420, 660, 1050, 1650, 2600, 4200, 6600, 10500, 16500)),
    (1600, (15, 21, 29, 39, 55, 78, 125, 195, 310, 500, 780, 1250, 1950, 3100, 5000, 7800, 12500, 19500)),
    (2000, (18, 25, 35, 46, 65, 92, 150, 230, 370, 600, 920, 1500, 2300, 3700, 6000, 9200, 15000, 23000)),
    (2500, (22, 30, 41, 55, 78, 110, 175, 280, 440, 700, 1100, 1750, 2800, 4400, 7000, 11000, 17500, 28000)),
    (3150, (26, 36, 50, 68, 96, 135, 210, 330, 540, 860, 1350, 2100, 3300, 5400, 8600, 13500, 21000, 33000)),
)

#: Table 1, footnote: IT14 to IT18 are not used for nominal sizes up to and including 1 mm.
COARSE_GRADES_FROM = 14
COARSE_GRADES_ABOVE_MM = 1.0

#: Largest nominal size [mm] of the fundamental deviations transcribed here (Tables 2 and 3).
DEVIATIONS_UP_TO_MM = 500.0

#: Table 2: upper deviation ``es`` [um] of shafts a to h, per letter.
SHAFT_UPPER_DEVIATIONS: dict[str, tuple[tuple[float, float | None], ...]] = {
    "a": ((3, -270), (6, -270), (10, -280), (18, -290), (30, -300), (40, -310), (50, -320), (65, -340),
          (80, -360), (100, -380), (120, -410), (140, -460), (160, -520), (180, -580), (200, -660),
          (225, -740), (250, -820), (280, -920), (315, -1050), (355, -1200), (400, -1350), (450, -1500),
          (500, -1650)),
    "b": ((3, -140), (6, -140), (10, -150), (18, -150), (30, -160), (40, -170), (50, -180), (65, -190),
          (80, -200), (100, -220), (120, -240), (140, -260), (160, -280), (180, -310), (200, -340),
          (225, -380), (250, -420), (280, -480), (315, -540), (355, -600), (400, -680), (450, -760),
          (500, -840)),
    "c": ((3, -60), (6, -70), (10, -80), (18, -95), (30, -110), (40, -120), (50, -130), (65, -140),
          (80, -150), (100, -170), (120, -180), (140, -200), (160, -210), (180, -230), (200, -240),
          (225, -260), (250, -280), (280, -300), (315, -330), (355, -360), (400, -400), (450, -440),
          (500, -480)),
    "cd": ((3, -34), (6, -46), (10, -56), (500, None)),
    "d": ((3, -20), (6, -30), (10, -40), (18, -50), (30, -65), (50, -80), (80, -100), (120, -120),
          (180, -145), (250, -170), (315, -190), (400, -210), (500, -230)),
    "e": ((3, -14), (6, -20), (10, -25), (18, -32), (30, -40), (50, -50), (80, -60), (120, -72),
          (180, -85), (250, -100), (315, -110), (400, -125), (500, -135)),
    "ef": ((3, -10), (6, -14), (10, -18), (500, None)),
    "f": ((3, -6), (6, -10), (10, -13), (18, -16), (30, -20), (50, -25), (80, -30), (120, -36),
          (180, -43), (250, -50), (315, -56), (400, -62), (500, -68)),
    "fg": ((3, -4), (6, -6), (10, -8), (500, None)),
    "g": ((3, -2), (6, -4), (10, -5), (18, -6), (30, -7), (50, -9), (80, -10), (120, -12),
          (180, -14), (250, -15), (315, -17), (400, -18), (500, -20)),
    "h": ((500, 0),),
}

#: Table 2, footnote: a and b (and A and B) are not used for nominal sizes up to and including 1 mm.
NOT_AT_OR_BELOW_1_MM = ("a", "b")

#: Table 3: lower deviation ``ei`` [um] of shafts k to s, per letter. For k the values hold for grades
#: IT4 to IT7 (:data:`K_GRADES`); for the other grades of k, ``ei = 0``.
SHAFT_LOWER_DEVIATIONS: dict[str, tuple[tuple[float, float | None], ...]] = {
    "k": ((3, 0), (6, 1), (10, 1), (18, 1), (30, 2), (50, 2), (80, 2), (120, 3), (180, 3), (250, 4),
          (315, 4), (400, 4), (500, 5)),
    "m": ((3, 2), (6, 4), (10, 6), (18, 7), (30, 8), (50, 9), (80, 11), (120, 13), (180, 15), (250, 17),
          (315, 20), (400, 21), (500, 23)),
    "n": ((3, 4), (6, 8), (10, 10), (18, 12), (30, 15), (50, 17), (80, 20), (120, 23), (180, 27),
          (250, 31), (315, 34), (400, 37), (500, 40)),
    "p": ((3, 6), (6, 12), (10, 15), (18, 18), (30, 22), (50, 26), (80, 32), (120, 37), (180, 43),
          (250, 50), (315, 56), (400, 62), (500, 68)),
    "r": ((3, 10), (6, 15), (10, 19), (18, 23), (30, 28), (50, 34), (65, 41), (80, 43), (100, 51),
          (120, 54), (140, 63), (160, 65), (180, 68), (200, 77), (225, 80), (250, 84), (280, 94),
          (315, 98), (355, 108), (400, 114), (450, 126), (500, 132)),
    "s": ((3, 14), (6, 19), (10, 23), (18, 28), (30, 35), (50, 43), (65, 53), (80, 59), (100, 71),
          (120, 79), (140, 92), (160, 100), (180, 108), (200, 122), (225, 130), (250, 140), (280, 158),
          (315, 170), (355, 190), (400, 208), (450, 232), (500, 252)),
}

#: Table 3: grades for which shaft k has the tabulated ``ei`` (otherwise ``ei = 0``).
K_GRADES = (4, 5, 6, 7)

#: Table 3: the special rule ``ES = -ei + Δ`` holds above 3 mm for holes K, M, N up to IT8 and for
#: holes P to ZC up to IT7; elsewhere the general rule ``ES = -ei``.
SPECIAL_RULE_ABOVE_MM = 3.0
SPECIAL_RULE_MAX_GRADE = {"K": 8, "M": 8, "N": 8, "P": 7, "R": 7, "S": 7}

#: Table 3: hole N above IT8 and above 3 mm has ``ES = 0`` (not ``-ei``).
N_COARSE_UPPER_UM = 0.0

#: Table 3, footnote: tolerance class M6 from 250 mm to 315 mm has ``ES = -9 um`` (instead of -11 um).
HOLE_EXCEPTIONS = {("M", 6, 315): -9.0}
