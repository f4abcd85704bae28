"""Animation: the camera and object transforms keyed over frames, and the turntable orbit.

A scene's :class:`Animation` has ``frames`` frames, numbered ``0 .. frames - 1``. Each keyed
property (the camera's ``eye``, ``target``, ``fov`` and ``view_height``; an object's
``translate``, ``rotate`` and ``scale``) is a track of the keys that set it:

- frame 0 is the scene as written (the camera's values; the identity transform for objects),
  and keys set values at later frames (1 .. frames - 1), so rendering the scene itself draws
  frame 0 and an animation only says what changes;
- between two keys the value moves from one to the other by the *start* key's interpolation:
  ``"linear"`` (constant speed) or ``"smooth"`` (eases out of the first key and into the
  second: the fraction ``t`` of the segment becomes ``3t² − 2t³``); after the last key it holds;
- keys give exact values at their frames.

An object's animated transform is ``transform_matrix(translate, rotate, scale)`` of its
interpolated tracks (angles interpolate as numbers, so ``rotate = [0, 360, 0]`` is a full spin)
applied to the object *as placed* by its own transform. Animated scales must be positive.

A :class:`Turntable` then turns the whole camera (eye and target) about the axis through a
centre (default: the centre of the scene's bounds) along the camera's ``up``: ``turns`` full
turns over the animation, counter-clockwise seen from above for positive ``turns``; frame
``frames`` would equal frame 0, so the frames loop seamlessly.
"""

from __future__ import annotations

import bisect
import dataclasses
import math
import numbers
from collections.abc import Sequence
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record
from pixelpath.scene.camera import Camera
from pixelpath.scene.primitives import Sphere
from pixelpath.scene.transform import transform_matrix, transform_object

INTERPOLATIONS = ("linear", "smooth")
MAX_FRAMES = 1_000_000
CAMERA_TRACKS = ("eye", "target", "fov", "view_height")
OBJECT_TRACKS = ("translate", "rotate", "scale")
_IDENTITY = {"translate": np.zeros(3), "rotate": np.zeros(3), "scale": np.ones(3)}


def ease(t: float, interpolation: str) -> float:
    """Return the fraction of a segment covered at fraction ``t`` of its frames.

    Examples
    --------
    >>> from pixelpath.scene.animation import ease
    >>> ease(0.25, "linear"), ease(0.25, "smooth"), ease(0.5, "smooth")
    (0.25, 0.15625, 0.5)
    """
    if interpolation == "smooth":
        return t * t * (3.0 - 2.0 * t)
    return t


@dataclasses.dataclass(frozen=True, eq=False)
class CameraKey(Record):
    """The camera values set at one frame.

    Parameters
    ----------
    frame : int
        The frame (>= 1; frame 0 is the scene's camera) at which the camera has these values.
    eye, target : (3,) array_like, optional
        Camera position and the point looked at.
    fov : float, optional
        Vertical field of view in degrees, in (0, 180).
    interpolation : {"linear", "smooth"}, optional
        How values move from this key to the next (default: the animation's).
    view_height : float, optional
        The view's height in world units, > 0: the zoom of an orthographic camera (keys of it
        on a perspective camera are a ValueError when the animation meets the scene).

    Examples
    --------
    >>> from pixelpath.scene.animation import CameraKey
    >>> CameraKey(30, eye=(0, 2, 6)).eye.tolist()
    [0.0, 2.0, 6.0]
    >>> CameraKey(30, view_height=8).view_height
    8.0
    """

    frame: int
    eye: Any = None
    target: Any = None
    fov: Any = None
    interpolation: str | None = None
    view_height: Any = None

    def __post_init__(self) -> None:
        values = {name: getattr(self, name) for name in CAMERA_TRACKS}
        if all(value is None for value in values.values()):
            raise ValueError(
                "a camera key must set at least one of eye, target, fov, view_height"
            )
        fov = self.fov
        if fov is not None:
            fov = v.real(fov, "fov")
            if not 0.0 < fov < 180.0:
                raise ValueError(f"fov (vertical, in degrees) must lie in (0, 180), got {fov}")
        self._set(
            frame=frame_number(self.frame, "frame"),
            eye=None if self.eye is None else v.vector3(self.eye, "eye"),
            target=None if self.target is None else v.vector3(self.target, "target"),
            fov=fov,
            interpolation=_interpolation(self.interpolation, optional=True),
            view_height=None if self.view_height is None
            else v.real(self.view_height, "view_height", positive=True),
        )


