"""Datasets of views: a model in, a NeRF-style dataset out (images, depth, normals, masks, poses).

:func:`render_views` places ``n`` cameras round a model (:mod:`pixelpath.frames.poses`), renders
each view with the frames machinery (here, or on a Dask cluster whose workers write the files),
and writes ``transforms.json`` last, in the layout NeRF, nerfstudio and instant-ngp read:

=========================  =========================================================================
file                       contents
=========================  =========================================================================
``images/view_0000.png``   the picture: RGB, or RGBA with ``transparent=True`` (NeRF-synthetic's
                           choice: the background is alpha 0), in the scene's encoding (sRGB for
                           model files)
``depth/view_0000.npy``    float32 (H, W) distance along the viewing axis, in the model's units;
                           0 where no surface was drawn (what nerfstudio reads as "no depth")
``normals/view_0000.png``  8-bit RGB ``(n + 1) / 2`` of the unit world-space normal; 0 where none
``masks/view_0000.png``    8-bit, 255 where a surface was drawn, 0 elsewhere
``transforms.json``        intrinsics and one ``transform_matrix`` (camera-to-world) per view
=========================  =========================================================================

Depth is a float32 ``.npy`` rather than a 16-bit PNG: it keeps the renderer's depth exactly,
with no scale to choose for the model's size (a millimetre step would flatten a small model,
and a 16-bit range would clip a large one). ``transforms.json`` says so with
``"depth_unit_scale_factor": 1.0``: nerfstudio multiplies ``.npy`` depths by its data parser's
``depth_unit_scale_factor`` (default 0.001, meant for millimetre PNGs), so set it to 1.

Poses and depths are in the model file's own world coordinates (its node transforms applied;
nothing recentred or rescaled). Every file is written atomically, and ``transforms.json`` only
once every view is on disk: a folder holding ``transforms.json`` holds a whole dataset.
"""

from __future__ import annotations

import dataclasses
import functools
import io
import json
import math
import numbers
import os
import re
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import numpy as np

from pixelpath.frames import poses as _poses
from pixelpath.frames.plan import (
    FRAMES_PNG_LEVEL,
    check_tile_size,
    checked_gamma,
    render_options,
)
from pixelpath.frames.poses import ViewCameras
from pixelpath.frames.writer import FrameWriter
from pixelpath.image import Image
from pixelpath.io.aovs import parse_aovs
from pixelpath.io.images import png_level_of
from pixelpath.scene import Camera, Scene

__all__ = [
    "VIEW_AOVS",
    "ViewJob",
    "ViewOutput",
    "ViewPlan",
    "plan_views",
    "render_views",
    "run_views",
]

VIEW_AOVS = ("depth", "normal", "mask")
FOLDERS = {"image": "images", "depth": "depth", "normal": "normals", "mask": "masks"}
SUFFIXES = {"image": ".png", "depth": ".npy", "normal": ".png", "mask": ".png"}
JSON_KEYS = {"depth": "depth_file_path", "normal": "normal_file_path", "mask": "mask_path"}
DEFAULT_SIZE = (800, 800)
# Written first: the request that made the folder's views, so --resume can tell a folder of
# this dataset's views from one of another's (transforms.json comes only at the end).
REQUEST_FILE = ".pixelpath-views.json"
# Views per task on a cluster. Each task costs the client and the scheduler about 2 ms of CPU
# (workers write the views' files, so nothing comes back but the task's end); the frames'
# guided self-scheduling takes batches of up to MOST_VIEWS_PER_TASK views, and none smaller
# than 1/SHARES_PER_WORKER of a worker's share of the views: the last tasks even out the end
# (to within 5 % of a worker's time) without thousands of single-view tasks on a big cluster.
MOST_VIEWS_PER_TASK = 64
SHARES_PER_WORKER = 20
_VIEW_FILE = re.compile(r"view_\d+\.(png|npy)")
# What an atomic write leaves when its process dies half-way (a worker killed mid-view).
_HALF_WRITTEN = re.compile(r"\.view_\d+\.(png|npy)\..+\.tmp")


