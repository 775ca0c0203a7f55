"""The spatial clearance revolute joint against an independent implementation of its law.

``tests/spatial_clearance_reference.py`` implements the law from the theory pages alone
(docs/theory/spatial-clearance-revolute.md, spatial-clearance-geometry.md): the section's closest point by its
own Newton iteration, the halves' penetrated part by Brent's method and 8-point Gauss-Legendre, the flange ring
over its touching part exactly in angle, Newton-Euler of one free body with quaternions, SciPy's DOP853 at
rtol 1e-10 with events restarting the run at every onset to latch its rate.

Static poses (zero velocities, so the elastic law alone): line contact of an aligned journal, a tilted journal
on one rim, the transition (a slight tilt, both halves touching unevenly), a flange pressed as a full ring.
Measured: forces and moments equal to 1e-13 relative except the transition, 4.7e-6 relative (the element's
4-point rule against the reference's 8-point one on a nearly linear profile).

Disagreement found (the flange ring): with the journal tilted, a flange touches its face on a short arc near
its edge; the element integrates the ring with 4 Gauss-Legendre radii and 24 fixed angles (the theory page's
rule, exact only for a fully touching ring), whose outermost radius (14.65 mm of 15 mm) lies inside that arc's
reach. Tilted 0.0128 rad, the element gives no force at all until the edge is about 4.5 um deep (at 2.83 um:
0 N, the law 5.56 N), 4-10 % too little at 30 um deep varying with the tilt axis' angle (921-979 N against
1015.7 N), -0.6 to +1.3 % at 60 um (8083-8231 N against 8128.9 N); the reference's ring integral matches a
brute-force sum to 5e-7. In a run the flange strikes of a tilted journal therefore come deeper and later in
force than the law says; the journal of this case with an axial clearance of 0.4 mm strikes flange A first at
4.98825 ms in both; after that strike the runs part (the next seven onsets differ by 6-200 us over 20 ms,
against 4e-8 s in the case below without flange strikes).

The dynamic case: a 1 kg journal (principal inertias 1e-3, 1e-3, 5e-4 kg m^2) dropped centred in a 10 mm bore
fixed to the ground, turning at 2 rad/s about x and 30 rad/s about its axis, drifting along its axis at
10 mm/s; clearance 0.5 mm, length 20 mm, steel, Hertz cylinder stiffness, Lankarani-Nikravesh e = 0.9,
stiction (0.15/0.10, 0.01/0.05 mm/s). 80 ms: seven rim impacts on both halves, tilts to 0.021 rad, contact
during 5.2 ms of which 0.26 ms with a whole half bearing (line contact), sliding at 0.25 m/s or more with the
spin (kinetic friction: the stiction band is not visited). The axial clearance is 4 mm here so that no flange strikes: the flange ring's
quadrature misses a partly touching ring (test below, marked as the known disagreement), and a strike would
mix that defect into the comparison of everything else; flange strikes are compared where the ring touches
whole (an aligned spinning journal without gravity, the last test). Measured on this machine (element rtol 1e-10,
atol 1e-13): centre position to 4.5e-9 m, centre velocity to 2.3e-5 m/s, body angular velocity to 9.6e-5 rad/s,
tilt to 2.2e-7 rad, normal forces to 0.18 N of 611 N peaks, the seven onsets to 4e-8 s. The differences grow
with each impact (each onset's sensitivity to the previous); the tolerances are about ten times them.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import jointplay as jp
import spatial_clearance_reference as ref

# trial stages of rejected steps may overflow in the reference's right-hand side (the step is then refused)
pytestmark = pytest.mark.filterwarnings("ignore:invalid value encountered:RuntimeWarning",
                                        "ignore:overflow encountered:RuntimeWarning")

CASE = replace(ref.Journal(), axial_clearance=4e-3)
T_END = 0.08
OUTPUT_STEP = 1e-5


def journal_in_bore(case: ref.Journal, pose=None) -> jp.Model:
    """The case through the Python API; ``pose`` = (position [m], axis, angle [rad]) for a static pose at rest."""
    m = jp.Model("journal_in_bore", kinematics="spatial")
    m.set_gravity(tuple(f"{g} m/s^2" for g in case.gravity))
    m.add_ground_point("P", (0, 0, 0))
    inertia = {"principal": [f"{i} kg m^2" for i in case.inertia]}
    if pose is None:
        m.add_body("pin", mass=f"{case.mass} kg", inertia=inertia, position=(0, 0, 0),
                   velocity=tuple(f"{v} m/s" for v in case.velocity),
                   angular_velocity=tuple(f"{w} rad/s" for w in case.angular_velocity), points={"J": (0, 0, 0)})
    else:
        position, axis, angle = pose
        m.add_body("pin", mass=f"{case.mass} kg", inertia=inertia, position=tuple(position),
                   orientation={"axis": tuple(axis), "angle": f"{angle} rad"}, points={"J": (0, 0, 0)})
    m.add_spatial_clearance_revolute(
        "play", "ground.P", "pin.J", bore_radius=f"{case.bore_radius} m", clearance=f"{case.clearance} m",
        bearing_length=f"{case.bearing_length} m", axial_clearance=f"{case.axial_clearance} m",
        flange_radius=f"{case.flange_radius} m", face_radius=f"{case.face_radius} m", lock_at_assembly=False,
        bearing_material={"youngs_modulus": f"{case.youngs_modulus} Pa", "poisson_ratio": case.poisson_ratio},
        journal_material={"youngs_modulus": f"{case.youngs_modulus} Pa", "poisson_ratio": case.poisson_ratio},
        contact={"law": "lankarani_nikravesh", "restitution": case.restitution}, stiffness={"law": "hertz_cylinder"},
        onset_velocity_floor=f"{case.onset_floor} m/s",
        friction={"law": "stiction", "static_coefficient": case.static_coefficient,
                  "kinetic_coefficient": case.kinetic_coefficient,
                  "stiction_velocity": f"{case.stiction_velocity} m/s",
                  "transition_velocity": f"{case.transition_velocity} m/s"})
    return m


LOADS = ("fn_a", "fn_b", "fn_fa", "fn_fb", "fx", "fy", "fz", "mx", "my", "mz")


def element_at_rest(case: ref.Journal, pose) -> dict:
    """The element's loads at a pose at rest (first sample)."""
    run = journal_in_bore(case, pose).simulate(t_end=1e-9, output_step=1e-9)
    return {k: float(run[f"play.{k}"][0]) for k in LOADS}