@dataclasses.dataclass(frozen=True, eq=False)
class ObjectKey(Record):
    """The animated transform of one object at one frame.

    Parameters
    ----------
    object : int
        Index of the object in ``scene.objects``.
    frame : int
        The frame (>= 1; frame 0 is the scene as written) at which the object has this
        transform.
    translate, rotate : (3,) array_like, optional
        Offset, and angles in degrees about X, then Y, then Z (as in ``transform``).
    scale : float or (3,) array_like, optional
        Positive factors, uniform or per axis; stored as (3,).
    interpolation : {"linear", "smooth"}, optional
        How values move from this key to the next (default: the animation's).

    Examples
    --------
    >>> from pixelpath.scene.animation import ObjectKey
    >>> ObjectKey(2, frame=10, scale=2).scale.tolist()
    [2.0, 2.0, 2.0]
    """

    object: int
    frame: int
    translate: Any = None
    rotate: Any = None
    scale: Any = None
    interpolation: str | None = None

    def __post_init__(self) -> None:
        if all(getattr(self, name) is None for name in OBJECT_TRACKS):
            raise ValueError("an object key must set at least one of translate, rotate, scale")
        scale = self.scale
        if scale is not None:
            uniform = isinstance(scale, numbers.Real) and not isinstance(scale, bool)
            scale = v.vector3((scale,) * 3 if uniform else scale, "scale")
            if np.any(scale <= 0.0):
                raise ValueError(f"scale factors must be positive, got {scale.tolist()}")
        self._set(
            object=frame_number(self.object, "object"),
            frame=frame_number(self.frame, "frame"),
            translate=None if self.translate is None else v.vector3(self.translate, "translate"),
            rotate=None if self.rotate is None else v.vector3(self.rotate, "rotate"),
            scale=scale,
            interpolation=_interpolation(self.interpolation, optional=True),
        )


@dataclasses.dataclass(frozen=True, eq=False)
class Turntable(Record):
    """An orbit of the whole camera about a vertical axis, over the whole animation.

    Parameters
    ----------
    turns : float
        Full turns over the animation (non-zero; negative turns clockwise seen from above).
    center : (3,) array_like, optional
        A point on the axis; default: the centre of the scene's bounds.

    Examples
    --------
    >>> from pixelpath.scene.animation import Turntable
    >>> Turntable(turns=0.5).turns
    0.5
    """

    turns: float = 1.0
    center: Any = None

    def __post_init__(self) -> None:
        turns = v.real(self.turns, "turns")
        if turns == 0.0:
            raise ValueError("turns must be non-zero (full turns over the animation)")
        center = None if self.center is None else v.vector3(self.center, "center")
        self._set(turns=turns, center=center)


