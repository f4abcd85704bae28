"""Light sources: coloured point lights and directional lights, any number of each.

A light's per-channel intensity IL is ``intensity * color``. A ``DirectionalLight``'s
``direction`` is the way its light travels (from the light into the scene), so the unit vector L
from a surface towards the light is ``-direction``.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from pixelpath import _validate as v
from pixelpath.scene._record import Record


@dataclasses.dataclass(frozen=True, eq=False)
class PointLight(Record):
    """A point light at ``position`` radiating ``intensity * color`` (no distance fall-off).

    Examples
    --------
    >>> from pixelpath.scene import PointLight
    >>> PointLight(position=(0, 5, 0), intensity=0.8).position.tolist()
    [0.0, 5.0, 0.0]
    """

    position: Any
    intensity: float = 1.0
    color: Any = (1.0, 1.0, 1.0)

    def __post_init__(self) -> None:
        self._set(
            position=v.vector3(self.position, "position"),
            intensity=v.real(self.intensity, "intensity", minimum=0.0),
            color=v.colour(self.color, "color"),
        )


@dataclasses.dataclass(frozen=True, eq=False)
class DirectionalLight(Record):
    """A light at infinity whose rays travel along ``direction`` (stored normalized).

    Examples
    --------
    >>> from pixelpath.scene import DirectionalLight
    >>> DirectionalLight(direction=(0, -2, 0)).direction.tolist()
    [0.0, -1.0, 0.0]
    """

    direction: Any
    intensity: float = 1.0
    color: Any = (1.0, 1.0, 1.0)

    def __post_init__(self) -> None:
        self._set(
            direction=v.unit_vector3(self.direction, "direction"),
            intensity=v.real(self.intensity, "intensity", minimum=0.0),
            color=v.colour(self.color, "color"),
        )
