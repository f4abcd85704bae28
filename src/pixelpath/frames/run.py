"""``render_frames``: many frames (and tiles of frames), in this process or on a Dask cluster.

Each piece of work is one of the pure functions of :mod:`pixelpath.frames.work` applied to the
scene, a frame number and the render options. In this process they run one after another (each
frame uses Numba's threads on every core). With a ``dask.distributed`` client the scene is
scattered to every worker once, before any task, and tasks name it by its key; consecutive
pieces go to the cluster in batches, one task each (:func:`_batch_sizes`), and a task lost
with a worker that died is run again on another, its whole batch (Dask retries it up to its
``allowed-failures``). Frames' files are written here, atomically, as batches complete: tasks
return the encoded bytes, or tiles that are stitched here, so workers need no shared disk
(:func:`run_tasks` also serves datasets of views, whose workers write their own files).

Files are encoded and written on a few threads (:class:`~pixelpath.frames.writer.FrameWriter`):
in this process the next frame renders while the last is encoded, and every file is written
when :func:`render_frames` returns.
"""

from __future__ import annotations

import os
import uuid
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from pixelpath.frames import work
from pixelpath.frames.plan import FRAMES_PNG_LEVEL, FramePlan, plan_frames
from pixelpath.frames.writer import FrameWriter
from pixelpath.image import Image
from pixelpath.scene import Scene

Progress = Callable[[int], None]

# A task's share of what is left: a few tasks a worker keep every worker busy to the end.
BATCHES_PER_WORKER = 4
# Batches stay short enough that progress and retries after a lost worker stay fine-grained.
MOST_TASKS_PER_BATCH = 8


def render_frames(
    scene: Scene,
    frames: Iterable[int] | None,
    client: Any = None,
    out: str | os.PathLike | None = None,
    *,
    tiles: tuple[int, int] = (1, 1),
    resume: bool = False,
    gamma: float | None = None,
    png_level: int | None = FRAMES_PNG_LEVEL,
    progress: Progress | None = None,
    **options: Any,
) -> list[Image] | list[Path]:
    """Render many frames of an animated scene, here or on a Dask cluster.

    Parameters
    ----------
    scene : Scene
        The scene; frame ``n`` is ``scene.at_frame(n)`` (every frame is the same scene when it
        has no animation).
    frames : iterable of int, or None
        Frame numbers, each once (``range(120)``); None for every frame of the animation.
    client : dask.distributed.Client, optional
        Run on this client's cluster; default: in this process, one frame after another.
    out : str or path-like, optional
        Write each frame to ``out.format(frame=n)`` (``"out/frame_{frame:04d}.png"``),
        atomically, creating folders as needed; default: return the images.
    tiles : (columns, rows)
        Split each frame into tiles rendered as separate tasks and stitched; the result is
        identical to the untiled frame.
    resume : bool
        Skip frames whose file already holds a whole image of the right size (each is read
        back to make sure); needs ``out``.
    gamma : float, optional
        Display gamma the files are encoded with, as ``Image.save``.
    png_level : int or None
        zlib compression level of PNG files, 0 (none) to 9 (smallest): by default 1, fast,
        whose files are half as large again as ``Image.save``'s but take a third of the time
        to encode (at 640×400, 7.7 ms a frame instead of 21). None: level 6, the bytes
        ``Image.save`` writes.
    progress : callable, optional
        Called with a count of frames (or tiles) each time some complete: one at a time
        here, a batch at a time on a cluster.
    **options
        Keywords of :func:`pixelpath.render`: ``method``, ``shading``, ``backface_cull``,
        ``ssaa``, ``blinn``, ``style``, ``max_depth``, ``samples``.

    Returns
    -------
    list of Path or list of Image
        In the order of ``frames``: the files (skipped ones included) when ``out`` is given,
        else the images.

    Raises
    ------
    ValueError, TypeError
        For a frame outside the animation, an ``out`` without ``{frame}`` for several frames,
        tiles smaller than a pixel or bad render options, before any work starts.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.scene import Animation, Turntable
    >>> scene = pp.Scene(
    ...     pp.Camera(eye=(0, 1, 5), target=(0, 0, 0), width=32, height=24),
    ...     [pp.Box((-1, -1, -1), (1, 1, 1))],
    ...     [pp.PointLight((3, 4, 5))],
    ...     animation=Animation(8, turntable=Turntable()),
    ... )
    >>> images = pp.render_frames(scene, range(0, 8, 2), shading="flat")
    >>> [image.shape for image in images] == [(24, 32, 3)] * 4
    True
    >>> paths = pp.render_frames(scene, [0, 4], out="spin/f_{frame:02d}.png")
    >>> [path.as_posix() for path in paths]
    ['spin/f_00.png', 'spin/f_04.png']
    """
    plan = plan_frames(
        scene,
        frames,
        out,
        tiles=tiles,
        resume=resume,
        gamma=gamma,
        png_level=png_level,
        options=options,
    )
    return run_plan(plan, client, progress)