@dataclasses.dataclass(frozen=True, eq=False)
class Animation(Record):
    """Keyframes of the camera and of object transforms over ``frames`` frames.

    Parameters
    ----------
    frames : int
        Number of frames (1..1,000,000), numbered from 0.
    camera : sequence of CameraKey
        Camera keys, at distinct frames.
    objects : sequence of ObjectKey
        Object keys, at distinct frames for each object.
    turntable : Turntable, optional
        An orbit of the camera about the scene over the animation.
    interpolation : {"linear", "smooth"}
        Interpolation of the keys that do not name their own.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.scene.animation import Animation, CameraKey
    >>> anim = Animation(5, camera=[CameraKey(4, eye=(0, 0, 9))])
    >>> camera = Camera(eye=(0, 0, 5), target=(0, 0, 0))
    >>> [float(anim.camera_at(camera, f).eye[2]) for f in range(5)]
    [5.0, 6.0, 7.0, 8.0, 9.0]
    """

    frames: int
    camera: Any = ()
    objects: Any = ()
    turntable: Turntable | None = None
    interpolation: str = "linear"

    def __post_init__(self) -> None:
        frames = frame_number(self.frames, "frames")
        if not 1 <= frames <= MAX_FRAMES:
            raise ValueError(f"frames must be between 1 and {MAX_FRAMES:,}, got {frames}")
        camera = _keys(self.camera, "camera", CameraKey, frames, lambda key: key.frame)
        objects = _keys(
            self.objects, "objects", ObjectKey, frames, lambda key: (key.object, key.frame)
        )
        if self.turntable is not None:
            v.instance(self.turntable, "turntable", Turntable)
        self._set(
            frames=frames,
            camera=camera,
            objects=objects,
            interpolation=_interpolation(self.interpolation, optional=False),
        )

    def checkframe_number(self, frame: Any) -> int:
        """Return ``frame`` as an int after checking that it lies in ``0 .. frames - 1``."""
        number = frame_number(frame, "frame")
        if number >= self.frames:
            raise ValueError(
                f"frame {number} is outside the animation (frames 0..{self.frames - 1})"
            )
        return number

    def camera_at(self, camera: Camera, frame: int, center: Any = None) -> Camera:
        """Return the camera at ``frame``, starting from the scene's ``camera``.

        ``center`` is the turntable's axis point when the turntable names none.
        """
        frame = self.checkframe_number(frame)
        if not camera.orthographic and any(key.view_height is not None for key in self.camera):
            raise ValueError(
                "view_height keys zoom an orthographic camera; this camera is perspective "
                "(key its fov instead)"
            )
        values = {
            name: _track_value(
                self.camera, name, frame, getattr(camera, name), self.interpolation
            )
            for name in CAMERA_TRACKS
        }
        eye, target = np.asarray(values["eye"]), np.asarray(values["target"])
        if self.turntable is not None and frame:  # frame 0 is the camera as written, exactly
            pivot = self.turntable.center if self.turntable.center is not None else center
            if pivot is None:
                raise ValueError("the turntable needs a center (the scene has no bounds)")
            angle = 2.0 * math.pi * self.turntable.turns * frame / self.frames
            turn = _rotation_about(camera.up, angle)
            eye, target = (pivot + turn @ (point - pivot) for point in (eye, target))
        height = values["view_height"]  # None for a perspective camera
        return dataclasses.replace(camera, eye=eye, target=target, fov=float(values["fov"]),
                                   view_height=None if height is None else float(height))

    def matrix_at(self, index: int, frame: int) -> np.ndarray | None:
        """Return the animated (4, 4) transform of object ``index`` at ``frame`` (None: unkeyed)."""
        keys = [key for key in self.objects if key.object == index]
        if not keys:
            return None
        frame = self.checkframe_number(frame)
        parts = {
            name: _track_value(keys, name, frame, _IDENTITY[name], self.interpolation)
            for name in OBJECT_TRACKS
        }
        return transform_matrix(**parts)

    def objects_at(self, objects: Sequence[Any], frame: int) -> tuple[Any, ...]:
        """Return ``objects`` moved by their animated transforms at ``frame``."""
        moved = []
        for index, obj in enumerate(objects):
            matrix = self.matrix_at(index, frame)
            unchanged = matrix is None or np.array_equal(matrix, np.eye(4))
            moved.append(obj if unchanged else transform_object(obj, matrix))
        return tuple(moved)

    def check_scene(self, camera: Camera, objects: Sequence[Any]) -> None:
        """Raise ValueError, naming the key, if a key does not fit the scene's objects or camera.

        Messages start with the key (``objects[2]: ...``, ``camera[0]: ...``). The turntable is
        left out of the camera check: turning the camera rigidly cannot make it invalid.
        """
        for position, key in enumerate(self.objects):
            try:
                check_object_key(key, objects)
            except ValueError as exc:
                raise ValueError(f"objects[{position}]: {exc}") from None
        keyed_only = dataclasses.replace(self, turntable=None)
        for position, key in enumerate(self.camera):
            try:
                keyed_only.camera_at(camera, key.frame)
            except ValueError as exc:
                raise ValueError(f"camera[{position}]: at frame {key.frame}: {exc}") from None


