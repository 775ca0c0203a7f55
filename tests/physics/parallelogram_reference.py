"""Independent references for parallelogram linkages: the one-degree-of-freedom equation and the
minimum-norm joint reactions of the absolute-coordinate model, written apart from the engine.

Parallelogram linkages of uniform bars (mass m, length L) whose "vertical" bars all turn by the same
angle theta (measured from +x) about ground pins on the x axis while the couplers translate:

- ``n_bars`` bars pinned to the ground, each ``T = (1/2)(m L^2/3) theta_dot^2`` (rotation about its
  ground pin), ``V = m g (L/2) sin(theta)``;
- couplers of total mass ``m_c`` that translate with their pins: ``T = (1/2) m_c L^2 theta_dot^2``,
  ``V = m_c g L sin(theta)``.

Lagrange's equation of ``T(theta_dot) + V(theta)`` gives

    theta_ddot = -(g/L) cos(theta) (n_bars m/2 + m_c) / (n_bars m/3 + m_c) = -k (g/L) cos(theta)

- the parallelogram four-bar (2 bars, coupler m): k = (3/2)/(5/3) = 6/5;
- the double parallelogram (3 bars, coupler 2 m long of mass 2 m): k = (7/2)/3 = 7/6.

Reactions: the absolute-coordinate model (x, y, phi of each centre of mass) with every revolute joint
as the point coincidence ``Phi = P_first - P_second = 0`` (two rows, force units for the multipliers).
With a redundant joint the multipliers are not unique; :func:`minimum_norm_solution` solves
``M q_ddot + Phi_q^T lambda = Q, Phi_q q_ddot = gamma`` by least squares (SVD), which picks the
accelerations (unique) and, of all multipliers that balance them, the one of least Euclidean norm.
"""

from __future__ import annotations

import functools
import importlib
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

G = 9.81  # m/s^2


def theta_ddot_factor(n_bars: int, bar_mass: float, coupler_mass: float) -> float:
    """k of ``theta_ddot = -k (g/L) cos(theta)`` (see the module docstring)."""
    return (n_bars * bar_mass / 2 + coupler_mass) / (n_bars * bar_mass / 3 + coupler_mass)


def one_dof_solution(k: float, length: float, theta0: float, omega0: float, t_end: float,
                     rtol: float = 1e-10, atol: float = 1e-12):
    """Dense solution ``sol(t) -> (theta, theta_dot)`` of ``theta_ddot = -k (g/L) cos(theta)``."""
    c = k * G / length

    def rhs(_t, y):
        return (y[1], -c * math.cos(y[0]))

    sol = solve_ivp(rhs, (0.0, t_end), (theta0, omega0), method="DOP853", rtol=rtol, atol=atol, dense_output=True)
    assert sol.success, sol.message
    return sol.sol


def wrapped(angle):
    """Angle (or angle difference) brought to (-pi, pi]."""
    return np.angle(np.exp(1j * np.asarray(angle)))


def flat_passages(theta) -> int:
    """Sign changes of sin(theta): passages of the bars through the ground line."""
    s = np.sign(np.sin(np.asarray(theta)))
    s = s[s != 0]
    return int(np.count_nonzero(s[1:] * s[:-1] < 0))


@dataclass
class Body:
    name: str
    mass: float
    inertia: float
    points: dict  # name -> (x, y) in body coordinates [m]


@dataclass
class Joint:
    """Revolute joint: the point ``first`` coincides with ``second`` (``"body.point"`` or
    ``"ground.point"``)."""
    name: str
    first: str
    second: str