@dataclasses.dataclass(frozen=True)
class ViewOutput:
    """Where and how each view's files are written (what a worker needs to write them).

    Attributes
    ----------
    folder : str
        The dataset's folder.
    count : int
        Number of views (it sets the width of the numbers in the file names, 4 at least).
    aovs : tuple of str
        The buffers written beside the pictures, from :data:`VIEW_AOVS`.
    transparent : bool
        RGBA pictures whose alpha is the coverage.
    gamma : float, "srgb", "linear" or None
        Display encoding of the pictures (None: the scene's ``encoding``).
    png_level : int or None
        zlib compression level of the PNG files, pictures and AOVs (None: 6, as
        ``Image.save``).
    """

    folder: str
    count: int
    aovs: tuple[str, ...] = ()
    transparent: bool = False
    gamma: float | str | None = None
    png_level: int | None = None

    def relative(self, index: int, kind: str) -> str:
        """Return the path of view ``index``'s ``kind`` file, relative to the folder.

        Examples
        --------
        >>> from pixelpath.frames.views import ViewOutput
        >>> ViewOutput("out", 100, ("depth",)).relative(7, "depth")
        'depth/view_0007.npy'
        """
        digits = max(4, len(str(self.count - 1)))
        return f"{FOLDERS[kind]}/view_{index:0{digits}d}{SUFFIXES[kind]}"

    def kinds(self) -> tuple[str, ...]:
        """Return the kinds of file each view has: ``"image"`` then the AOVs."""
        return ("image", *self.aovs)

    def path(self, index: int, kind: str) -> Path:
        """Return the file of view ``index``'s ``kind`` (``"image"`` or an AOV)."""
        return Path(self.folder) / self.relative(index, kind)

    def write(self, index: int, image: Image) -> None:
        """Write view ``index``'s picture and AOVs, each file atomically."""
        from pixelpath.io.images import write_bytes

        for kind in self.kinds():
            path = self.path(index, kind)
            path.parent.mkdir(parents=True, exist_ok=True)
            write_bytes(path, self.encode(image, kind))

    def submit(self, index: int, image: Image, writer: FrameWriter) -> None:
        """Hand view ``index``'s files to ``writer``'s threads, to encode and write them."""
        for kind in self.kinds():
            path = self.path(index, kind)
            path.parent.mkdir(parents=True, exist_ok=True)
            writer.submit(path, functools.partial(self.encode, image, kind))

    def encode(self, image: Image, kind: str) -> bytes:
        """Return the bytes of the ``kind`` file of ``image``."""
        from pixelpath.frames.work import encode
        from pixelpath.io.aovs import encode_aov

        if kind == "image":
            return encode(
                image, ".png", self.gamma, alpha=self.transparent, png_level=self.png_level
            )
        if kind == "depth":
            buffer = io.BytesIO()
            depth = image.depth
            np.save(buffer, np.where(np.isfinite(depth), depth, 0.0).astype(np.float32))
            return buffer.getvalue()
        return encode_aov(image, kind, self.png_level)

    def is_complete(self, index: int, width: int, height: int) -> bool:
        """Return True when every file of view ``index`` is on disk, whole and of the size."""
        from pixelpath.frames.plan import frame_is_complete

        for kind in self.kinds():
            path = self.path(index, kind)
            if kind != "depth":
                if not frame_is_complete(path, width, height):
                    return False
                continue
            try:
                depth = np.load(path, allow_pickle=False)
            except (OSError, ValueError, EOFError):
                return False
            if depth.shape != (height, width) or depth.dtype != np.float32:
                return False
        return True