def check_object_key(key: ObjectKey, objects: Sequence[Any]) -> None:
    """Raise ValueError if ``key`` names no object of ``objects`` or scales a sphere unevenly."""
    if key.object >= len(objects):
        raise ValueError(
            f"object {key.object} does not exist (the scene has {len(objects)} objects, "
            f"numbered from 0)"
        )
    scale = key.scale
    if isinstance(objects[key.object], Sphere) and scale is not None:
        if not np.all(scale == scale[0]):
            raise ValueError(
                f"scale must be uniform for a sphere, got {scale.tolist()} (use an icosphere "
                f"for an ellipsoid)"
            )


def frame_number(value: Any, name: str) -> int:
    """Return ``value`` as an int after checking that it is an integer >= 0."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an int, got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be >= 0, got {value}")
    return int(value)


def _interpolation(value: Any, *, optional: bool) -> str | None:
    if value is None and optional:
        return None
    if value not in INTERPOLATIONS:
        raise ValueError(
            f"interpolation must be one of {', '.join(map(repr, INTERPOLATIONS))}, got {value!r}"
        )
    return value


def _keys(values: Any, name: str, kind: type, frames: int, identity: Any) -> tuple[Any, ...]:
    """Return the keys (in the order given) after checking their type, frame and uniqueness."""
    if isinstance(values, str | bytes) or not hasattr(values, "__iter__"):
        raise TypeError(f"{name} must be a sequence of {kind.__name__}, got {values!r}")
    keys = tuple(values)
    seen: dict[Any, int] = {}
    for position, key in enumerate(keys):
        v.instance(key, f"{name}[{position}]", kind)
        if key.frame == 0:
            raise ValueError(
                f"{name}[{position}]: frame 0 is the scene as written (its camera and "
                f"objects); keys set values at frames 1..{frames - 1}"
            )
        if key.frame >= frames:
            raise ValueError(
                f"{name}[{position}]: frame {key.frame} is outside the animation "
                f"(frames 0..{frames - 1}; keys at 1..{frames - 1})"
            )
        if identity(key) in seen:
            raise ValueError(
                f"{name}[{position}]: a second key at frame {key.frame} (the first is "
                f"{name}[{seen[identity(key)]}])"
            )
        seen[identity(key)] = position
    return keys


def _track_value(keys: Sequence[Any], name: str, frame: int, start: Any, default: str) -> Any:
    """Interpolate property ``name`` over the keys that set it, from ``start`` at frame 0."""
    keyed = sorted((key for key in keys if getattr(key, name) is not None), key=_frame_of)
    track = [(0, start, default)]
    track += [(key.frame, getattr(key, name), key.interpolation or default) for key in keyed]
    frames = [entry[0] for entry in track]
    index = bisect.bisect_right(frames, frame) - 1
    first, value, interpolation = track[index]
    if index + 1 == len(track):
        return value
    last, after, _ = track[index + 1]
    fraction = ease((frame - first) / (last - first), interpolation)
    return value + fraction * (np.asarray(after) - value) if fraction else value


def _frame_of(key: Any) -> int:
    return key.frame


def _rotation_about(axis: np.ndarray, angle: float) -> np.ndarray:
    """Return the (3, 3) rotation by ``angle`` radians about ``axis`` (Rodrigues' formula)."""
    x, y, z = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    cross = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + math.sin(angle) * cross + (1.0 - math.cos(angle)) * (cross @ cross)
