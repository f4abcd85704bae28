"""Many frames: animations, datasets of views and huge tiled images, here or on a Dask cluster.

:func:`render_frames` renders frames of an animated scene (see
:mod:`pixelpath.scene.animation`) in this process, or on a ``dask.distributed`` cluster when
given a client, and :func:`render_views` a dataset of views of a model the same way
(:mod:`pixelpath.frames.views`; :mod:`pixelpath.frames.poses` places the cameras).
:mod:`pixelpath.frames.work` holds the pure per-frame functions the tasks run,
:mod:`pixelpath.frames.plan` checks a request before any work starts, and
:mod:`pixelpath.frames.cluster` (the ``dask`` extra) starts or reaches a cluster.

Examples
--------
>>> from pixelpath.frames import parse_frames, parse_tiles
>>> parse_frames("0:4"), parse_tiles("2x2")
([0, 1, 2, 3], (2, 2))
"""

from pixelpath.frames.plan import (
    FramePlan,
    frame_is_complete,
    parse_frames,
    parse_tiles,
    plan_frames,
    tile_regions,
)
from pixelpath.frames.run import render_frames, run_plan
from pixelpath.frames.views import plan_views, render_views, run_views
from pixelpath.frames.work import frame_file, render_frame, view_files

__all__ = [
    "FramePlan",
    "frame_file",
    "frame_is_complete",
    "parse_frames",
    "parse_tiles",
    "plan_frames",
    "plan_views",
    "render_frame",
    "render_frames",
    "render_views",
    "run_plan",
    "run_views",
    "tile_regions",
    "view_files",
]
