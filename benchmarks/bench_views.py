"""Datasets of views: views/s of the Duck dataset beside pyrender, and Dask's cost per view.

1. ``pixelpath views``' work, 100 views of the glTF Duck (tests/data/models/Duck.glb) at
   800×800 with depth, normals and masks (PNG pictures, float32 ``.npy`` depths, PNG normals
   and masks, ``transforms.json``), each run in a fresh folder, in ``--rounds`` rounds whose
   order rotates (the machine's speed drifts):

   - serially in this process, Numba's threads on every core, and on one thread;
   - on local Dask clusters of 1 and of 2 worker processes (one Numba thread each; started and
     warmed before the clock), whose workers write the files.

2. The anchor: pyrender (OpenGL through EGL, Mesa's llvmpipe on a machine without a GPU)
   rendering the same 100 poses, read from the dataset's ``transforms.json``, with colour and
   depth read back and the same files written (PNG picture, ``.npy`` depth, PNG mask; pyrender
   has no normal output), in a child process per thread setting (``LP_NUM_THREADS``: one, and
   every core), beside pixelpath writing the same three files: in this process on one thread,
   and on every core as ``pixelpath views`` runs that many views (a local cluster, a worker a
   core). Skipped, with a message, when
   pyrender or EGL is missing (``pip install pyrender``; EGL comes with Mesa: ``libegl1``).

3. Blender, where a Python with ``bpy`` is at hand (``--blender-python``; ``pip install bpy``
   wants the Python version of its Blender release, 3.11 for 4.2): the first
   ``--blender-views`` poses rendered one after another in a child process, pictures only
   (PNG), with Cycles at its cheapest (one sample a pixel on the CPU, no denoising) and with
   the Workbench engine, beside pixelpath writing the whole dataset in one process.
   EEVEE is left out: without a GPU it took a minute a picture here.

4. Scaling past one machine: the CPU time the client and the scheduler spend per view (the
   process running both, a local cluster's scheduler being in the client's process), for
   2,000 tiny views (16×16, nothing else written) on 2 workers, beside the same number of tiny
   frames through ``render_frames`` (at most 8 frames a task, each file written here).

Usage::

    python benchmarks/bench_views.py [--views 100] [--size 800] [--rounds 3] [--tiny 2000]
        [--blender-python /path/to/python-with-bpy] [--blender-views 20]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

DUCK = Path(__file__).resolve().parents[1] / "tests" / "data" / "models" / "Duck.glb"
AOVS = ("depth", "normal", "mask")


def serial(folder: Path, views: int, size: int, aovs=AOVS, threads: int | None = None) -> float:
    import numba

    import pixelpath as pp

    before = numba.get_num_threads()
    if threads is not None:
        numba.set_num_threads(threads)
    try:
        pp.render_views(DUCK, 1, folder / "warm", aovs, size=(size, size))  # kernels loaded
        start = time.perf_counter()
        pp.render_views(DUCK, views, folder / "views", aovs, size=(size, size))
        return time.perf_counter() - start
    finally:
        numba.set_num_threads(before)


def on_cluster(folder: Path, views: int, size: int, workers: int, aovs=AOVS) -> float:
    import pixelpath as pp
    from pixelpath.frames.cluster import local_client, warm_workers

    with local_client(workers, numba_threads=1) as client:
        warm_workers(client, {})
        pp.render_views(DUCK, 1, folder / "warm", aovs, client=client, size=(size, size))
        start = time.perf_counter()
        pp.render_views(DUCK, views, folder / "views", aovs, client=client, size=(size, size))
        return time.perf_counter() - start


def dataset_bytes(folder: Path) -> dict[str, bytes]:
    return {
        path.relative_to(folder).as_posix(): path.read_bytes()
        for path in sorted(folder.rglob("*"))
        if path.is_file()
    }


def timed(views: int, size: int, rounds: int) -> tuple[dict, bool]:
    """Return ({run: [seconds per round]}, whether the 2-worker files equal the serial ones)."""
    names = ("serial", 1, 2)
    seconds: dict = {name: [] for name in names}
    same = True
    for turn in range(rounds):
        order = names[turn % 3 :] + names[: turn % 3]
        with tempfile.TemporaryDirectory() as root:
            for name in order:
                folder = Path(root) / str(name)
                if name == "serial":
                    seconds[name].append(serial(folder, views, size))
                else:
                    seconds[name].append(on_cluster(folder, views, size, name))
            same &= dataset_bytes(Path(root) / "serial" / "views") == dataset_bytes(
                Path(root) / "2" / "views"
            )
        line = "  ".join(f"{name}: {views / seconds[name][-1]:5.1f}" for name in order)
        print(f"round {turn + 1}, views/s in the order run: {line}")
    return seconds, same


# --- pyrender, in a child process: llvmpipe reads LP_NUM_THREADS when it starts ----------------


def pyrender_views(dataset: Path, out: Path) -> float:
    """Render the dataset's poses with pyrender and write picture, depth and mask; seconds."""
    import numpy as np
    import pyrender
    import trimesh
    from PIL import Image as PILImage

    document = json.loads((dataset / "transforms.json").read_text())
    width, height = document["w"], document["h"]
    scene = pyrender.Scene.from_trimesh_scene(trimesh.load(DUCK), ambient_light=(0.2,) * 3)
    for direction, intensity in (((-0.6, 0.7, 0.8), 2.3), ((0.8, -0.1, 0.6), 0.9)):
        pose = np.eye(4)
        back = np.array(direction) / np.linalg.norm(direction)
        right = np.cross((0, 1, 0), back)
        right /= np.linalg.norm(right)
        pose[:3, :3] = np.stack([right, np.cross(back, right), back], axis=1)
        scene.add(pyrender.DirectionalLight(intensity=intensity), pose=pose)
    request = document["pixelpath"]
    camera = pyrender.PerspectiveCamera(
        yfov=document["camera_angle_y"], aspectRatio=width / height, znear=request["near"],
        zfar=request["far"],
    )
    node = scene.add(camera, pose=np.eye(4))
    renderer = pyrender.OffscreenRenderer(width, height)
    renderer.render(scene)  # the context and shaders, before the clock
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    for index, frame in enumerate(document["frames"]):
        scene.set_pose(node, np.array(frame["transform_matrix"]))
        color, depth = renderer.render(scene)
        PILImage.fromarray(color).save(out / f"image_{index:04d}.png")
        np.save(out / f"depth_{index:04d}.npy", depth.astype(np.float32))
        PILImage.fromarray(np.where(depth > 0, 255, 0).astype(np.uint8)).save(
            out / f"mask_{index:04d}.png"
        )
    seconds = time.perf_counter() - start
    renderer.delete()
    return seconds


