"""The ray tracer puts every object on the z-buffer's pixels, up to silhouettes.

Colours differ by design (shadows, reflections), so only ``object_id`` and ``depth`` are
compared: ids equal on at least 99 % of the pixels and differing only on edges of the
z-buffer's id image; depths equal where the ids do, except on analytic spheres (the rasterizer
draws their tessellation, a little inside the true surface).
"""

from __future__ import annotations

import numpy as np
import pytest
from agreement import KINDS, id_edges, scene_of

import pixelpath as pp
from pixelpath.scene.bundled import bundled_scene


def check_ids(scene: pp.Scene, **options) -> float:
    reference = pp.render(scene, "zbuffer", **options)
    image = pp.render(scene, "raytrace", max_depth=0, **options)
    same = image.object_id == reference.object_id
    assert same.mean() >= 0.99, f"only {same.mean():.2%} of the object ids agree"
    stray = ~same & ~id_edges(reference.object_id)
    assert not stray.any(), f"ids differ off the edges, e.g. at {np.argwhere(stray)[0].tolist()}"
    spheres = [k for k, o in enumerate(scene.objects) if isinstance(o, pp.Sphere)]
    exact = same & ~np.isin(reference.object_id, spheres) & np.isfinite(reference.depth)
    np.testing.assert_allclose(image.depth[exact], reference.depth[exact], rtol=1e-4)
    np.testing.assert_array_equal(np.isinf(image.depth), image.object_id < 0)
    return float(same.mean())


@pytest.mark.parametrize("kind", KINDS)
def test_raytrace_ids_equal_the_zbuffers(kind):
    check_ids(scene_of(kind, seed=5))


def test_raytrace_ids_equal_the_zbuffers_with_back_faces_drawn():
    check_ids(scene_of("near", seed=6), backface_cull=False)


def test_raytrace_ids_equal_the_zbuffers_on_the_showcase():
    scene = pp.load_scene(bundled_scene("showcase"))
    scene = pp.Scene(
        scene.camera.with_size(160, 100), scene.objects, scene.lights, scene.ambient,
        scene.background,
    )
    check_ids(scene)
