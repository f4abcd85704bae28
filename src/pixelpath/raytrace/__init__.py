"""Ray tracing (notes, section 8): ray geometry, a BVH for meshes, and the recursive ray tracer.

* :mod:`~pixelpath.raytrace.geometry`: ``ray_sphere``, ``ray_plane``, ``reflect``, ``refract``,
  vectorized over batches of rays;
* :mod:`~pixelpath.raytrace.bvh`: ``BVH`` (binned surface-area heuristic, flat arrays) and
  ``intersect``, the nearest hits of many rays on a mesh;
* :mod:`~pixelpath.raytrace.tracer`: the rendering method, ``render(scene, method="raytrace")``:
  shadows, reflection and refraction to ``max_depth``, stratified supersampling;
* :mod:`~pixelpath.raytrace.explain`: ``ray_tree``, one pixel's tree of rays as data and as
  the notes would write it out.

Importing this package compiles nothing; the kernels load on first use.

Examples
--------
>>> from pixelpath import raytrace
>>> raytrace.ray_sphere((0, 0, 5), (0, 0, -1), (0, 0, 0), 1.0)
4.0
>>> raytrace.refract((0, -1, 0), (0, 1, 0), 1 / 1.5).tolist()
[0.0, -1.0, 0.0]
"""

from pixelpath.raytrace.bvh import BVH, intersect
from pixelpath.raytrace.explain import RayNode, RayTree, ray_tree
from pixelpath.raytrace.geometry import ray_plane, ray_sphere, reflect, refract

__all__ = [
    "BVH",
    "RayNode",
    "RayTree",
    "intersect",
    "ray_plane",
    "ray_sphere",
    "ray_tree",
    "reflect",
    "refract",
]