def pyrender_in_child(dataset: Path, threads: int | None) -> float | str:
    """Seconds pyrender took in a child process with ``threads`` llvmpipe threads, or why not."""
    env = dict(os.environ, PYOPENGL_PLATFORM="egl")
    if threads is not None:
        env["LP_NUM_THREADS"] = str(threads)
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run(
            [sys.executable, __file__, "--pyrender-child", str(dataset), out],
            env=env, capture_output=True, text=True, check=False,
        )
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return f"pyrender did not run: {last}"
    return float(done.stdout.strip().splitlines()[-1])


def like_for_like(views: int, size: int) -> None:
    """pixelpath and pyrender writing the same files for the same poses, per core and all."""
    import importlib.util

    import numba

    if importlib.util.find_spec("pyrender") is None:
        print("pyrender: skipped, not installed (pip install pyrender; needs EGL: libegl1)")
        return
    cores = numba.get_num_threads()
    aovs = ("depth", "mask")
    with tempfile.TemporaryDirectory() as root:
        ours = {  # on all cores, as `pixelpath views` runs 100 views: a worker per core
            1: serial(Path(root) / "one", views, size, aovs, threads=1),
            cores: on_cluster(Path(root) / "all", views, size, cores, aovs),
        }
        dataset = Path(root) / "all" / "views"
        theirs = {1: pyrender_in_child(dataset, 1), cores: pyrender_in_child(dataset, None)}
    print(f"{views} views {size}x{size}, picture + depth + mask files, the same poses:")
    for threads in (1, cores):
        label = "1 thread each" if threads == 1 else f"all {cores} cores each"
        anchor = theirs[threads]
        if isinstance(anchor, str):
            print(f"  {label}: pixelpath {views / ours[threads]:5.1f} views/s; {anchor}")
            continue
        print(
            f"  {label}: pixelpath {views / ours[threads]:5.1f} views/s, pyrender (llvmpipe) "
            f"{views / anchor:5.1f} views/s: pixelpath takes {ours[threads] / anchor:.2f}x "
            f"pyrender's time"
        )


