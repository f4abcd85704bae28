"""Ray-tracing speed: pixelpath's BVH and tracer beside Embree and Mitsuba 3, in the same run.

* Primary rays: one ray through each pixel centre of a 1024×1024 view of the Stanford bunny
  (69,451 triangles, from ../shared/data/meshes; an icosphere of 81,920 triangles when absent),
  nearest hits by ``pixelpath.raytrace.intersect`` beside Embree (the ``embreex`` package,
  directly and through trimesh's ``RayMeshIntersector``), in Mrays/s: pixelpath on one thread
  (Embree's single ``run`` call traces on one) and on all of Numba's, and the fraction of rays
  on which pixelpath and Embree report the same triangle (or both a miss). The tree is built
  before timing.
* BVH builds, of the bunny and of a million triangles (a 708×708 height field, 999,698
  triangles): ``BVH.build`` (one thread) beside Embree's construction of a scene of the same
  triangles (the scene, its ``TriangleMesh`` and the first ``run`` of one ray, where Embree
  builds its tree on all cores), taking turns.
* The shadowed bunny: ``render(method="raytrace")`` at 1024² with one point light, a diffuse
  material and one sample per pixel (primary and shadow rays, shading, the image), beside
  Mitsuba 3's ``scalar_rgb`` and ``llvm_ad_rgb`` variants with the ``direct`` integrator (one
  emitter sample, one sample per pixel; the LLVM variant needs LLVM 16 or newer, see
  ``mitsuba_renders``); Mitsuba's scene loading and kernel set-up are outside its timing.
* The bundled showcase (a chrome and a glass sphere among analytic and mesh objects) at
  1024×768 with ``max_depth=5``, beside Mitsuba 3 rendering the same shapes and lights with its
  nearest materials (a dielectric, a mirror blended with a diffuse surface, diffuse ones), one
  sample per pixel, with its path tracer to the same depth and with its direct integrator:
  the first traces more rays than a Whitted tracer (it bounces off diffuse surfaces too), the
  second fewer (no bounce), so the two bracket the work; no goal, a ratio to watch.

Each figure is the best of ``--repeat`` runs after a warm-up run (compilation excluded). The
shadowed bunny's two renderers take turns (pixelpath, Mitsuba, pixelpath, ...), so that both
meet the same moods of a shared machine; it also shows each one's median and least CPU time
of the process (all threads), which moves less than wall time with the load. The anchors are
optional (``pip install embreex mitsuba``, in the ``bench`` extra) and are skipped with a
message when absent. Ratios are only meaningful between figures of the same run.

Usage::

    python benchmarks/bench_ray.py [--repeat 3] [--size 1024]
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import statistics
import tempfile
import time
from pathlib import Path

import numba
import numpy as np

import pixelpath as pp
from pixelpath.raytrace import BVH, intersect

MESHES = Path(__file__).resolve().parents[2] / "shared" / "data" / "meshes"


def load_bunny() -> tuple[str, pp.Mesh, Path | None]:
    """A label, the bunny (or a stand-in of similar size) and its file when there is one."""
    path = MESHES / "stanford-bunny.obj"
    if path.is_file():
        return "Stanford bunny", pp.Mesh.load(path), path
    print(f"({path} not found: using an icosphere as a stand-in)")
    return "icosphere (bunny stand-in)", pp.scene.icosphere(subdivisions=6), None


def framed_camera(mesh: pp.Mesh, width: int, height: int) -> pp.Camera:
    """The mesh seen from the front and a little above, filling most of the frame."""
    low, high = mesh.bounds()
    center = (low + high) / 2
    radius = float(np.linalg.norm(high - low)) / 2
    return pp.Camera(
        eye=center + radius * np.array([0.0, 0.3, 2.6]),
        target=center,
        fov=45.0,
        width=width,
        height=height,
        near=0.05 * radius,
        far=10.0 * radius,
    )


def primary_rays(camera: pp.Camera) -> tuple[np.ndarray, np.ndarray]:
    """Origins and unit directions of the rays through every pixel centre, row by row."""
    u, v, w = camera.basis()
    tan_y = np.tan(np.radians(camera.fov) / 2)
    xs = (2 * (np.arange(camera.width) + 0.5) / camera.width - 1) * tan_y * camera.aspect
    ys = (1 - 2 * (np.arange(camera.height) + 0.5) / camera.height) * tan_y
    gx, gy = np.meshgrid(xs, ys)
    directions = gx[..., None] * u + gy[..., None] * v - w
    directions = directions.reshape(-1, 3)
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    origins = np.broadcast_to(np.asarray(camera.eye, dtype=float), directions.shape).copy()
    return origins, directions


def best_of(repeat: int, call) -> tuple[float, object]:
    """Seconds of the fastest of ``repeat`` calls after a warm-up call, and its result."""
    (timing,) = interleaved(repeat, [call])
    return timing.best, timing.result


@dataclasses.dataclass
class Timing:
    best: float  # seconds, the fastest call
    best_cpu: float  # the least CPU time of the process (all threads) of a call
    median: float  # seconds
    result: object


def interleaved(repeat: int, calls) -> list[Timing]:
    """Time each call ``repeat`` times after a warm-up call each, taking turns.

    Taking turns (a, b, a, b, ...) lets every program meet the same moods of a shared machine,
    whose speed drifts by 10-25 % within a minute, so their ratio means something. CPU time
    counts only the work done, not the time other jobs took the cores.
    """
    results = [call() for call in calls]
    times: list[list[float]] = [[] for _ in calls]
    cpu = [float("inf")] * len(calls)
    for _ in range(repeat):
        for k, call in enumerate(calls):
            start, start_cpu = time.perf_counter(), time.process_time()
            results[k] = call()
            times[k].append(time.perf_counter() - start)
            cpu[k] = min(cpu[k], time.process_time() - start_cpu)
    return [
        Timing(min(t), c, statistics.median(t), result)
        for t, c, result in zip(times, cpu, results, strict=True)
    ]


def bench_primary(mesh: pp.Mesh, size: int, repeat: int) -> None:
    camera = framed_camera(mesh, size, size)
    origins, directions = primary_rays(camera)
    count = len(origins)
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    one_thread, (_, face) = best_of(repeat, lambda: intersect(mesh, origins, directions))
    numba.set_num_threads(threads)
    seconds, (_, all_face) = best_of(repeat, lambda: intersect(mesh, origins, directions))
    assert np.array_equal(face, all_face)
    hits = int(np.count_nonzero(face >= 0))
    print(
        f"  pixelpath, 1 thread     {count / one_thread / 1e6:8.2f} Mrays/s  "
        f"({1000 * one_thread:.0f} ms, {hits:,} hits)"
    )
    print(
        f"  pixelpath, {threads} threads    {count / seconds / 1e6:8.2f} Mrays/s  "
        f"({1000 * seconds:.0f} ms: {one_thread / seconds:.2f}x one thread's rate)"
    )
    if importlib.util.find_spec("embreex") is None:
        print("  Embree skipped: embreex is not installed (pip install embreex)")
        return
    from embreex import rtcore_scene
    from embreex.mesh_construction import TriangleMesh

    def embree_scene():
        scene = rtcore_scene.EmbreeScene()
        TriangleMesh(scene, mesh.vertices[mesh.triangles].astype(np.float32))
        return scene

    scene = embree_scene()
    o32, d32 = origins.astype(np.float32), directions.astype(np.float32)
    e_seconds, result = best_of(repeat, lambda: scene.run(o32, d32, output=1))
    prim = np.asarray(result["primID"])
    embree_face = np.where(prim >= 0, mesh.triangle_face[np.maximum(prim, 0)], -1)
    same = float(np.mean(embree_face == face))
    print(
        f"  Embree (embreex)        {count / e_seconds / 1e6:8.2f} Mrays/s  "
        f"({1000 * e_seconds:.0f} ms); same face on {same:.2%} of the rays"
    )
    print(
        f"  per core, pixelpath's time / Embree's: {one_thread / e_seconds:.2f} (Embree traces "
        f"on one thread; all pixelpath's threads: {seconds / e_seconds:.2f})"
    )
    if importlib.util.find_spec("trimesh") is None:
        print("  trimesh skipped: trimesh is not installed")
        return
    import trimesh
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    tm = trimesh.Trimesh(mesh.vertices, mesh.triangles, process=False)
    intersector = RayMeshIntersector(tm)
    t_seconds, _ = best_of(repeat, lambda: intersector.intersects_first(origins, directions))
    print(
        f"  trimesh (Embree)        {count / t_seconds / 1e6:8.2f} Mrays/s  "
        f"({1000 * t_seconds:.0f} ms); pixelpath's time ({threads} threads) / trimesh's "
        f"{seconds / t_seconds:.2f}"
    )


def height_field(side: int = 708) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of a rippled side × side grid: 2 (side - 1)² triangles."""
    xs = np.linspace(-1.0, 1.0, side)
    gx, gy = np.meshgrid(xs, xs)
    gz = 0.1 * np.sin(5 * gx) * np.cos(4 * gy)
    vertices = np.stack([gx.ravel(), gy.ravel(), gz.ravel()], axis=1)
    rows, cols = np.meshgrid(np.arange(side - 1), np.arange(side - 1), indexing="ij")
    v = (rows * side + cols).ravel()
    triangles = np.concatenate(
        [np.stack([v, v + 1, v + side + 1], axis=1), np.stack([v, v + side + 1, v + side], axis=1)]
    )
    return vertices, triangles