def run_plan(plan: FramePlan, client: Any = None, progress: Progress | None = None) -> list:
    """Carry out a :class:`~pixelpath.frames.plan.FramePlan`; see :func:`render_frames`."""
    with FrameWriter() as writer:
        frames = _Frames(plan, writer)
        tasks = _tasks(plan, here=client is None)
        run_tasks(plan.scene, plan.options, tasks, frames.add, client, progress)
    if plan.paths is None:
        return [frames.images[frame] for frame in plan.frames]
    return [plan.paths[frame] for frame in plan.frames]


def run_tasks(
    shared: Any,
    options: dict[str, Any],
    tasks: list[tuple[Callable, int, int, tuple]],
    add: Callable[[int, int, Any], None],
    client: Any = None,
    progress: Progress | None = None,
    *,
    most_per_batch: int = MOST_TASKS_PER_BATCH,
    least_per_batch: int = 1,
) -> None:
    """Run ``tasks`` here or on ``client``'s cluster, handing each result to ``add``.

    A task is ``(function, frame, part, args)``: its result is ``function(shared, frame,
    *args)``, given to ``add(frame, part, result)`` in this process; ``shared`` (a scene, or
    anything the functions take) goes to each worker once. On a cluster the tasks go
    in batches of ``least_per_batch`` to ``most_per_batch`` (:func:`_batch_sizes`);
    ``options`` (render keywords) warm the workers.
    """
    advance = progress or (lambda steps: None)
    if client is None:
        for function, frame, part, args in tasks:
            add(frame, part, function(shared, frame, *args))
            advance(1)
        return
    _run_on(client, shared, options, tasks, add, advance, (most_per_batch, least_per_batch))


def _tasks(plan: FramePlan, here: bool = False) -> list[tuple[Callable, int, int, tuple]]:
    """Return (function, frame, tile index, further arguments) for every task, frame by frame.

    On a cluster (not ``here``) the workers encode whole frames' files; here the writer
    threads encode them while the next frame renders.
    """
    tasks = []
    for frame in plan.todo:
        if len(plan.regions) == 1 and plan.paths is not None and not here:
            args = (plan.options, plan.paths[frame].suffix, plan.gamma, plan.png_level)
            tasks.append((work.frame_file, frame, 0, args))
            continue
        tiled = len(plan.regions) > 1
        for tile, region in enumerate(plan.regions):
            args = (plan.options, region if tiled else None)
            tasks.append((work.render_frame, frame, tile, args))
    return tasks


class _Frames:
    """Gathers task results; finishes (stitches, writes) each frame when its last tile is in."""

    def __init__(self, plan: FramePlan, writer: FrameWriter) -> None:
        self.plan = plan
        self.writer = writer
        self.images: dict[int, Image] = {}
        self.pending: dict[int, dict[int, Any]] = {}
        if plan.paths is not None:
            for path in {plan.paths[frame].parent for frame in plan.todo}:
                path.mkdir(parents=True, exist_ok=True)

    def add(self, frame: int, tile: int, result: Any) -> None:
        parts = self.pending.setdefault(frame, {})
        parts[tile] = result
        if len(parts) < len(self.plan.regions):
            return
        del self.pending[frame]
        path = None if self.plan.paths is None else self.plan.paths[frame]
        if isinstance(result, bytes):
            self.writer.submit(path, lambda: result)
            return
        image = result
        if len(self.plan.regions) > 1:
            image = work.stitch([parts[i] for i in range(len(parts))], self.plan.regions)
        if path is None:
            self.images[frame] = image
            return
        encoder = work.picture_encoder(image, path.suffix, self.plan.gamma, self.plan.png_level)
        self.writer.submit(path, encoder)