# --- Blender (bpy), in a child process of an interpreter that has it -------------------------

BLENDER_ENGINES = ("CYCLES", "BLENDER_WORKBENCH")


def blender_views(dataset: Path, out: Path, engine: str, views: int) -> float:
    """Render the first ``views`` poses with Blender's ``engine``, pictures only; seconds."""
    import bpy
    import mathutils

    document = json.loads((dataset / "transforms.json").read_text())
    request = document["pixelpath"]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=str(DUCK))
    scene = bpy.context.scene
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.data.sensor_fit = "VERTICAL"
    camera.data.angle_y = document["camera_angle_y"]
    camera.data.clip_start, camera.data.clip_end = request["near"], request["far"]
    scene.collection.objects.link(camera)
    scene.camera = camera
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    scene.collection.objects.link(sun)
    scene.render.resolution_x, scene.render.resolution_y = document["w"], document["h"]
    scene.render.engine = engine
    if engine == "CYCLES":  # its cheapest picture: one sample a pixel, no denoising
        scene.cycles.device, scene.cycles.samples, scene.cycles.use_denoising = "CPU", 1, False
    # glTF's +Y up is Blender's +Z up: (x, y, z) -> (x, -z, y); camera axes are the same
    y_up_to_z_up = mathutils.Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    out.mkdir(parents=True, exist_ok=True)
    frames = document["frames"][:views]
    camera.matrix_world = y_up_to_z_up @ mathutils.Matrix(frames[0]["transform_matrix"])
    scene.render.filepath = str(out / "warm.png")
    bpy.ops.render.render(write_still=True)  # shaders and the scene's BVH, before the clock
    start = time.perf_counter()
    for index, frame in enumerate(frames):
        camera.matrix_world = y_up_to_z_up @ mathutils.Matrix(frame["transform_matrix"])
        scene.render.filepath = str(out / f"view_{index:04d}.png")
        bpy.ops.render.render(write_still=True)
    return time.perf_counter() - start


def blender_in_child(python: str, dataset: Path, engine: str, views: int) -> float | str:
    """Seconds Blender took in a child process of ``python``, or why it did not run."""
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run(
            [python, __file__, "--blender-child", str(dataset), out, engine, str(views)],
            capture_output=True, text=True, check=False,
        )
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return f"Blender did not run: {last}"
    return float(done.stdout.strip().splitlines()[-1])


def against_blender(python: str | None, views: int, size: int) -> None:
    """pixelpath's whole dataset beside Blender's pictures alone, one view after another."""
    import importlib.util

    if python is None:
        if importlib.util.find_spec("bpy") is None:
            print("Blender: skipped, no bpy here (pip install bpy in a Python it supports, "
                  "then --blender-python PATH)")
            return
        python = sys.executable
    with tempfile.TemporaryDirectory() as root:
        seconds = serial(Path(root), views, size) / views
        dataset = Path(root) / "views"
        print(f"{views} views {size}x{size}, one process each: pixelpath {seconds * 1e3:.0f} ms "
              f"a view (picture, depth, normals, mask)")
        for engine in BLENDER_ENGINES:
            theirs = blender_in_child(python, dataset, engine, views)
            if isinstance(theirs, str):
                print(f"  {engine}: {theirs}")
                continue
            print(f"  Blender {engine} (the picture alone): {theirs / views * 1e3:.0f} ms a view: "
                  f"pixelpath takes {seconds * views / theirs:.2f}x Blender's time")