def bench_build(vertices: np.ndarray, triangles: np.ndarray, repeat: int) -> None:
    """Print ``BVH.build``'s time beside Embree's construction of the same triangles."""
    calls = [lambda: BVH.build(vertices, triangles)]
    embree = importlib.util.find_spec("embreex") is not None
    if embree:
        from embreex import rtcore_scene
        from embreex.mesh_construction import TriangleMesh

        vertices32, triangles32 = vertices.astype(np.float32), triangles.astype(np.int32)
        origin = np.array([[0.1, 0.1, 1.0]], dtype=np.float32)
        down = np.array([[0.0, 0.0, -1.0]], dtype=np.float32)

        def embree_build() -> tuple[float, float]:
            """Build a scene (Embree builds its tree at the first run); return the two parts."""
            start = time.perf_counter()
            scene = rtcore_scene.EmbreeScene()
            TriangleMesh(scene, vertices32, triangles32)
            mesh = time.perf_counter()
            scene.run(origin, down, output=1)
            return mesh - start, time.perf_counter() - mesh

        calls.append(embree_build)
    timings = interleaved(repeat, calls)
    stats = timings[0].result.statistics()
    print(
        f"  BVH build, 1 thread     {1000 * timings[0].best:8.1f} ms  (CPU "
        f"{1000 * timings[0].best_cpu:.0f} ms; {stats['nodes']:,} nodes, depth {stats['depth']}, "
        f"SAH cost {stats['SAH cost']:.1f})"
    )
    if not embree:
        print("  Embree skipped: embreex is not installed (pip install embreex)")
        return
    mesh, tree = timings[1].result
    print(
        f"  Embree scene (embreex)  {1000 * timings[1].best:8.1f} ms  (CPU "
        f"{1000 * timings[1].best_cpu:.0f} ms; last call: TriangleMesh {1000 * mesh:.0f} ms, "
        f"tree at the first run {1000 * tree:.0f} ms)"
    )