def reference_at_rest(case: ref.Journal, pose) -> dict:
    position, axis, angle = pose
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    q = np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])
    state = ref.unpack(np.concatenate([position, q, np.zeros(6)]))
    loads = ref.candidates(case, state, [case.onset_floor] * 4)
    force, moment = sum(x[0] for x in loads), sum(x[1] for x in loads)
    values = dict(zip(LOADS[:4], (x[2] for x in loads)))
    values.update(zip(LOADS[4:], (*force, *moment)))
    return values


POSES = {
    # aligned, 1 um into the bottom of the bore: line contact along the whole length
    "line": ((0.0, -5.01e-4, 0.0), (1.0, 0.0, 0.0), 0.0, 1e-9),
    # tilted 0.0201 rad about x, 0.4 mm down: rim B bites, and both flanges (deep, a full ring here)
    "rim": ((0.0, -4.0e-4, 0.0), (1.0, 0.0, 0.0), 0.0201, None),
    # a slight tilt on the bottom: half B bears along its length, half A only near the middle
    "transition": ((0.0, -5.0e-4, 0.0), (1.0, 0.0, 0.0), 1e-4, 5e-5),
    # aligned, 2 um onto face B: the flange's full ring
    "ring": ((0.0, 0.0, -2.02e-4), (1.0, 0.0, 0.0), 0.0, 1e-9),
}