@dataclasses.dataclass(frozen=True, eq=False)
class ViewJob:
    """Everything a worker needs for any view of a dataset; sent to each worker once.

    Attributes
    ----------
    scene : Scene
        The scene (frame 0 of its animation); each view replaces its camera.
    cameras : ViewCameras
        The views' cameras.
    options : dict
        Keywords of :func:`pixelpath.render`.
    output : ViewOutput
        The files' folder, names and formats.
    """

    scene: Scene
    cameras: ViewCameras
    options: dict[str, Any]
    output: ViewOutput

    def render(self, index: int) -> Image:
        """Return view ``index``, rendered."""
        from pixelpath.renderer import render

        camera = self.cameras.camera(index)
        return render(dataclasses.replace(self.scene, camera=camera), **self.options)


@dataclasses.dataclass(frozen=True, eq=False)
class ViewPlan:
    """A checked dataset request: the job, the views still to render, and what made it.

    Attributes
    ----------
    job : ViewJob
        The scene, cameras, render options and files.
    todo : tuple of int
        The views to render (all but those complete on disk, with ``resume``).
    request : dict
        What made the dataset (JSON-serializable); stored in the folder so that ``resume``
        only ever completes the same dataset, and in ``transforms.json``.
    """

    job: ViewJob
    todo: tuple[int, ...]
    request: dict[str, Any]

    def transforms(self) -> dict[str, Any]:
        """Return the ``transforms.json`` document (NeRF-synthetic / nerfstudio layout)."""
        cameras, output = self.job.cameras, self.job.output
        width, height = cameras.size
        focal = (height / 2.0) / math.tan(math.radians(cameras.fov) / 2.0)  # square pixels
        frames = []
        for index, pose in enumerate(cameras.poses().tolist()):
            frame = {"file_path": output.relative(index, "image"), "transform_matrix": pose}
            for aov in output.aovs:
                frame[JSON_KEYS[aov]] = output.relative(index, aov)
            frames.append(frame)
        document = {
            "camera_model": "PINHOLE",
            "camera_angle_x": 2.0 * math.atan(width / (2.0 * focal)),
            "camera_angle_y": math.radians(cameras.fov),
            "fl_x": focal,
            "fl_y": focal,
            "cx": width / 2.0,
            "cy": height / 2.0,
            "w": width,
            "h": height,
        }
        if "depth" in output.aovs:
            document["depth_unit_scale_factor"] = 1.0
        document["frames"] = frames
        document["pixelpath"] = self.request
        return document


