"""A row's texture lookups, made together by the shading pass, equal the lookups one by one."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from pixelpath.raster import _kernels
from pixelpath.scene import Material, Mesh, Texture
from pixelpath.scene import _texture_kernels as tk
from pixelpath.scene.texture import surface_tables

QUAD = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
QUAD_UV = [[0, 0], [1, 0], [1, 1], [0, 1]]
PICTURES = [np.random.default_rng(seed).integers(0, 256, shape, dtype=np.uint8)
            for seed, shape in ((1, (8, 8, 4)), (2, (6, 5, 3)), (3, (4, 4, 3)))]
# (filter, wrap) of the three textures: a power-of-two one repeated, an odd one clamped, and
# one read nearest (which takes no part in the base-level loop).
SAMPLERS = [("trilinear", "repeat"), ("bilinear", "clamp"), ("nearest", "mirror")]
TABLES = surface_tables([
    Mesh(QUAD, [[0, 1, 2, 3]],
         Material(texture=Texture(picture), texture_filter=texture_filter, texture_wrap=wrap),
         uv=QUAD_UV)
    for picture, (texture_filter, wrap) in zip(PICTURES, SAMPLERS, strict=True)
])

lookup = st.tuples(
    st.integers(0, 2),  # the texture
    # (no NaN: without the JIT, as CI also runs the suite, Python's floor refuses it)
    st.floats(-3, 3, allow_nan=False) | st.just(1e12) | st.just(-1e12),
    st.floats(-3, 3, allow_nan=False),
    st.floats(0.0, 1.0) | st.floats(1.0, 200.0),  # the squared footprint: base level or not
)


@settings(max_examples=150, deadline=None)
@given(st.lists(lookup, min_size=1, max_size=40), st.booleans())
def test_a_rows_lookups_equal_the_lookups_one_by_one(lookups, emission):
    # Rows that start with a base-level lookup take the loop of their own for those, the
    # others the general one; either way each pixel's colour is the product, bit for bit, of
    # its surface colour and the texture sampled at its footprint (the ray tracer's lookup).
    # The emission textures' lookups are listed after the row's room for the surface's.
    width = len(lookups)
    first = width if emission else 0
    batch = _kernels.new_batch(width)
    for q, (texture, u, v, squared) in enumerate(lookups):
        batch.lookups[:, first + q] = u, v, squared
        batch.lookup_textures[first + q] = texture
        batch.lookup_columns[first + q] = width - 1 - q  # the pixels in another order
    colours = np.random.default_rng(width).uniform(0.2, 1.0, (width, 3))
    expected = colours.copy()
    for q, (texture, u, v, squared) in enumerate(lookups):
        sampled = tk.sample(TABLES, texture, u, v, math.sqrt(squared))
        expected[width - 1 - q] *= sampled[:3]

    _kernels._apply_lookups(np.intp(first), np.intp(first + width), TABLES, batch, colours)

    assert colours.tobytes() == expected.tobytes()


def test_plain_scenes_are_drawn_without_lookups_to_the_same_bytes(monkeypatch):
    # A scene without textures, vertex colours or alpha tests does not look its surfaces up:
    # the passes get None (their versions without the alpha test and colour lookups), and
    # the cutouts and tables otherwise. For a plain scene, the passes with them (forced here)
    # draw the very same bytes.
    import dataclasses

    import pixelpath as pp
    from pixelpath.contract import RenderOptions, View
    from pixelpath.hsr import pipeline
    from pixelpath.scene import bundled_scenes, load_scene

    plain = load_scene(bundled_scenes()["showcase"])
    plain = dataclasses.replace(plain, camera=plain.camera.with_size(80, 50))
    quad = Mesh(QUAD, [[0, 1, 2, 3]], Material(texture=Texture(PICTURES[0])), uv=QUAD_UV)
    cut = Mesh(QUAD, [[0, 1, 2, 3]], Material(alpha=0.3, alpha_cutoff=0.5))
    for objects, looked_up in ((plain.objects, False), ([quad], True), ([cut], True)):
        scene = dataclasses.replace(plain, objects=objects)
        view = View.whole(scene.camera)
        prepared = pipeline.prepare(scene, view, RenderOptions())
        assert _kernels.looks_up(pipeline.surfaces(prepared, scene, view)) is looked_up
    pictures = {method: pp.render(plain, method) for method in ("zbuffer", "painter")}
    monkeypatch.setattr(_kernels, "looks_up", lambda surfaces: True)
    for method, picture in pictures.items():
        forced = pp.render(plain, method)
        for name in ("rgb", "depth", "object_id", "normal"):
            assert np.array_equal(getattr(forced, name), getattr(picture, name)), (method, name)
