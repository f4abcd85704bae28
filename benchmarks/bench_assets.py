"""Real assets: what textures cost, beside llvmpipe drawing the same textured mesh, and loading.

1. Texturing: the z-buffer with per-pixel Phong shading at 1024×1024 on (a) the glTF Duck
   (tests/data/models/Duck.glb, its own 512² texture) framed like the bunny of
   ``bench_raster.py``, and (b) the Stanford bunny (../shared/data/meshes; an icosphere when
   absent) with spherical texture coordinates and a procedural 2048² texture; each drawn
   textured and untextured (the same mesh without its texture and uv), in the same run. The
   ray tracer does the same at 512×512. The anchor is Mesa's llvmpipe through moderngl
   (``bench_raster.Llvmpipe``: an sRGB texture with mip maps, trilinear), drawing the same
   textured mesh with the same camera.
2. Loading: ``pixelpath.load_scene`` beside ``trimesh.load`` of the same file (the Duck, and the
   CesiumMilkTruck when ``--models`` holds it: it is in trimesh's own ``models/`` folder).

Usage::

    python benchmarks/bench_assets.py [--frames 10] [--size 1024] [--models DIR]
                                      [--only zbuffer|raytrace|loading ...]

``--only`` runs the named parts alone (``zbuffer`` and ``raytrace``: part 1's two renderers,
``zbuffer`` with llvmpipe beside it; ``loading``: part 2).
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import time
from pathlib import Path

import numpy as np
from bench_raster import compare_with_llvmpipe, framed_scene, load_model, time_frames

import pixelpath as pp
from pixelpath.scene.texture import linear_to_srgb

MODELS = Path(__file__).resolve().parents[1] / "tests" / "data" / "models"
PARTS = ("zbuffer", "raytrace", "loading")
LOADING_REPEATS = 300


def spherical_uv(mesh: pp.Mesh) -> np.ndarray:
    """(V, 2) longitude and latitude of each vertex about the mesh's centre, scaled to [0, 1]."""
    low, high = mesh.bounds()
    p = mesh.vertices - (low + high) / 2
    radius = np.linalg.norm(p, axis=1)
    u = np.arctan2(p[:, 0], p[:, 2]) / (2 * np.pi) + 0.5
    v = np.arcsin(np.clip(p[:, 1] / np.maximum(radius, 1e-12), -1, 1)) / np.pi + 0.5
    return np.stack([u, v], axis=1)


def procedural_texture(side: int) -> pp.Texture:
    """A side × side colourful checkerboard with soft stripes (8-bit, sRGB)."""
    y, x = np.mgrid[0:side, 0:side] / side
    checker = ((np.floor(x * 32) + np.floor(y * 32)) % 2)[..., None]
    stripes = 0.5 + 0.5 * np.sin(2 * np.pi * np.stack([x * 7, y * 5, (x + y) * 3], axis=2))
    picture = 0.35 + 0.65 * (0.6 * checker + 0.4 * stripes)
    return pp.Texture(np.rint(picture * 255).astype(np.uint8))


def textured_pair(label: str, mesh: pp.Mesh, texture: pp.Texture, uv: np.ndarray, size: int):
    """The scene drawn textured and the same scene untextured."""
    material = dataclasses.replace(mesh.material, texture=texture)
    textured = pp.Mesh(mesh.vertices, mesh.faces, material, mesh.normals, uv=uv, name=label)
    plain = pp.Mesh(mesh.vertices, mesh.faces, dataclasses.replace(material, texture=None),
                    mesh.normals, name=label)
    return framed_scene(textured, size), framed_scene(plain, size)


def duck() -> tuple[str, pp.Mesh]:
    """The Duck's one mesh, textured, in the file's coordinates."""
    from pixelpath.io.models import read_model_objects

    (mesh,) = read_model_objects(MODELS / "Duck.glb")
    return "Duck.glb", mesh