def render_views(
    scene_or_path: Scene | str | os.PathLike,
    n: int,
    out: str | os.PathLike,
    aovs: Iterable[str] | str = (),
    client: Any = None,
    *,
    layout: str = "orbit",
    seed: int = 0,
    elevation: float | None = None,
    hemisphere: bool = True,
    distance: float | None = None,
    size: tuple[int, int] | None = None,
    fov: float | None = None,
    transparent: bool = False,
    gamma: float | str | None = None,
    png_level: int | None = FRAMES_PNG_LEVEL,
    resume: bool = False,
    overwrite: bool = False,
    up: str = "+y",
    progress: Callable[[int], None] | None = None,
    **options: Any,
) -> np.ndarray:
    """Render ``n`` views of a model into a NeRF-style dataset; return the poses.

    Parameters
    ----------
    scene_or_path : Scene, str or path-like
        A Scene, or a model file (``.glb .gltf .obj .ply .stl``) or scene file to load.
    n : int
        Number of views.
    out : str or path-like
        The dataset's folder (created). A folder that already holds a dataset is refused
        unless ``resume`` (complete this one) or ``overwrite`` (replace it).
    aovs : iterable of str or str
        Buffers written beside each picture: ``"depth"``, ``"normal"``, ``"mask"``.
    client : dask.distributed.Client, optional
        Render on this client's cluster; its workers write the files, so they must see
        ``out`` at the same path (a local cluster always does).
    layout : {"orbit", "sphere", "random"}
        Where the cameras stand (:func:`pixelpath.frames.poses.view_directions`).
    seed : int
        Seed of the ``random`` layout.
    elevation : float, optional
        The orbit's height in degrees (default 22).
    hemisphere : bool
        ``sphere`` and ``random`` views from above the horizon only (default).
    distance : float, optional
        The cameras' distance from the model's centre (default: the model framed in every
        view, all cameras at one distance).
    size : (int, int), optional
        Width and height (default: the Scene's camera size, or 800 x 800 for a file).
    fov : float, optional
        Vertical field of view in degrees (default: the scene camera's when perspective,
        else 45).
    transparent : bool
        RGBA pictures, the background transparent.
    gamma : float, "srgb" or "linear", optional
        Display encoding of the pictures (default: the scene's).
    png_level : int or None
        zlib compression level of the PNG files, the pictures and the normals and masks, 0
        to 9 (default 1, fast, as :func:`pixelpath.render_frames`); None: 6, the bytes
        ``Image.save`` writes.
    resume : bool
        Keep the views already complete on disk (each file read back) and render the rest.
    overwrite : bool
        Delete the folder's previous dataset (its ``view_*`` files and ``transforms.json``).
    up : str
        A model file's up axis, turned to point up (+Y) before the views are placed round it:
        ``"+z"`` for most CAD and 3D-printing files (see :func:`pixelpath.load_scene`).
    progress : callable, optional
        Called with a count of views each time some are written.
    **options
        Keywords of :func:`pixelpath.render`: ``method``, ``shading``, ``ssaa``, ...

    Returns
    -------
    ndarray
        (n, 4, 4) camera-to-world matrices (OpenGL axes), as in ``transforms.json``.

    Raises
    ------
    ValueError, TypeError
        For bad requests, before anything is written.

    Examples
    --------
    >>> import json, os, tempfile
    >>> import pixelpath as pp
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=32, height=32),
    ...                  [pp.Sphere((0, 0, 0), 1.0)], [pp.PointLight((2, 3, 4))])
    >>> folder = os.path.join(tempfile.mkdtemp(), "views")
    >>> poses = pp.render_views(scene, 8, folder, aovs="depth,mask")
    >>> poses.shape
    (8, 4, 4)
    >>> with open(os.path.join(folder, "transforms.json")) as f:
    ...     document = json.load(f)
    >>> document["w"], document["frames"][1]["depth_file_path"]
    (32, 'depth/view_0001.npy')
    """
    plan = plan_views(
        scene_or_path,
        n,
        out,
        aovs,
        layout=layout,
        seed=seed,
        elevation=elevation,
        hemisphere=hemisphere,
        distance=distance,
        size=size,
        fov=fov,
        transparent=transparent,
        gamma=gamma,
        png_level=png_level,
        resume=resume,
        overwrite=overwrite,
        up=up,
        options=options,
    )
    run_views(plan, client, progress)
    return plan.job.cameras.poses()