def bench_shadowed(mesh: pp.Mesh, path: Path | None, size: int, repeat: int) -> None:
    camera = framed_camera(mesh, size, size)
    low, high = mesh.bounds()
    center = (low + high) / 2
    radius = float(np.linalg.norm(high - low)) / 2
    light = center + radius * np.array([2.0, 2.5, 1.5])
    diffuse = pp.Material(color=(0.8, 0.8, 0.8), ka=0.0, kd=1.0, ks=0.0)
    bunny = pp.Mesh(mesh.vertices, mesh.faces, material=diffuse, normals=mesh.normals)
    scene = pp.Scene(camera, [bunny], [pp.PointLight(light)], ambient=0.0)
    render = lambda: pp.render(scene, "raytrace", max_depth=0)  # noqa: E731
    ours = interleaved(repeat, [render])[0]
    report_render("pixelpath raytrace", ours)
    image = ours.result
    print(
        f"    {int((image.object_id >= 0).sum()):,} pixels on the bunny, "
        f"{image.stats['shadow rays']:,} shadow rays"
    )
    if path is None:
        print("  Mitsuba skipped: it loads the mesh from a file and the bunny file is absent")
        return
    compare_with_mitsuba(
        render, lambda mi: bunny_scene_dict(mi, path, camera, light, size), repeat
    )


def compare_with_mitsuba(render, scene_dict, repeat: int) -> None:
    """Time ``render`` beside Mitsuba rendering ``scene_dict(mi)`` in each variant, in turns."""
    for variant, mitsuba in mitsuba_renders(scene_dict):
        # Each variant takes turns with pixelpath in a block of its own: switching Mitsuba's
        # variant between calls would cost its render about 80 ms.
        ours, theirs = interleaved(repeat, [render, mitsuba])
        report_render("pixelpath raytrace", ours)
        report_render(f"Mitsuba 3 {variant}", theirs)
        print(
            f"    ratio pixelpath / Mitsuba time: {ours.best / theirs.best:.2f} (medians: "
            f"{ours.median / theirs.median:.2f}; CPU time: {ours.best_cpu / theirs.best_cpu:.2f})"
        )


