"""The scene: a camera, objects (spheres, planes, boxes, meshes), lights and the ambient light.

``ambient`` is the ambient light intensity Ia of the Phong model, given as a scalar or per
channel (r, g, b) and stored as a (3,) array; ``background`` is the colour where nothing is hit.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record
from pixelpath.scene.animation import Animation, frame_number
from pixelpath.scene.camera import Camera
from pixelpath.scene.lights import DirectionalLight, PointLight
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.primitives import Box, Plane, Sphere

SceneObject = Sphere | Plane | Box | Mesh
Light = PointLight | DirectionalLight
OBJECT_TYPES = (Sphere, Plane, Box, Mesh)
LIGHT_TYPES = (PointLight, DirectionalLight)
ENCODINGS = ("linear", "srgb")


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
    animation : Animation, optional
        Camera and object keys over frames (see :mod:`pixelpath.scene.animation`); the scene
        as given is frame 0, and :meth:`at_frame` returns any other frame.
    encoding : {"linear", "srgb"}
        How the rendered pictures are written by default (``Image.save``): ``"linear"``
        maps intensity 0..1 to 0..255 as the notes do; ``"srgb"`` applies the sRGB curve, so
        that textures (decoded from sRGB to linear light) come out as bright as they were.
        Scenes loaded from model files (glTF, OBJ, ...) are ``"srgb"``.

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
    animation: Animation | None = None
    encoding: str = "linear"

    def __post_init__(self) -> None:
        self._set(
            camera=v.instance(self.camera, "camera", Camera),
            objects=_members(self.objects, "objects", OBJECT_TYPES),
            lights=_members(self.lights, "lights", LIGHT_TYPES),
            ambient=v.rgb_or_scalar(self.ambient, "ambient"),
            background=v.colour(self.background, "background"),
        )
        if self.animation is not None:
            v.instance(self.animation, "animation", Animation)
        if not isinstance(self.encoding, str) or self.encoding not in ENCODINGS:
            choices = ", ".join(ENCODINGS)
            raise ValueError(f"encoding must be one of {choices}; got {self.encoding!r}")
        if self.animation is not None:
            try:
                self.animation.check_scene(self.camera, self.objects)
            except ValueError as exc:
                raise ValueError(f"animation.{exc}") from None
        self._set(_orbit_center=self._turntable_center())

    def _turntable_center(self) -> np.ndarray | None:
        """Return the centre of the bounds when a turntable orbits it, else None."""
        turntable = None if self.animation is None else self.animation.turntable
        if turntable is None or turntable.center is not None:
            return None
        try:
            low, high = self.bounds()
        except ValueError:
            raise ValueError(
                "animation.turntable: the scene has no bounded objects to orbit; give the "
                "turntable a center"
            ) from None
        return v.frozen((low + high) / 2.0)

    def at_frame(self, frame: int) -> Scene:
        """Return the scene at ``frame`` of its animation: a scene without an animation.

        Frame 0 is the scene as written. A scene without an animation is the same at every
        frame (``frame`` >= 0); with one, ``frame`` must lie in ``0 .. animation.frames - 1``.

        Raises
        ------
        ValueError
            A frame outside the animation, or a camera the animation makes invalid there.

        Examples
        --------
        >>> from pixelpath.scene import Camera, Scene, Sphere
        >>> from pixelpath.scene.animation import Animation, frame_number, Turntable
        >>> scene = Scene(
        ...     Camera(eye=(0, 0, 5), target=(0, 0, 0)),
        ...     [Sphere((0, 0, 0), 1.0)],
        ...     animation=Animation(4, turntable=Turntable()),
        ... )
        >>> scene.at_frame(1).camera.eye.round(12).tolist()  # a quarter turn about +Y
        [5.0, 0.0, 0.0]
        """
        if self.animation is None:
            frame_number(frame, "frame")  # any frame >= 0: the scene is the same at every one
            return self
        objects = self.animation.objects_at(self.objects, frame)
        return dataclasses.replace(
            self, camera=self.camera_at(frame), objects=objects, animation=None
        )

    def camera_at(self, frame: int) -> Camera:
        """Return the camera at ``frame`` (cheaper than :meth:`at_frame` when only it is needed).

        Examples
        --------
        >>> from pixelpath.scene import Camera, Scene
        >>> Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0))).camera_at(7).eye.tolist()
        [0.0, 0.0, 5.0]
        """
        if self.animation is None:
            frame_number(frame, "frame")
            return self.camera
        return self.animation.camera_at(self.camera, frame, self._orbit_center)

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