def bench_texturing(label, textured, plain, size, frames, method="zbuffer") -> None:
    """Print textured and untextured ms/frame and the cost of texturing."""
    mesh = textured.objects[0]
    texture = mesh.material.texture
    print(f"\n{label}: {len(mesh.triangles):,} triangles, {texture.width}x{texture.height} "
          f"texture, {size}x{size}, {method}, Phong per pixel")
    cameras = {}
    for name, scene in (("untextured", plain), ("textured", textured)):
        scene = dataclasses.replace(scene, camera=scene.camera.with_size(size, size))
        cameras[name] = scene
        pp.render(scene, method)
    times = {name: time_frames(lambda s=scene: pp.render(s, method), frames)
             for name, scene in cameras.items()}
    for name, (median, best) in times.items():
        print(f"  pixelpath {name:10s} {median:8.1f} ms/frame (best {best:.1f})")
    cost = times["textured"][0] / times["untextured"][0] - 1
    print(f"  texturing costs {cost:+.0%} (goal: at most +30 %)")
    if method == "zbuffer":  # llvmpipe draws the textured scene; pictures compared in sRGB
        image = np.asarray(pp.render(cameras["textured"]))
        compare_with_llvmpipe(cameras["textured"], image, times["textured"][0], frames,
                              encode=linear_to_srgb)


def bench_loading(models: Path, repeats: int) -> None:
    """Print pixelpath's and trimesh's loading times of the same files."""
    import trimesh

    print(f"\nloading (median of {repeats} loads, after one warm-up load)")
    for name in ("Duck.glb", "CesiumMilkTruck.glb"):
        path = models / name
        if not path.is_file():
            print(f"  {name}: not in {models} (it is in trimesh's models/ folder): skipped")
            continue

        def seconds(load, path=path) -> float:
            load(path)
            times = []
            for _ in range(repeats):
                start = time.perf_counter()
                load(path)
                times.append(time.perf_counter() - start)
            return 1000 * statistics.median(times)

        ours = seconds(pp.load_scene)
        theirs = seconds(lambda p: trimesh.load(p, process=False))
        print(f"  {name:20s} pixelpath {ours:6.2f} ms   trimesh.load {theirs:6.2f} ms   "
              f"ratio {ours / theirs:.2f} (goal: at most 1.5)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=10, help="timed frames per renderer")
    parser.add_argument("--size", type=int, default=1024, help="raster image side in pixels")
    parser.add_argument("--models", type=Path, default=MODELS, help="folder of model files")
    parser.add_argument("--only", nargs="+", choices=PARTS, default=PARTS,
                        help="the parts to run (default: all)")
    args = parser.parse_args()

    import numba

    print(f"pixelpath {pp.__version__}: numba {numba.__version__}, "
          f"{numba.get_num_threads()} threads; {os.cpu_count()} CPUs; "
          f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'default')}")
    loading_repeats = max(args.frames, LOADING_REPEATS)  # a load takes milliseconds
    if "loading" in args.only and len(args.only) == 1:
        bench_loading(args.models, loading_repeats)
        return
    label, bunny = load_model("stanford-bunny.obj")
    cases = []
    duck_label, duck_mesh = duck()
    cases.append((duck_label, *textured_pair(duck_label, duck_mesh, duck_mesh.material.texture,
                                             duck_mesh.uv, args.size)))
    cases.append((label, *textured_pair(label, bunny, procedural_texture(2048),
                                        spherical_uv(bunny), args.size)))
    if "zbuffer" in args.only:
        for name, textured, plain in cases:
            bench_texturing(name, textured, plain, args.size, args.frames)
    if "raytrace" in args.only:
        for name, textured, plain in cases:
            bench_texturing(name, textured, plain, args.size // 2, max(args.frames // 2, 3),
                            method="raytrace")
    if "loading" in args.only:
        bench_loading(args.models, loading_repeats)


if __name__ == "__main__":
    main()