def report_render(label: str, timing: Timing) -> None:
    print(
        f"  {label:<23} {1000 * timing.best:8.0f} ms  (median {1000 * timing.median:.0f} ms, "
        f"CPU {1000 * timing.best_cpu:.0f} ms)"
    )


def mitsuba_renders(scene_dict):
    """Yield (variant, render call) for Mitsuba 3's variants that run here, each set in turn.

    ``scalar_rgb`` traces one ray at a time; ``llvm_ad_rgb`` compiles its integrator with
    Dr.Jit into vectorized code on all cores, and needs LLVM 16 or newer (on Debian 12:
    ``apt install libllvm19`` and ``DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so``).
    The call renders the scene ``scene_dict(mi)`` describes, one sample per pixel, and reads
    the image back; variants that cannot run are skipped with the reason printed.
    """
    if importlib.util.find_spec("mitsuba") is None:
        print("  Mitsuba skipped: mitsuba is not installed (pip install mitsuba)")
        return
    import mitsuba as mi

    for variant in ("scalar_rgb", "llvm_ad_rgb"):
        try:
            mi.set_variant(variant)
        except Exception as error:  # Dr.Jit reports a missing or old LLVM in several ways
            print(f"  Mitsuba {variant} skipped: {error}")
            continue
        scene = mi.load_dict(scene_dict(mi))
        yield variant, lambda scene=scene: np.array(mi.render(scene, spp=1))


def mitsuba_sensor(mi, camera: pp.Camera) -> dict:
    """pixelpath's perspective camera as a Mitsuba sensor: one sample, a box filter."""
    return {
        "type": "perspective",
        "fov": camera.fov,
        "fov_axis": "y",
        "near_clip": camera.near,
        "far_clip": camera.far,
        "to_world": mi.ScalarTransform4f().look_at(
            origin=list(map(float, camera.eye)),
            target=list(map(float, camera.target)),
            up=list(map(float, camera.up)),
        ),
        "film": {
            "type": "hdrfilm",
            "width": camera.width,
            "height": camera.height,
            "rfilter": {"type": "box"},
        },
        "sampler": {"type": "independent", "sample_count": 1},
    }


def bunny_scene_dict(mi, path, camera, light, size) -> dict:
    """The shadowed bunny as a Mitsuba scene description (for the variant set now)."""
    return {
        "type": "scene",
        "integrator": {"type": "direct", "emitter_samples": 1, "bsdf_samples": 0},
        "sensor": mitsuba_sensor(mi, camera.with_size(size, size)),
        "bunny": {
            "type": "obj",
            "filename": str(path),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0.8] * 3}},
        },
        "light": {"type": "point", "position": list(map(float, light)), "intensity": 1.0},
    }


def bench_showcase(width: int, height: int, repeat: int) -> None:
    scene = pp.load_scene(pp.scene.bundled_scene("showcase"))
    scene = dataclasses.replace(scene, camera=scene.camera.with_size(width, height))
    render = lambda: pp.render(scene, "raytrace", max_depth=SHOWCASE_DEPTH)  # noqa: E731
    (ours,) = interleaved(repeat, [render])
    report_render("pixelpath raytrace", ours)
    stats = ours.result.stats
    print(
        f"    {stats['reflected rays']:,} reflected, {stats['refracted rays']:,} refracted, "
        f"{stats['shadow rays']:,} shadow rays"
    )
    with tempfile.TemporaryDirectory() as folder:
        for label, integrator in SHOWCASE_INTEGRATORS.items():
            print(f"  beside Mitsuba's {label}")
            compare_with_mitsuba(
                render, lambda mi, i=integrator: showcase_scene_dict(mi, scene, i, folder), repeat
            )


# pixelpath's max_depth counts the bounces after the first hit; Mitsuba's max_depth counts
# the segments of a path, the one to the light included: 5 bounces are a max_depth of 7. Its
# path tracer bounces off every surface, where a Whitted tracer stops at the diffuse ones, so
# it traces more rays than pixelpath; the direct integrator (no bounce at all) traces fewer:
# the two bracket the work.
SHOWCASE_DEPTH = 5
SHOWCASE_INTEGRATORS = {
    f"path tracer (max_depth {SHOWCASE_DEPTH + 2}, no Russian roulette)": {
        "type": "path", "max_depth": SHOWCASE_DEPTH + 2, "rr_depth": SHOWCASE_DEPTH + 2
    },
    "direct integrator (one emitter sample, no bounce)": {
        "type": "direct", "emitter_samples": 1, "bsdf_samples": 0
    },
}