@pytest.mark.parametrize("name", POSES)
def test_the_loads_at_a_pose_follow_the_law(name):
    position, axis, angle, tolerance = POSES[name]
    case = ref.Journal()
    element = element_at_rest(case, (position, axis, angle))
    reference = reference_at_rest(case, (np.array(position), axis, angle))
    radial = ("fn_a", "fn_b", "fx", "fy") if name == "rim" else LOADS
    scale = max(abs(v) for v in reference.values())
    for key in radial:
        assert element[key] == pytest.approx(reference[key], abs=(tolerance or 1e-9) * scale), key


def test_a_tilted_flange_touching_on_a_short_arc_carries_its_force():
    # tilted 0.0128 rad about x, 10 um towards -z: flange B's edge penetrates face B by 2.83 um over an arc of
    # about +-0.14 rad; the law integrated over that arc gives 5.56 N (the element's first ring rule, 4 fixed
    # radii and 24 fixed angles, gave 0 N with penetration_fb > 0; it now integrates the touching arc)
    pose = (np.array([0.0, 0.0, -1.0e-5]), (1.0, 0.0, 0.0), 0.0128)
    case = ref.Journal()
    reference = reference_at_rest(case, pose)
    assert reference["fn_fb"] == pytest.approx(5.559, rel=1e-3)
    assert element_at_rest(case, pose)["fn_fb"] == pytest.approx(reference["fn_fb"], rel=1e-3)


@pytest.mark.parametrize("depth", [1e-5, 3e-5])
def test_the_reference_integrates_a_partly_touching_ring_as_a_brute_force_sum(depth):
    # the flange's elastic force over its touching arc against a midpoint sum over the radii that touch (1000)
    # and 8000 angles round the ring (measured 5.0e-7 and 4.8e-7 relative, the sum's own error)
    case = ref.Journal()
    state = ref.unpack(np.concatenate([[0.0, 0.0, -depth], [math.cos(0.0064), math.sin(0.0064), 0.0, 0.0],
                                       np.zeros(6)]))
    force = ref.candidates(case, state, [case.onset_floor] * 4)[3][2]
    _, centre_depth, slope, direction = ref._flange_frame(case, 1, state.r, state.rot)
    inner = max(case.bore_radius, -centre_depth / slope)
    width = case.ring_outer_radius - inner
    radius = inner + (np.arange(1000) + 0.5) / 1000 * width
    angle = (np.arange(8000) + 0.5) / 8000 * 2.0 * math.pi
    depths = np.maximum(centre_depth + slope * np.outer(radius, np.cos(angle - direction)), 0.0)
    brute = case.axial_stiffness / case.ring_area * np.sum(depths * radius[:, None]) * width / 1000 * math.pi / 4000
    assert force == pytest.approx(brute, rel=2e-6)


def signed_half_penetration(case: ref.Journal, position, quaternion, half: int) -> float:
    """The deepest penetration of bore half 0 (A) or 1 (B) at a pose, by the reference's geometry."""
    state = ref.unpack(np.concatenate([position, quaternion, np.zeros(6)]))
    return ref.deepest(case, state)[half][0]


def onsets_of(run: jp.Results, case: ref.Journal, half: int) -> list:
    """The element's onsets of a half: at each sample where its penetration channel turns positive, the root of
    the deepest penetration of the sampled poses (by the reference's geometry, linear between the two samples;
    the penetration is nearly linear in time there: error ~ dt^2 |delta''| / delta' < 1e-8 s)."""
    channel = run["play.penetration_a" if half == 0 else "play.penetration_b"]
    pose = np.column_stack([run[f"pin.{k}"] for k in ("x", "y", "z", "qw", "qx", "qy", "qz")])
    t, found = run.time, []
    for i in np.where((channel[:-1] <= 0.0) & (channel[1:] > 0.0))[0]:
        before, after = (signed_half_penetration(case, pose[k, :3], pose[k, 3:], half) for k in (i, i + 1))
        found.append(float(t[i] - before * (t[i + 1] - t[i]) / (after - before)))
    return found


@pytest.fixture(scope="module")
def runs():
    element = journal_in_bore(CASE).simulate(t_end=T_END, rtol=1e-10, atol=1e-13, output_step=OUTPUT_STEP)
    reference = ref.simulate(CASE, T_END)
    return element, reference, reference.states(element.time)


