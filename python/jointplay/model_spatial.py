"""The spatial side of the :class:`jointplay.Model` builder: methods that add a planar or a spatial element by
the model's kinematics, elements of one kinematics only, and the reading of ``kinematics`` and of a spatial
gravity (docs/model-files.md, "Spatial models")."""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import Any

from .errors import ModelError

SPATIAL_HINT = 'Model(name, kinematics="spatial")'


def either(planar: Callable[..., str], spatial: Callable[..., str]) -> Callable[..., str]:
    """A builder method that adds ``planar``'s element to a planar model and ``spatial``'s to a spatial one; its
    signature is the planar method's, its docstring both."""

    def add(self: Any, *args: Any, **kwargs: Any) -> str:
        return (spatial if self.kinematics == "spatial" else planar)(self, *args, **kwargs)

    add.__signature__ = inspect.signature(planar)  # type: ignore[attr-defined]
    add.__name__, add.__qualname__ = planar.__name__, planar.__qualname__
    add.__doc__ = (f"{planar.__doc__}\n\nIn a spatial model ({SPATIAL_HINT}), its arguments are these:\n\n"
                   f"{spatial.__doc__}")
    add.planar, add.spatial = planar, spatial  # type: ignore[attr-defined]
    return add


def spatial_only(method: Callable[..., str], section: str, word: str) -> Callable[..., str]:
    """``method`` of spatial models; on a planar model a ModelError at ``<section>.<name>.type``."""

    @functools.wraps(method)
    def add(self: Any, name: str, *args: Any, **kwargs: Any) -> str:
        if self.kinematics != "spatial":
            raise ModelError([(f"{_where(section, name)}.type", f'"{word}" is available in spatial models only '
                                                               f"({SPATIAL_HINT})")])
        return method(self, name, *args, **kwargs)

    return add


def planar_only(method: Callable[..., str], location: Callable[[str], str], what: str) -> Callable[..., str]:
    """``method`` of planar models; on a spatial model a ModelError at ``location(name)`` saying ``what`` is not
    available there."""

    @functools.wraps(method)
    def add(self: Any, name: str, *args: Any, **kwargs: Any) -> str:
        if self.kinematics == "spatial":
            raise ModelError([(location(name), f"{what} not available in spatial models")])
        return method(self, name, *args, **kwargs)

    return add


def kinematics_of(raw: Any) -> str:
    """``"planar"`` or ``"spatial"``, read as the model file's ``[model] kinematics``."""
    from .modelfile import schema

    return _choice_of(schema.ModelTable, "kinematics", raw, "model")


def _choice_of(cls: Any, key: str, raw: Any, where: str) -> str:
    from pydantic_core import PydanticCustomError

    from .modelfile.arguments import _validator

    try:
        return _validator(cls, key)(raw)
    except PydanticCustomError as exc:
        raise ModelError([(f"{where}.{key}", exc.message())]) from None


def gravity3(raw: Any) -> list[float]:
    """The gravity of a spatial model [m/s^2]: three components (a pair is refused by name)."""
    from .modelfile.spatial import two_component_gravity

    pair = two_component_gravity(raw)
    if pair:
        raise ModelError([("model.gravity", pair)])
    return _arg("SpatialModelTable", "gravity", raw, "model")


def _where(section: str, name: str) -> str:
    from .modelfile.fields import join

    return join(section, name)


def _arg(table: str, key: str, raw: Any, where: str) -> Any:
    from .modelfile import arguments, schema

    return arguments.value(getattr(schema, table), key, raw, where)