def _run_on(
    client: Any,
    shared: Any,
    options: dict[str, Any],
    tasks: list,
    add: Callable[[int, int, Any], None],
    advance: Progress,
    limits: tuple[int, int],
) -> None:
    """Run ``tasks`` on a Dask cluster; ``shared`` goes to each worker once, before them.

    Tasks go to the cluster in batches (:func:`_batch_sizes`), each run in turn on one worker:
    the scheduler's cost is per batch, not per frame.
    """
    from distributed import as_completed

    from pixelpath.frames.cluster import warm_workers

    warm_workers(client, options)
    run = uuid.uuid4().hex[:8]
    workers = max(1, len(client.scheduler_info()["workers"]))
    scattered = client.scatter(shared, broadcast=True, hash=False)
    futures = {}
    try:
        for function, group in _by_function(tasks):
            batches = _batches(group, workers, *limits)
            first = [batch[0] for batch in batches]
            keys = [f"pixelpath-{run}-frame-{frame}-tile-{tile}" for _, frame, tile, _ in first]
            calls = [[(frame, *args) for _, frame, _, args in batch] for batch in batches]
            submitted = client.map(
                work.in_turn,
                [function] * len(batches),
                [scattered] * len(batches),
                calls,
                key=keys,
                pure=False,
            )
            futures.update(zip(submitted, batches, strict=True))
        # Results come with their futures, fetched by the client's event loop: asking each
        # future for its result from this thread costs a round trip to that loop per task.
        for future, results in as_completed(futures, with_results=True, raise_errors=False):
            batch = futures[future]
            places = [(frame, tile) for _, frame, tile, _ in batch]
            for (frame, tile), result in zip(places, _result(future, results, places), strict=True):
                add(frame, tile, result)
            future.release()
            advance(len(batch))
    finally:
        client.cancel([*futures, scattered])


def _by_function(tasks: list) -> list[tuple[Callable, list]]:
    """Group ``tasks`` by their function, keeping their order (one ``client.map`` a group)."""
    groups: dict[Callable, list] = {}
    for task in tasks:
        groups.setdefault(task[0], []).append(task)
    return list(groups.items())


def _batches(tasks: list, workers: int, most: int, least: int = 1) -> list[list]:
    """Split ``tasks`` into consecutive batches of :func:`_batch_sizes`."""
    batches, start = [], 0
    for size in _batch_sizes(len(tasks), workers, most, least):
        batches.append(tasks[start : start + size])
        start += size
    return batches


def _batch_sizes(
    count: int, workers: int, most: int = MOST_TASKS_PER_BATCH, least: int = 1
) -> list[int]:
    """Return batch sizes for ``count`` tasks on ``workers``: large first, small ones last.

    Each batch takes a ``1 / (BATCHES_PER_WORKER * workers)`` share of the tasks left, from
    ``least`` to ``most`` (the last takes what is left), so the scheduler handles few tasks
    while the last, short ones even out when the workers finish (guided self-scheduling).

    Examples
    --------
    >>> _batch_sizes(40, 2)
    [5, 4, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1]
    >>> sum(_batch_sizes(120, 2)), max(_batch_sizes(120, 2)), _batch_sizes(3, 1)
    (120, 8, [1, 1, 1])
    >>> len(_batch_sizes(2000, 2, most=64)), len(_batch_sizes(2000, 2, most=64, least=50))
    (66, 34)
    """
    sizes = []
    while count:
        size = min(most, count, max(least, count // (BATCHES_PER_WORKER * workers)))
        sizes.append(size)
        count -= size
    return sizes


def _result(future: Any, results: Any, places: list[tuple[int, int]]) -> Any:
    """Return a finished batch's ``results``; else raise its error (lost frames named)."""
    from distributed import KilledWorker

    if future.status == "finished":
        return results
    try:
        return future.result()  # raises the task's exception, with its traceback
    except KilledWorker as exc:
        numbers = sorted({frame for frame, _ in places})
        named = f"frame {numbers[0]} was" if len(numbers) == 1 else f"frames {numbers} were"
        raise RuntimeError(
            f"{named} lost with a worker too many times ({exc}); see Dask's "
            f"distributed.scheduler.allowed-failures"
        ) from None