def plan_views(
    scene_or_path: Scene | str | os.PathLike,
    n: int,
    out: str | os.PathLike,
    aovs: Iterable[str] | str = (),
    *,
    layout: str = "orbit",
    seed: int = 0,
    elevation: float | None = None,
    hemisphere: bool = True,
    distance: float | None = None,
    size: tuple[int, int] | None = None,
    fov: float | None = None,
    transparent: bool = False,
    gamma: float | str | None = None,
    png_level: int | None = FRAMES_PNG_LEVEL,
    resume: bool = False,
    overwrite: bool = False,
    up: str = "+y",
    options: dict[str, Any] | None = None,
) -> ViewPlan:
    """Check a dataset request and return its :class:`ViewPlan`; see :func:`render_views`.

    Nothing is written: every error is raised here, before any view is rendered.
    """
    if resume and overwrite:
        raise ValueError("resume and overwrite exclude each other: keep the views, or not")
    source, scene, up = _scene(scene_or_path, up)
    chosen = parse_aovs(aovs, VIEW_AOVS)
    options = render_options(options or {})
    size = _size(size, scene, source)
    fov = _fov(fov, scene.camera)
    directions = _poses.view_directions(
        n, layout, seed=seed, elevation=elevation, hemisphere=hemisphere
    )
    cameras = _poses.place_cameras(scene, directions, size, fov=fov, distance=distance)
    gamma = checked_gamma(gamma)
    png_level = None if png_level is None else png_level_of(png_level)
    output = ViewOutput(os.fspath(out), len(cameras), chosen, bool(transparent), gamma, png_level)
    check_tile_size(((0, 0, *size),), options.get("ssaa", 1), "view", "ask for smaller views")
    job = ViewJob(scene, cameras, options, output)
    _check_render(job)
    request = {
        "source": source,
        "views": len(cameras),
        "layout": layout,
        "seed": seed if layout == "random" else None,
        # the orbit's height itself, so that the default and the same number asked for
        # make the same request (a dataset resumed either way)
        "elevation": (_poses.ELEVATION if elevation is None else float(elevation))
        if layout == "orbit" else None,
        "hemisphere": hemisphere if layout != "orbit" else None,
        "distance": float(np.linalg.norm(cameras.eyes[0] - cameras.target)),
        "near": cameras.near,
        "far": cameras.far,
        "size": list(size),
        "fov": fov,
        "aovs": list(chosen),
        "transparent": output.transparent,
        "gamma": output.gamma,
        "options": {key: options[key] for key in sorted(options)},
        # only when turned: the datasets written before up existed resume as they were
        **({"up": up} if up != "+y" else {}),
    }
    folder = Path(output.folder)
    _check_folder(folder, request, resume=resume, overwrite=overwrite)
    todo = tuple(range(len(cameras)))
    if resume:
        todo = tuple(i for i in todo if not output.is_complete(i, *size))
    return ViewPlan(job, todo, request)


def run_views(
    plan: ViewPlan, client: Any = None, progress: Callable[[int], None] | None = None
) -> Path:
    """Render a :class:`ViewPlan`'s views, then write ``transforms.json``; return its path.

    Examples
    --------
    >>> import os, tempfile
    >>> import pixelpath as pp
    >>> from pixelpath.frames.views import plan_views, run_views
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=16, height=16),
    ...                  [pp.Box((-1, -1, -1), (1, 1, 1))])
    >>> plan = plan_views(scene, 2, os.path.join(tempfile.mkdtemp(), "boxes"))
    >>> run_views(plan).name
    'transforms.json'
    """
    from pixelpath.frames import work
    from pixelpath.frames.run import run_tasks

    folder = Path(plan.job.output.folder)
    _prepare(folder, plan)
    if client is None:  # writer threads encode and write a view while the next renders
        with FrameWriter() as writer:
            tasks = [(ViewJob.render, index, 0, ()) for index in plan.todo]

            def add(index: int, part: int, image: Image) -> None:
                plan.job.output.submit(index, image, writer)

            run_tasks(plan.job, plan.job.options, tasks, add, None, progress)
        return _finish(folder, plan)
    tasks = [(work.view_files, index, 0, ()) for index in plan.todo]
    run_tasks(
        plan.job,
        plan.job.options,
        tasks,
        _ignore,
        client,
        progress,
        most_per_batch=MOST_VIEWS_PER_TASK,
        least_per_batch=_least_per_task(client, len(tasks)),
    )
    return _finish(folder, plan)


def _finish(folder: Path, plan: ViewPlan) -> Path:
    """Remove what dead workers left half-written; write ``transforms.json``; return its path."""
    from pixelpath.io.images import write_bytes

    for leftover in _in_view_folders(folder, _HALF_WRITTEN):  # from a worker that died
        leftover.unlink(missing_ok=True)
    path = folder / "transforms.json"
    write_bytes(path, (json.dumps(plan.transforms(), indent=2) + "\n").encode())
    return path


def _ignore(index: int, part: int, result: Any) -> None:
    """Take a view task's result: nothing, the workers wrote the files."""