class AbsoluteModel:
    """A planar linkage of revolute joints in absolute coordinates, with gravity along -y."""

    def __init__(self, bodies: list[Body], ground: dict, joints: list[Joint], gravity: float = G):
        self.bodies, self.ground, self.joints, self.g = bodies, ground, joints, gravity
        self.index = {b.name: k for k, b in enumerate(bodies)}
        self.n = 3 * len(bodies)
        self.mass = np.diag(np.concatenate([[b.mass, b.mass, b.inertia] for b in bodies]))

    def _end(self, ref: str):
        """(body index or None, local/ground point) of ``"body.point"``."""
        body, point = ref.split(".")
        if body == "ground":
            return None, np.asarray(self.ground[point], dtype=float)
        k = self.index[body]
        return k, np.asarray(self.bodies[k].points[point], dtype=float)

    def jacobian_and_gamma(self, q: np.ndarray, qd: np.ndarray):
        """``Phi_q`` (2 rows per joint) and ``gamma`` with ``Phi_q q_ddot = gamma``."""
        rows, gamma = np.zeros((2 * len(self.joints), self.n)), np.zeros(2 * len(self.joints))
        for j, joint in enumerate(self.joints):
            for ref, sign in ((joint.first, 1.0), (joint.second, -1.0)):
                k, s = self._end(ref)
                if k is None:
                    continue
                phi, omega = q[3 * k + 2], qd[3 * k + 2]
                c, sn = math.cos(phi), math.sin(phi)
                a_s = np.array([c * s[0] - sn * s[1], sn * s[0] + c * s[1]])  # A s
                rows[2 * j:2 * j + 2, 3 * k:3 * k + 2] = sign * np.eye(2)
                rows[2 * j:2 * j + 2, 3 * k + 2] = sign * np.array([-a_s[1], a_s[0]])  # d(A s)/dphi
                gamma[2 * j:2 * j + 2] += sign * omega**2 * a_s  # Phi_ddot = Phi_q q_ddot - sign w^2 A s
        return rows, gamma

    def applied(self) -> np.ndarray:
        """Generalised applied forces: gravity."""
        out = np.zeros(self.n)
        for k, b in enumerate(self.bodies):
            out[3 * k + 1] = -b.mass * self.g
        return out

    def minimum_norm_solution(self, q: np.ndarray, qd: np.ndarray):
        """Accelerations and the least-norm multipliers (see the module docstring), and the rank of Phi_q."""
        jac, gamma = self.jacobian_and_gamma(q, qd)
        m = len(gamma)
        kkt = np.block([[self.mass, jac.T], [jac, np.zeros((m, m))]])
        rhs = np.concatenate([self.applied(), gamma])
        solution, *_ = np.linalg.lstsq(kkt, rhs, rcond=1e-12)
        return solution[:self.n], solution[self.n:], np.linalg.matrix_rank(jac, tol=1e-9)

    def reactions(self, q: np.ndarray, qd: np.ndarray) -> dict[str, np.ndarray]:
        """Force [N] each joint's first end exerts on its second end (the second body's share of
        ``-Phi_q^T lambda``), global frame, under the least-norm multipliers."""
        _, lam, _ = self.minimum_norm_solution(q, qd)
        # Phi = P_first - P_second: d(Phi)/d(r_second) = -I, so the force on the second body is +lambda
        return {joint.name: lam[2 * j:2 * j + 2].copy() for j, joint in enumerate(self.joints)}


def state_from_results(results, bodies: list[Body], k: int):
    """(q, q_dot) of sample ``k`` from a run's channels ``<body>.x, .y, .angle, .vx, .vy, .omega``."""
    q = np.concatenate([[results[f"{b.name}.{c}"][k] for c in ("x", "y", "angle")] for b in bodies])
    qd = np.concatenate([[results[f"{b.name}.{c}"][k] for c in ("vx", "vy", "omega")] for b in bodies])
    return q, qd


@functools.cache
def run_model_file(path):
    """The model file's own run: its [simulation] settings to its t_end (run once per path)."""
    import jointplay as jp

    model = jp.load(path)
    options = dict(model.simulation)
    return model.simulate(options.pop("t_end"), **options)


@functools.cache
def one_dof_to_end_of(path, k: float, length: float, theta0: float, omega0: float):
    """:func:`one_dof_solution` to the model file's t_end (computed once per case)."""
    import jointplay as jp

    return one_dof_solution(k, length, theta0, omega0, jp.load(path).simulation["t_end"])


def example_builds_the_model_file(example: str, path) -> bool:
    """Whether the Python example ``example`` (a module in examples/) builds the model file's spec."""
    import jointplay as jp

    return importlib.import_module(example).build_model().to_spec() == jp.load(path).to_spec()