def test_the_journal_moves_as_the_independent_implementation(runs):
    element, _, states = runs
    for i, k in enumerate("xyz"):
        assert np.max(np.abs(element[f"pin.{k}"] - states[:, i])) < 5e-8, k
        assert np.max(np.abs(element[f"pin.v{k}"] - states[:, 7 + i])) < 2e-4, k
        assert np.max(np.abs(element[f"pin.w{k}"] - states[:, 10 + i])) < 1e-3, k
    tilt = np.array([math.acos(min(1.0, ref.rotation(y[3:7])[2, 2])) for y in states])
    assert tilt.max() > 0.02
    assert np.max(np.abs(element["play.tilt"] - tilt)) < 2e-6


def test_the_impacts_begin_when_the_independent_implementation_says(runs):
    element, reference, _ = runs
    for half in (0, 1):
        expected = [t for t, k, _ in reference.onsets if k == half]
        found = onsets_of(element, CASE, half)
        assert len(expected) >= 3 and len(found) == len(expected), (found, expected)
        assert np.max(np.abs(np.array(found) - np.array(expected))) < 4e-7
    assert not [k for _, k, _ in reference.onsets if k > 1], "no flange strikes in this case"


def test_the_candidates_carry_the_forces_of_the_independent_implementation(runs):
    element, reference, _ = runs
    every = 10
    times = element.time[::every]
    loads = np.array([[x[2] for x in ref.candidates(CASE, ref.unpack(y), latched)]
                      for y, latched in (reference.state(t) for t in times)])
    for k, key in enumerate(("fn_a", "fn_b")):
        channel = element[f"play.{key}"][::every]
        assert loads[:, k].max() > 400.0, key
        assert np.max(np.abs(channel - loads[:, k])) < 2.0, key


STRIKE = replace(ref.Journal(), gravity=(0.0, 0.0, 0.0), velocity=(0.0, 0.0, 0.05), angular_velocity=(0.0, 0.0, 30.0))


def test_an_aligned_spinning_journal_strikes_its_flanges_as_the_independent_implementation():
    """Without gravity, centred, spinning at 30 rad/s and drifting at 50 mm/s along the axis, the journal strikes
    flange A's face at 4 ms and flange B's at 12.8 ms as full rings (the element's ring rule is exact for
    them): the strikes' damping with the latched onset rate, and the ring's friction against the spin (which
    slows it from 30 to 29.54 rad/s). Measured: axial position to 1.2e-12 m, axial velocity to 1.5e-8 m/s, spin
    to 3.9e-8 rad/s, flange normal forces to 9e-4 N of 2433 N peaks (4e-7); tolerances about ten times these.
    (The ``ft_f*`` channels are not compared: the reference sums the ring's friction magnitudes, whose forces
    cancel round a full ring into a torque; the spin compares that torque.)"""
    element = journal_in_bore(STRIKE).simulate(t_end=0.015, rtol=1e-10, atol=1e-13, output_step=1e-6)
    reference = ref.simulate(STRIKE, 0.015)
    states = reference.states(element.time)
    assert [k for _, k, _ in reference.onsets] == [2, 3]
    assert np.max(np.abs(element["pin.z"] - states[:, 2])) < 1e-11
    assert np.max(np.abs(element["pin.vz"] - states[:, 9])) < 2e-7
    assert np.max(np.abs(element["pin.wz"] - states[:, 12])) < 4e-7
    assert states[-1, 12] < 30.0 - 0.4 and states[-1, 9] > 0.04
    contact = np.where(element["play.fn_fa"] + element["play.fn_fb"] > 0.0)[0]
    loads = np.array([[x[2] for x in ref.candidates(STRIKE, ref.unpack(states[i]), reference.state(t)[1])]
                      for i, t in zip(contact, element.time[contact])])
    peak = loads[:, 2:].max()
    assert peak > 1e3
    for k, key in ((2, "fn_fa"), (3, "fn_fb")):
        assert np.max(np.abs(element[f"play.{key}"][contact] - loads[:, k])) < 4e-6 * peak, key
