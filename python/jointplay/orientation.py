"""Orientations, inertia tensors, 3-vectors and marker frames of spatial models, read with units.

An orientation is a rotation from a body's frame to the global frame (active: ``x_global = R x_body``),
given in one of four forms, and returned as a unit quaternion ``[w, x, y, z]``, scalar first (Hamilton
convention, the core's ``kinematics::quaternion``):

- axis and angle: ``{ axis = [0, 0, 1], angle = "30 deg" }`` (the axis need not be unit length);
- Euler angles with their sequence named: ``{ euler = ["10 deg", "20 deg", "30 deg"], sequence = "ZXZ" }``,
  intrinsic (each rotation about an axis of the frame being turned: ``"ZXZ"`` is ``R_z(a) R_x(b) R_z(c)``),
  upper case as in SciPy; ``"3-1-3"`` is another name of ``"ZXZ"`` (1 = X, 2 = Y, 3 = Z);
- a rotation matrix: ``{ matrix = [[...], [...], [...]] }``, rows as written, its columns the body's axes
  in global coordinates; orthonormal with determinant +1 within :data:`MATRIX_TOLERANCE`;
- a quaternion: ``{ quaternion = [w, x, y, z] }``, scalar first, normalised here.

The conversions are SciPy's (``scipy.spatial.transform.Rotation``, whose quaternions are scalar last:
converted here). An inertia tensor is given by its principal moments and their axes (``J = R diag(J1, J2,
J3) R^T``) or in full; both are checked to be those of a rigid body (symmetric, positive definite, each
principal moment at most the sum of the other two). Every problem raises :class:`OrientationError` with
the key under the value where it lies, for a located message.

SciPy loads on first use (``import jointplay`` stays light).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: Largest deviation of a rotation matrix from orthonormality (``|R^T R - I|``, entrywise) and of its
#: determinant from +1: a matrix written with six or seven significant digits passes, a shear or a
#: reflection does not.
MATRIX_TOLERANCE = 1e-6

#: Relative tolerance of the checks of an inertia tensor (symmetry, the triangle inequalities): round-off of
#: a tensor written with about nine digits, so that a thin plate (J3 = J1 + J2 exactly) passes.
INERTIA_TOLERANCE = 1e-9

#: Deviation from a unit quaternion or an orthonormal matrix that is round-off: such a value is kept as written
#: (a model written by ``Model.to_toml`` reads back bit for bit), a larger one is normalised.
ROUND_OFF = 4e-16

#: The twelve intrinsic Euler sequences, as SciPy names them (upper case: about the moving axes).
EULER_SEQUENCES = ("XYX", "XYZ", "XZX", "XZY", "YXY", "YXZ", "YZX", "YZY", "ZXY", "ZXZ", "ZYX", "ZYZ")
#: The same sequences by axis numbers, 1 = X, 2 = Y, 3 = Z (``"3-1-3"`` is ``"ZXZ"``, paper 002's).
EULER_ALIASES = {"-".join(str("XYZ".index(c) + 1) for c in name): name for name in EULER_SEQUENCES}

#: The forms of an orientation, by the keys each one takes.
FORMS = {"axis": ("axis", "angle"), "euler": ("euler", "sequence"), "matrix": ("matrix",),
         "quaternion": ("quaternion",)}
FORM_EXAMPLES = ('{ axis = [0, 0, 1], angle = "30 deg" }',
                 '{ euler = ["10 deg", "20 deg", "30 deg"], sequence = "ZXZ" }',
                 "{ matrix = [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }", "{ quaternion = [1, 0, 0, 0] }")
IDENTITY = (1.0, 0.0, 0.0, 0.0)


class OrientationError(ValueError):
    """A value that is not an orientation, inertia tensor, 3-vector or marker; ``at`` is the key path under
    the value where the problem lies (``("matrix",)``), empty for the value itself."""

    def __init__(self, message: str, *at: Any):
        super().__init__(message)
        self.message = message
        self.at = at


def _show(raw: Any) -> str:
    from .modelfile.fields import _show as show

    return show(raw)


def _quantity(raw: Any, kind: str, **bounds: Any) -> float:
    """A quantity of ``kind`` in SI (the model file's reading: units, declared units of bare numbers)."""
    from pydantic_core import PydanticCustomError

    from .modelfile.fields import convert

    try:
        return float(convert(raw, kind, **bounds))
    except PydanticCustomError as exc:
        raise OrientationError(exc.message()) from None


def _numbers(raw: Any, n: int, what: str, example: str) -> list[Any]:
    if not isinstance(raw, (list, tuple)) or len(raw) != n:
        raise OrientationError(f"must be {what} (e.g. {example}), got {_show(raw)}")
    return list(raw)


def vector3(raw: Any, kind: str, **bounds: Any) -> list[float]:
    """``[x, y, z]``: three quantities of ``kind`` (``["0 mm", "10 mm", "5 mm"]``) in SI units, each within
    ``bounds`` (``ge=0``...) when given."""
    from .units import KINDS

    example = KINDS[kind].example
    items = _numbers(raw, 3, "three components [x, y, z]", f'["{example}", 0, 0]')
    out = []
    for axis, component in zip("xyz", items):
        try:
            out.append(_quantity(component, kind, **bounds))
        except OrientationError as exc:
            glue = ": " if exc.message.startswith("a bare number") else " "
            raise OrientationError(f"{axis} component{glue}{exc.message}") from None
    return out


def _plain(raw: Any, what: str) -> float:
    # (an integer beyond the floats' range is not finite either)
    if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(_as_float(raw)):
        raise OrientationError(f"{what} must be a finite plain number, got {_show(raw)}")
    return float(raw)


def _as_float(raw: int | float) -> float:
    """``raw`` as a float, infinity for an integer too large for one."""
    try:
        return float(raw)
    except OverflowError:
        return math.inf


def _plain_vector(raw: Any, n: int, what: str, example: str) -> np.ndarray:
    items = _numbers(raw, n, what, example)
    return np.array([_plain(v, f"component {k + 1}") for k, v in enumerate(items)])


def _nonzero_vector(raw: dict, key: str, n: int, what: str, example: str, zero: str) -> np.ndarray:
    """The vector ``raw[key]`` of ``n`` plain numbers, not zero (``zero``: the message if it is); errors located
    at ``key``."""
    try:
        vector = _plain_vector(raw[key], n, what, example)
    except OrientationError as exc:
        raise OrientationError(exc.message, key) from None
    if float(np.linalg.norm(vector)) == 0.0:
        raise OrientationError(zero, key)
    return vector


# orientations ---------------------------------------------------------------

def _rotation():
    from scipy.spatial.transform import Rotation

    return Rotation


def _scalar_first(rotation) -> list[float]:
    """A SciPy rotation's quaternion, scalar first, with w >= 0 (one of the two that give the rotation)."""
    x, y, z, w = rotation.as_quat()
    q = np.array([w, x, y, z])
    return [float(v) for v in (-q if w < 0 else q)]


def quaternion(raw: Any) -> list[float]:
    """The unit quaternion ``[w, x, y, z]`` (body -> global, active) of an orientation in any of the four
    forms (module doc), or of a SciPy ``Rotation`` (in Python); raises :class:`OrientationError`."""
    if _is_scipy_rotation(raw):
        if not raw.single:
            raise OrientationError(f"must be a single rotation, got a stack of {len(raw)}")
        return _scalar_first(raw)
    if not isinstance(raw, dict):
        raise OrientationError(f"must be a table in one of the forms {', '.join(FORM_EXAMPLES)}, got {_show(raw)}")
    form = _form(raw)
    return {"axis": _axis_angle, "euler": _euler, "matrix": _matrix, "quaternion": _quaternion}[form](raw)


def _is_scipy_rotation(raw: Any) -> bool:
    """Whether ``raw`` is a ``scipy.spatial.transform.Rotation`` (without importing SciPy for other values)."""
    return type(raw).__module__.startswith("scipy.spatial.transform") and hasattr(raw, "as_quat")


def _form(raw: dict) -> str:
    """The form an orientation table is written in, from its keys."""
    from .modelfile.fields import did_you_mean

    keys = [key for form in FORMS.values() for key in form]
    for key in raw:
        if key not in keys:
            raise OrientationError(f"unknown key{did_you_mean(key, keys)}; an orientation is one of "
                                   f"{', '.join(FORM_EXAMPLES)}", key)
    forms = [form for form, form_keys in FORMS.items() if any(key in raw for key in form_keys)]
    if len(forms) != 1:
        given = "none" if not forms else " and ".join(forms)
        raise OrientationError(f"give exactly one form of orientation, got {given}; the forms: "
                               f"{', '.join(FORM_EXAMPLES)}")
    form = forms[0]
    for key in FORMS[form]:
        if key not in raw:
            example = FORM_EXAMPLES[list(FORMS).index(form)]
            raise OrientationError(f"missing required value: {form} form needs {' and '.join(FORMS[form])}, "
                                   f"e.g. {example}", key)
    return form


def _axis_angle(raw: dict) -> list[float]:
    axis = _nonzero_vector(raw, "axis", 3, "a direction [x, y, z] of plain numbers", "[0, 0, 1]",
                           "must be a non-zero direction, got [0, 0, 0]")
    norm = float(np.linalg.norm(axis))
    try:
        angle = _quantity(raw["angle"], "angle")
    except OrientationError as exc:
        raise OrientationError(exc.message, "angle") from None
    return _scalar_first(_rotation().from_rotvec(axis / norm * angle))


def euler_sequence(raw: Any) -> str:
    """The upper-case intrinsic sequence named by ``raw`` (``"ZXZ"`` or ``"3-1-3"``)."""
    from .modelfile.fields import did_you_mean

    if isinstance(raw, str) and raw.strip() in EULER_SEQUENCES:
        return raw.strip()
    if isinstance(raw, str) and raw.strip() in EULER_ALIASES:
        return EULER_ALIASES[raw.strip()]
    if isinstance(raw, str) and raw.strip().upper() in EULER_SEQUENCES:
        raise OrientationError(f"must be written in upper case, {raw.strip().upper()!r}: the angles are intrinsic "
                               f"(each about an axis of the frame being turned), got {raw!r}", "sequence")
    raise OrientationError(f"must be an intrinsic Euler sequence, one of {', '.join(EULER_SEQUENCES)} (or by axis "
                           f"numbers, \"3-1-3\" for \"ZXZ\"), got {_show(raw)}"
                           f"{did_you_mean(raw, [*EULER_SEQUENCES, *EULER_ALIASES])}", "sequence")


def _euler(raw: dict) -> list[float]:
    sequence = euler_sequence(raw["sequence"])
    items = raw["euler"]
    if not isinstance(items, (list, tuple)) or len(items) != 3:
        raise OrientationError(f"must be three angles (e.g. [\"10 deg\", \"20 deg\", \"30 deg\"]), got "
                               f"{_show(raw['euler'])}", "euler")
    angles = []
    for k, item in enumerate(items):
        try:
            angles.append(_quantity(item, "angle"))
        except OrientationError as exc:
            raise OrientationError(exc.message, "euler", k) from None
    return _scalar_first(_rotation().from_euler(sequence, angles))


def _matrix(raw: dict) -> list[float]:
    rows = raw["matrix"]
    example = "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]"
    if not isinstance(rows, (list, tuple)) or len(rows) != 3:
        raise OrientationError(f"must be three rows of three plain numbers (e.g. {example}), got {_show(rows)}",
                               "matrix")
    matrix = np.empty((3, 3))
    for i, row in enumerate(rows):
        try:
            matrix[i] = _plain_vector(row, 3, "a row of three plain numbers", "[1, 0, 0]")
        except OrientationError as exc:
            raise OrientationError(exc.message, "matrix", i) from None
    check_rotation_matrix(matrix)
    return _scalar_first(_rotation().from_matrix(matrix))


def check_rotation_matrix(matrix: np.ndarray) -> None:
    """Raises :class:`OrientationError` at ``matrix`` unless it is a rotation within :data:`MATRIX_TOLERANCE`."""
    deviation = float(np.max(np.abs(matrix.T @ matrix - np.eye(3))))
    determinant = float(np.linalg.det(matrix))
    if deviation > MATRIX_TOLERANCE:
        raise OrientationError(f"is not a rotation: its columns must be orthonormal within {MATRIX_TOLERANCE:g}, "
                               f"but R^T R differs from the identity by {deviation:.3g}", "matrix")
    if abs(determinant - 1.0) > MATRIX_TOLERANCE:
        raise OrientationError(f"is not a rotation: its determinant must be +1 within {MATRIX_TOLERANCE:g}, got "
                               f"{determinant:.6g} (a reflection: one axis points the wrong way)", "matrix")


def _quaternion(raw: dict) -> list[float]:
    q = _nonzero_vector(raw, "quaternion", 4, "four plain numbers [w, x, y, z], scalar first", "[1, 0, 0, 0]",
                        "must not be zero: [w, x, y, z] is normalised, and a zero quaternion has no direction")
    norm = float(np.linalg.norm(q))
    if abs(norm - 1.0) <= ROUND_OFF:
        return [float(v) for v in q]  # unit already: kept as written, so that a written model reads back the same
    return [float(v) for v in q / norm]


def rotation_matrix(q: Any) -> np.ndarray:
    """The rotation matrix of a unit quaternion ``[w, x, y, z]`` (body -> global)."""
    w, x, y, z = q
    return _rotation().from_quat([x, y, z, w]).as_matrix()


def matrix_quaternion(matrix: Any) -> list[float]:
    """The unit quaternion ``[w, x, y, z]`` (w >= 0) of a rotation matrix."""
    return _scalar_first(_rotation().from_matrix(np.asarray(matrix, dtype=float)))


# inertia tensors ------------------------------------------------------------

INERTIA_FORMS = ('{ principal = ["1 kg m^2", "2 kg m^2", "2.5 kg m^2"], axes = <orientation> }',
                 '{ tensor = [["1 kg m^2", 0, 0], [0, "2 kg m^2", 0], [0, 0, "2.5 kg m^2"]] }')


def inertia_tensor(raw: Any) -> list[list[float]]:
    """The inertia tensor about the centre of mass in the body frame [kg m^2] (row lists) of
    ``{ principal = [J1, J2, J3], axes = <orientation> }`` (``R diag(J) R^T``, ``axes`` default identity) or
    ``{ tensor = [[...], [...], [...]] }``; raises :class:`OrientationError` unless it is a rigid body's."""
    if not isinstance(raw, dict):
        raise OrientationError(f"must be an inertia tensor, {' or '.join(INERTIA_FORMS)}, got {_show(raw)} (a "
                               "single moment of inertia is for planar models)")
    keys = ("principal", "axes", "tensor")
    from .modelfile.fields import did_you_mean

    for key in raw:
        if key not in keys:
            raise OrientationError(f"unknown key{did_you_mean(key, keys)}; an inertia tensor is "
                                   f"{' or '.join(INERTIA_FORMS)}", key)
    if ("tensor" in raw) == ("principal" in raw):
        given = "both" if "tensor" in raw else "neither"
        raise OrientationError(f"give exactly one of principal or tensor, got {given}: {' or '.join(INERTIA_FORMS)}")
    if "tensor" in raw:
        if "axes" in raw:
            raise OrientationError("goes with principal moments; a full tensor holds its axes already", "axes")
        tensor = _tensor(raw["tensor"])
        _check_tensor(tensor)
    else:
        moments = _principal(raw["principal"])
        rotation = rotation_matrix(_orientation_at(raw.get("axes"), "axes"))
        tensor = rotation @ np.diag(moments) @ rotation.T
        tensor = (tensor + tensor.T) / 2  # exactly symmetric, as a body's tensor is
    return [[float(v) for v in row] for row in tensor]


def _orientation_at(raw: Any, key: str) -> list[float]:
    if raw is None:
        return list(IDENTITY)
    try:
        return quaternion(raw)
    except OrientationError as exc:
        raise OrientationError(exc.message, key, *exc.at) from None


def _principal(raw: Any) -> np.ndarray:
    items = raw
    if not isinstance(items, (list, tuple)) or len(items) != 3:
        raise OrientationError(f"must be three principal moments (e.g. [\"1 kg m^2\", \"2 kg m^2\", "
                               f"\"2.5 kg m^2\"]), got {_show(raw)}", "principal")
    moments = []
    for k, item in enumerate(items):
        try:
            moments.append(_quantity(item, "inertia", gt=0))
        except OrientationError as exc:
            raise OrientationError(exc.message, "principal", k) from None
    moments = np.array(moments)
    violated = triangle_violation(moments)
    if violated:
        raise OrientationError(violated, "principal")
    return moments


def _tensor(raw: Any) -> np.ndarray:
    example = '[["1 kg m^2", 0, 0], [0, "2 kg m^2", 0], [0, 0, "2.5 kg m^2"]]'
    if not isinstance(raw, (list, tuple)) or len(raw) != 3 or not all(isinstance(r, (list, tuple)) and len(r) == 3
                                                                       for r in raw):
        raise OrientationError(f"must be three rows of three moments of inertia (e.g. {example}), got {_show(raw)}",
                               "tensor")
    tensor = np.empty((3, 3))
    for i, row in enumerate(raw):
        for j, item in enumerate(row):
            try:
                tensor[i, j] = _quantity(item, "inertia")
            except OrientationError as exc:
                raise OrientationError(exc.message, "tensor", i, j) from None
    return tensor


def _check_tensor(tensor: np.ndarray) -> None:
    scale = float(np.max(np.abs(tensor)))
    asymmetry = float(np.max(np.abs(tensor - tensor.T)))
    if asymmetry > INERTIA_TOLERANCE * scale:
        i, j = np.unravel_index(int(np.argmax(np.abs(tensor - tensor.T))), tensor.shape)
        raise OrientationError(f"must be symmetric: entry [{i}][{j}] = {tensor[i, j]:g} kg m^2 differs from "
                               f"[{j}][{i}] = {tensor[j, i]:g} kg m^2", "tensor")
    moments = np.linalg.eigvalsh((tensor + tensor.T) / 2)
    if scale == 0.0 or moments[0] <= INERTIA_TOLERANCE * scale:
        raise OrientationError(f"must be positive definite (a body has inertia about every axis), but its smallest "
                               f"principal moment is {moments[0]:.6g} kg m^2", "tensor")
    violated = triangle_violation(moments)
    if violated:
        raise OrientationError(violated, "tensor")


def triangle_violation(moments: np.ndarray) -> str:
    """``""`` when each principal moment is at most the sum of the other two (J_k = integral of the squared
    distance from axis k, so J1 + J2 - J3 = 2 integral z^2 dm >= 0), else the message naming the inequality
    that fails."""
    for k in range(3):
        i, j = [m for m in range(3) if m != k]
        if moments[i] + moments[j] < moments[k] * (1.0 - INERTIA_TOLERANCE):
            return (f"principal moments [{', '.join(f'{m:g}' for m in moments)}] kg m^2 violate the triangle "
                    f"inequality J{i + 1} + J{j + 1} >= J{k + 1} ({moments[i]:g} + {moments[j]:g} < "
                    f"{moments[k]:g} kg m^2): no rigid body has them")
    return ""


# markers --------------------------------------------------------------------

def marker(raw: Any) -> tuple[list[float], list[list[float]] | None]:
    """A point with an optional frame: ``["x", "y", "z"]`` or ``{ position = [...], axes = <orientation> }``;
    its position [m] and its axes as a rotation matrix (rows; columns the marker's x, y, z axes in its body's
    frame), None for the body's own axes."""
    if isinstance(raw, dict):
        from .modelfile.fields import did_you_mean

        for key in raw:
            if key not in ("position", "axes"):
                raise OrientationError(f"unknown key{did_you_mean(key, ['position', 'axes'])}; a point with axes "
                                       "is { position = [x, y, z], axes = <orientation> }", key)
        if "position" not in raw:
            raise OrientationError('missing required value: a point, e.g. ["0 mm", "10 mm", "5 mm"]', "position")
        try:
            position = vector3(raw["position"], "length")
        except OrientationError as exc:
            raise OrientationError(exc.message, "position") from None
        if raw.get("axes") is None:
            return position, None
        return position, axes_matrix(raw["axes"])
    return vector3(raw, "length"), None


def axes_matrix(raw: Any) -> list[list[float]]:
    """The rotation matrix (rows) of the axes of a marker given as an orientation; a matrix orthonormal to
    round-off is kept as written, other forms go through their quaternion."""
    q = _orientation_at(raw, "axes")
    if isinstance(raw, dict) and set(raw) == {"matrix"}:
        given = np.array(raw["matrix"], dtype=float)
        if float(np.max(np.abs(given.T @ given - np.eye(3)))) <= 4 * ROUND_OFF:
            return [[float(v) for v in row] for row in given]
    return [[float(v) for v in row] for row in rotation_matrix(q)]
