"""Small animated scenes for the frame tests, and a scene that counts how often it is sent.

Worker processes import this module by name (they inherit the test process's ``sys.path``).
"""

from __future__ import annotations

import dataclasses

import pixelpath as pp
from pixelpath.scene import Animation, CameraKey, ObjectKey, Turntable

# How many scenes this process has pickled (sent) and unpickled (a worker receiving one).
PICKLED = 0
UNPICKLED = 0


def animated_scene(frames: int = 6, width: int = 32, height: int = 24) -> pp.Scene:
    """A box, an icosphere and a floor; the camera moves in, the box slides, all turning."""
    icosphere = pp.scene.icosphere(subdivisions=1, radius=0.6, center=(1.4, 0.6, 0.5))
    return pp.Scene(
        camera=pp.Camera(eye=(0, 2, 6), target=(0, 0.5, 0), width=width, height=height),
        objects=[
            pp.Plane((0, 0, 0), (0, 1, 0)),
            pp.Box((-1.5, 0, -0.5), (-0.5, 1, 0.5), pp.Material(color=(0.9, 0.2, 0.1))),
            icosphere,
        ],
        lights=[pp.PointLight((3, 5, 4))],
        animation=Animation(
            frames,
            camera=[CameraKey(frames - 1, eye=(0, 2.5, 4.5), fov=50)],
            objects=[ObjectKey(1, frames - 1, translate=(0.5, 0, 0), rotate=(0, 90, 0))],
            turntable=Turntable(turns=0.5),
            interpolation="smooth",
        ),
    )


def unpickled_count() -> int:
    """Return how many scenes this process has unpickled (run on workers by client.run)."""
    return UNPICKLED


def _rebuild(fields: dict) -> CountingScene:
    global UNPICKLED
    UNPICKLED += 1
    return CountingScene(**fields)


@dataclasses.dataclass(frozen=True, eq=False)
class CountingScene(pp.Scene):
    """A Scene that counts each time it is pickled, and in the receiving process unpickled."""

    def __reduce__(self):
        global PICKLED
        PICKLED += 1
        fields = {field.name: getattr(self, field.name) for field in dataclasses.fields(self)}
        return _rebuild, (fields,)


def counting(scene: pp.Scene) -> CountingScene:
    """Return ``scene`` as a CountingScene."""
    fields = {field.name: getattr(scene, field.name) for field in dataclasses.fields(scene)}
    return CountingScene(**fields)


class BrokenScene(pp.Scene):
    """What a :func:`broken_on_workers` scene becomes in a worker: frame 3 raises."""

    def at_frame(self, frame: int) -> pp.Scene:
        if frame == 3:
            raise ZeroDivisionError("frame 3 cannot be drawn")
        return super().at_frame(frame)


def _rebuild_broken(fields: dict) -> BrokenScene:
    return BrokenScene(**fields)


@dataclasses.dataclass(frozen=True, eq=False)
class _BreaksWhenSent(pp.Scene):
    def __reduce__(self):
        fields = {field.name: getattr(self, field.name) for field in dataclasses.fields(self)}
        return _rebuild_broken, (fields,)


def broken_on_workers(scene: pp.Scene) -> pp.Scene:
    """Return ``scene`` as one that renders here but fails on frame 3 wherever it is sent."""
    fields = {field.name: getattr(scene, field.name) for field in dataclasses.fields(scene)}
    return _BreaksWhenSent(**fields)
