"""The scene: a camera, objects (spheres, planes, boxes, meshes), lights and the ambient light.

``ambient`` is the ambient light intensity Ia of the Phong model, given as a scalar or per
channel (r, g, b) and stored as a (3,) array; ``background`` is the colour where nothing is hit.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record
from pixelpath.scene.camera import Camera
from pixelpath.scene.lights import DirectionalLight, PointLight
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.primitives import Box, Plane, Sphere

SceneObject = Sphere | Plane | Box | Mesh
Light = PointLight | DirectionalLight
OBJECT_TYPES = (Sphere, Plane, Box, Mesh)
LIGHT_TYPES = (PointLight, DirectionalLight)


@dataclasses.dataclass(frozen=True, eq=False)
class Scene(Record):
    """Everything a renderer needs: camera, objects, lights, ambient light and background.

    Parameters
    ----------
    camera : Camera
    objects : sequence of Sphere, Plane, Box or Mesh
        Stored as a tuple. An empty scene is valid and renders as the background.
    lights : sequence of PointLight or DirectionalLight
        Stored as a tuple.
    ambient : float or (3,) array_like
        Ambient intensity Ia (scalar or per channel), non-negative; stored as (3,).
    background : (3,) array_like
        Colour of pixels that show no object.

    Examples
    --------
    >>> from pixelpath.scene import Camera, PointLight, Scene, Sphere
    >>> scene = Scene(
    ...     camera=Camera(eye=(0, 0, 5), target=(0, 0, 0)),
    ...     objects=[Sphere((0, 0, 0), 1.0)],
    ...     lights=[PointLight((5, 5, 5))],
    ... )
    >>> scene.ambient.tolist(), scene.bounds().tolist()
    ([0.1, 0.1, 0.1], [[-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]])
    """

    camera: Camera
    objects: Any = ()
    lights: Any = ()
    ambient: Any = 0.1
    background: Any = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        self._set(
            camera=v.instance(self.camera, "camera", Camera),
            objects=_members(self.objects, "objects", OBJECT_TYPES),
            lights=_members(self.lights, "lights", LIGHT_TYPES),
            ambient=v.rgb_or_scalar(self.ambient, "ambient"),
            background=v.colour(self.background, "background"),
        )

    def to_dict(self, base_dir: str | Path | None = None) -> dict[str, Any]:
        """Return the scene as a dict of plain values in the scene-file format.

        The dict holds only str, float, int, list and dict values, so it can be written as
        JSON or TOML, and ``Scene.from_dict(scene.to_dict())`` rebuilds an equal scene.
        Meshes read from a file, and generated ones (icosphere, torus, rotated box) that came
        from a scene file, are written as their file path or parameters with their transform;
        other meshes are written inline (vertices, faces, normals). Materials other than the
        default are gathered under ``materials`` as ``material1``, ``material2``, ...

        Parameters
        ----------
        base_dir : str or Path, optional
            Write mesh paths relative to this folder (default: absolute paths).

        Examples
        --------
        >>> from pixelpath.scene import Camera, Scene, Sphere
        >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), [Sphere((0, 0, 0), 1.0)])
        >>> scene.to_dict()["objects"]
        [{'type': 'sphere', 'center': [0.0, 0.0, 0.0], 'radius': 1.0}]
        >>> Scene.from_dict(scene.to_dict()) == scene
        True
        """
        from pixelpath.scene.loader import scene_to_dict

        return scene_to_dict(self, base_dir)

    @classmethod
    def from_dict(cls, data: dict[str, Any], base_dir: str | Path | None = None) -> Scene:
        """Build a scene from a dict in the scene-file format (as ``tomllib`` or JSON give it).

        Parameters
        ----------
        data : dict
            The scene (see ``docs/scene-format.md``).
        base_dir : str or Path, optional
            Folder that relative mesh paths start from (default: the working directory).

        Raises
        ------
        ValueError
            For unknown or missing keys and invalid values, naming the key path.

        Examples
        --------
        >>> from pixelpath.scene import Scene
        >>> scene = Scene.from_dict({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})
        >>> scene.camera.fov
        45.0
        """
        from pixelpath.scene.loader import scene_from_dict

        return scene_from_dict(data, base_dir=base_dir)

    def bounds(self) -> np.ndarray:
        """Return the (2, 3) bounding box of the bounded objects (planes are infinite).

        Raises
        ------
        ValueError
            When the scene has no bounded object.

        Examples
        --------
        >>> from pixelpath.scene import Box, Camera, Plane, Scene
        >>> camera = Camera(eye=(0, 0, 9), target=(0, 0, 0))
        >>> floor = Plane((0, 0, 0), (0, 1, 0))
        >>> Scene(camera, [floor, Box((0, 0, 0), (1, 1, 1))]).bounds().tolist()
        [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
        """
        boxes = [obj.bounds() for obj in self.objects if not isinstance(obj, Plane)]
        if not boxes:
            raise ValueError("the scene has no bounded objects (only planes, or none at all)")
        stacked = np.stack(boxes)
        return np.stack([stacked[:, 0].min(axis=0), stacked[:, 1].max(axis=0)])


def _members(values: Any, name: str, kinds: tuple[type, ...]) -> tuple[Any, ...]:
    if isinstance(values, str | bytes) or not hasattr(values, "__iter__"):
        raise TypeError(f"{name} must be a sequence, got {type(values).__name__}")
    items = tuple(values)
    for index, item in enumerate(items):
        v.instance(item, f"{name}[{index}]", kinds)
    return items