def _least_per_task(client: Any, views: int) -> int:
    if client is None:
        return 1
    workers = max(1, len(client.scheduler_info()["workers"]))
    return max(1, min(MOST_VIEWS_PER_TASK, views // (SHARES_PER_WORKER * workers)))


def _scene(scene_or_path: Any, up: Any) -> tuple[str | None, Scene, str]:
    """Return (the file's name or None, the scene at frame 0, its up axis as :data:`UP_AXES`)."""
    from pixelpath.io.models import up_axis

    axis = up_axis(up)
    if isinstance(scene_or_path, Scene):
        if axis != "+y":
            raise ValueError(f"up={up!r} turns a model file as it is read: pass the file's "
                             "path, or a Scene whose objects stand on +Y")
        return None, scene_or_path.at_frame(0), axis
    if not isinstance(scene_or_path, str | os.PathLike):
        raise TypeError(
            f"scene_or_path must be a Scene or a path, got {type(scene_or_path).__name__}"
        )
    from pixelpath.scene import load_scene

    path = Path(scene_or_path)
    return path.name, load_scene(path, up=axis).at_frame(0), axis


def _size(size: Any, scene: Scene, source: str | None) -> tuple[int, int]:
    if size is None:
        return DEFAULT_SIZE if source is not None else (scene.camera.width, scene.camera.height)
    try:
        width, height = size
    except (TypeError, ValueError):
        raise TypeError(f"size must be (width, height), got {size!r}") from None
    for name, side in (("width", width), ("height", height)):
        if isinstance(side, bool) or not isinstance(side, numbers.Integral) or side < 1:
            raise ValueError(f"size: the {name} must be a whole number >= 1, got {side!r}")
    return int(width), int(height)


def _fov(fov: Any, camera: Camera) -> float:
    if fov is None:
        return 45.0 if camera.orthographic else float(camera.fov)
    if isinstance(fov, bool) or not isinstance(fov, numbers.Real) or not 0 < fov < 180:
        raise ValueError(f"fov must be degrees strictly between 0 and 180, got {fov!r}")
    return float(fov)


def _check_render(job: ViewJob) -> None:
    """Render one pixel of the first view: every render option is checked by render."""
    from pixelpath.renderer import render

    scene = dataclasses.replace(job.scene, camera=job.cameras.camera(0))
    render(scene, region=(0, 0, 1, 1), **job.options)


def _previous_files(folder: Path) -> list[Path]:
    """Return the files a dataset of views left in ``folder``: views, JSON, request."""
    found = [folder / name for name in ("transforms.json", REQUEST_FILE)]
    return [path for path in found if path.is_file()] + _in_view_folders(folder, _VIEW_FILE)


def _in_view_folders(folder: Path, pattern: re.Pattern) -> list[Path]:
    """Return the files of the views' sub-folders whose names match ``pattern``."""
    found = []
    for sub in FOLDERS.values():
        if (folder / sub).is_dir():
            found.extend(p for p in (folder / sub).iterdir() if pattern.fullmatch(p.name))
    return found


def _check_folder(folder: Path, request: dict, *, resume: bool, overwrite: bool) -> None:
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"out: {folder} exists and is not a folder")
    if not folder.is_dir() or overwrite or not _previous_files(folder):
        return
    if not resume:
        raise ValueError(
            f"{folder} already holds a dataset of views; pass resume=True (--resume) to "
            f"complete it or overwrite=True (--overwrite) to replace it"
        )
    stored = folder / REQUEST_FILE
    try:
        previous = json.loads(stored.read_text())
    except (OSError, ValueError):
        previous = None
    if previous != json.loads(json.dumps(request)):
        raise ValueError(
            f"{folder} holds views made with other settings (or by something else), which "
            f"resume cannot complete; pass overwrite=True (--overwrite) to replace them"
        )


def _prepare(folder: Path, plan: ViewPlan) -> None:
    """Clear a previous dataset unless resuming; record the request."""
    from pixelpath.io.images import write_bytes

    folder.mkdir(parents=True, exist_ok=True)
    if len(plan.todo) == len(plan.job.cameras):  # nothing kept: nothing of an older dataset stays
        for path in _previous_files(folder):
            path.unlink()
    write_bytes(folder / REQUEST_FILE, json.dumps(plan.request).encode())