# --- the client's and scheduler's CPU per view ---------------------------------------------


def scheduler_cost(tiny: int) -> tuple[float, float]:
    """Return (ms of client+scheduler CPU per view, per frame) for ``tiny`` 16×16 renders."""
    import pixelpath as pp
    from pixelpath.frames.cluster import local_client, warm_workers
    from pixelpath.scene import Animation, Turntable

    scene = pp.Scene(
        pp.Camera(eye=(0, 1, 5), target=(0, 0, 0), width=16, height=16),
        [pp.Box((-1, -1, -1), (1, 1, 1))],
        [pp.PointLight((2, 3, 4))],
    )
    with local_client(2, numba_threads=1) as client, tempfile.TemporaryDirectory() as root:
        warm_workers(client, {})
        pp.render_views(scene, 4, Path(root) / "warm", client=client)
        cpu = time.process_time()
        pp.render_views(scene, tiny, Path(root) / "views", client=client)
        per_view = (time.process_time() - cpu) / tiny * 1e3
        animated = pp.Scene(scene.camera, scene.objects, scene.lights,
                            animation=Animation(tiny, turntable=Turntable()))
        cpu = time.process_time()
        pp.render_frames(animated, range(tiny), client, out=Path(root) / "f_{frame:05d}.png")
        per_frame = (time.process_time() - cpu) / tiny * 1e3
    return per_view, per_frame


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--views", type=int, default=100)
    parser.add_argument("--size", type=int, default=800)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--tiny", type=int, default=2000)
    parser.add_argument("--blender-views", type=int, default=20)
    parser.add_argument("--blender-python", help="a Python interpreter that has bpy")
    parser.add_argument("--pyrender-child", nargs=2, metavar=("DATASET", "OUT"),
                        help=argparse.SUPPRESS)
    parser.add_argument("--blender-child", nargs=4, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.pyrender_child:
        print(pyrender_views(Path(args.pyrender_child[0]), Path(args.pyrender_child[1])))
        return
    if args.blender_child:
        dataset, out, engine, views = args.blender_child
        print(blender_views(Path(dataset), Path(out), engine, int(views)))
        return
    cores = len(os.sched_getaffinity(0))
    print(f"the Duck, {args.views} views {args.size}x{args.size} with depth, normals and masks, "
          f"{cores} cores")
    seconds, same = timed(args.views, args.size, args.rounds)
    medians = {name: statistics.median(times) for name, times in seconds.items()}
    labels = {"serial": "serial, Numba threads on all cores", 1: "Dask, 1 worker, 1 thread",
              2: "Dask, 2 workers, 1 thread each"}
    for name, label in labels.items():
        print(f"  {label:38} {args.views / medians[name]:6.1f} views/s "
              f"({medians[name]:5.1f} s for {args.views})")
    ratios = sorted(one / two for one, two in zip(seconds[1], seconds[2], strict=True))
    print(f"  2 workers / 1 worker: {statistics.median(ratios):.2f}x median "
          f"({', '.join(f'{r:.2f}' for r in ratios)}); 2-worker files byte-identical to the "
          f"serial ones: {same}")
    like_for_like(args.views, args.size)
    against_blender(args.blender_python, args.blender_views, args.size)
    per_view, per_frame = scheduler_cost(args.tiny)
    print(f"client + scheduler CPU, {args.tiny} tiny renders on 2 workers: {per_view:.3f} ms a "
          f"view (views, workers writing), {per_frame:.3f} ms a frame (render_frames)")


if __name__ == "__main__":  # worker processes re-import this file: keep the work behind main
    main()