def showcase_scene_dict(mi, scene: pp.Scene, integrator: dict, folder: str) -> dict:
    """A pixelpath scene as a Mitsuba scene description, meshes written as PLY into ``folder``.

    Shapes map one to one (the plane a large rectangle); lights keep their colour times their
    intensity; materials become the nearest Mitsuba BSDF (:func:`mitsuba_bsdf`). The ambient
    term and the background colour have no counterpart and are left out.
    """
    shapes = {}
    for k, shape in enumerate(scene.objects):
        shapes[f"shape{k}"] = {**mitsuba_shape(mi, shape, Path(folder) / f"mesh{k}.ply"),
                               "bsdf": mitsuba_bsdf(shape.material)}
    lights = {}
    for k, light in enumerate(scene.lights):
        value = {"type": "rgb", "value": [float(c) * light.intensity for c in light.color]}
        if isinstance(light, pp.PointLight):
            lights[f"light{k}"] = {"type": "point", "position": list(map(float, light.position)),
                                   "intensity": value}
        else:
            lights[f"light{k}"] = {"type": "directional",
                                   "direction": list(map(float, light.direction)),
                                   "irradiance": value}
    return {"type": "scene", "integrator": integrator,
            "sensor": mitsuba_sensor(mi, scene.camera), **shapes, **lights}


def mitsuba_shape(mi, shape, ply: Path) -> dict:
    """One pixelpath object as a Mitsuba shape (a mesh is written to ``ply`` first)."""
    transform = mi.ScalarTransform4f()
    if isinstance(shape, pp.Sphere):
        return {"type": "sphere", "center": list(map(float, shape.center)),
                "radius": float(shape.radius)}
    if isinstance(shape, pp.Plane):
        point, normal = list(map(float, shape.point)), np.asarray(shape.normal, dtype=float)
        up = [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0]
        frame = transform.look_at(origin=point, target=list(point + normal), up=up)
        return {"type": "rectangle", "to_world": frame.scale([1000.0, 1000.0, 1.0])}
    if isinstance(shape, pp.Box):
        low, high = np.asarray(shape.minimum), np.asarray(shape.maximum)
        place = transform.translate(list((low + high) / 2)).scale(list((high - low) / 2))
        return {"type": "cube", "to_world": place}
    import trimesh

    mesh = trimesh.Trimesh(shape.vertices, shape.triangles, vertex_normals=shape.normals,
                           process=False)
    mesh.export(ply)
    return {"type": "ply", "filename": str(ply)}


def mitsuba_bsdf(material: pp.Material) -> dict:
    """The Mitsuba BSDF nearest a pixelpath material, for timing more than for looks.

    Transparent: a smooth dielectric of the same index. Reflective: a blend of a perfect
    mirror (weight ``reflectivity``) and a diffuse surface. Otherwise diffuse, of the
    material's colour times ``kd`` (the Phong highlight has no counterpart).
    """
    diffuse = {"type": "diffuse",
               "reflectance": {"type": "rgb", "value": [float(c) * material.kd
                                                        for c in material.color]}}
    if material.transparency > 0:
        return {"type": "dielectric", "int_ior": float(material.ior)}
    if material.reflectivity > 0:
        return {"type": "blendbsdf", "weight": float(material.reflectivity),
                "bsdf_0": diffuse, "bsdf_1": {"type": "conductor"}}
    return diffuse


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per figure (best)")
    parser.add_argument("--size", type=int, default=1024, help="image side in pixels")
    args = parser.parse_args()
    label, mesh, path = load_bunny()
    # The shadowed bunny first: Embree's worker threads, once started by the primary-ray
    # section, stay in the process and slowed pixelpath's two threads by about 10 % (and sped
    # Mitsuba up by about 5 %) in the renders that followed.
    print(f"\nshadowed {label} at {args.size}²: one point light, diffuse, one sample")
    bench_shadowed(mesh, path, args.size, args.repeat)
    print(f"\n{label}: {len(mesh.triangles):,} triangles, {args.size}² primary rays")
    bench_primary(mesh, args.size, args.repeat)
    print(f"\n{label}: BVH construction")
    bench_build(mesh.vertices, mesh.triangles, args.repeat)
    vertices, triangles = height_field()
    print(f"\nheight field: {len(triangles):,} triangles, BVH construction")
    bench_build(vertices, triangles, args.repeat)
    height = args.size * 3 // 4
    print(f"\nshowcase (chrome and glass spheres) at {args.size}x{height}, max_depth 5")
    bench_showcase(args.size, height, args.repeat)


if __name__ == "__main__":
    main()
