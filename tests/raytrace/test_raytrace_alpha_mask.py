"""The ray tracer's eye, shadow, reflected and refracted rays pass through alpha-tested holes.

Expected pixels come from independent NumPy geometry (tests/alpha_scenes.py, camera_rays.py),
never from the renderer itself. That the eye rays see the holes every raster method sees:
tests/hsr/test_hsr_alpha_mask.py; packets of rays against holes: test_raytrace_packets.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import pixelpath as pp
from alpha_scenes import (
    BLUE,
    FOV,
    HOLES,
    OPAQUE,
    SIZE,
    SQUARE_UV,
    expected_holes,
    facing_scene,
    holed_quad,
    texel_under,
    unlit,
    wall,
)
from camera_rays import view_rays


def test_shadow_rays_pass_through_the_holes():
    # A holed quad lies flat at y = 0 over a white floor at y = -1, under a light straight
    # above: the floor is lit below the holes and in shadow below the opaque texels. The
    # camera looks at the floor from below the quad's plane, so it never sees the quad.
    quad = pp.Mesh([[-1, 0, 1], [1, 0, 1], [1, 0, -1], [-1, 0, -1]], [[0, 1, 2, 3]],
                   unlit(texture=HOLES, texture_filter="nearest", alpha_cutoff=0.5),
                   uv=SQUARE_UV)  # u along +x, v along -z
    floor = pp.Plane((0, -1, 0), (0, 1, 0), pp.Material(color=(1, 1, 1), ka=0.0, kd=1.0, ks=0.0))
    eye = np.array([0.0, -0.2, 2.0])
    view = pp.Camera(eye=eye, target=(0, -1, 0), fov=FOV, width=SIZE, height=SIZE)
    scene = pp.Scene(view, [quad, floor], [pp.DirectionalLight((0, -1, 0))], ambient=0.0)
    image = pp.render(scene, "raytrace")
    # independent geometry: each pixel's ray met with the floor, then straight up to the quad
    directions = view_rays(view)
    t = (-1.0 - eye[1]) / directions[..., 1]
    points = eye + t[..., None] * directions
    inside, clear, row, column = texel_under(points[..., 0], -points[..., 2])
    lit = ~(inside & OPAQUE[row, column])
    check = clear & (t > 0) & (image.object_id == 1)
    assert check.sum() > 100 and (check & ~lit).sum() > 20
    brightness = np.asarray(image)[..., 0]
    np.testing.assert_array_equal(brightness[check] > 0.5, lit[check])
    assert np.all(brightness[check & ~lit] == 0.0)


def test_refracted_rays_pass_through_the_holes():
    # A clear pane (transmits everything, ior 1: rays go on straight) in front of the holed
    # quad: through the pane, the refracted rays see the quad's holes and the wall behind.
    pane = pp.Mesh([[-2, -2, 1], [2, -2, 1], [2, 2, 1], [-2, 2, 1]], [[0, 1, 2, 3]],
                   pp.Material(color=(0, 0, 0), ka=0.0, kd=0.0, ks=0.0, transparency=1.0,
                               ior=1.0))
    image = pp.render(facing_scene([pane, holed_quad(), wall()]), "raytrace", fresnel=False)
    kept, clear, colour = expected_holes(3.0)
    assert (image.object_id[clear] == 0).all()  # the pane is what the eye rays hit
    rgb = np.asarray(image)
    np.testing.assert_allclose(rgb[clear & kept], colour[clear & kept], atol=1e-6)
    np.testing.assert_allclose(rgb[clear & ~kept], np.broadcast_to(BLUE, rgb.shape)[
        clear & ~kept], atol=1e-6)


def test_reflected_rays_pass_through_the_holes():
    # A mirror at z = -1 facing the camera reflects what lies behind the camera: the holed
    # quad at z = 4 (facing the mirror), and through its holes a wall at z = 5. A reflected ray
    # travels 4 to the mirror and 5 back to the quad: the quad is seen as at distance 9.
    mirror = pp.Plane((0, 0, -1), (0, 0, 1),
                      pp.Material(color=(0, 0, 0), ka=0.0, kd=0.0, ks=0.0, reflectivity=1.0))
    quad = holed_quad(z=4.0)
    # facing -z, mirrored: as seen in the mirror its texels are where a quad at distance 9 in
    # front of the camera would show them
    quad = pp.Mesh(quad.vertices, [[3, 2, 1, 0]], quad.material, uv=quad.uv)
    behind = wall(z=5.0, normal_z=-1.0, half=8.0)
    scene = facing_scene([mirror, quad, behind])
    image = pp.render(scene, "raytrace", fresnel=False)
    kept, clear, colour = expected_holes(9.0)
    rgb = np.asarray(image)
    assert (image.object_id[clear] == 0).all()  # the mirror
    np.testing.assert_allclose(rgb[clear & kept], colour[clear & kept], atol=1e-6)
    np.testing.assert_allclose(rgb[clear & ~kept], np.broadcast_to(BLUE, rgb.shape)[
        clear & ~kept], atol=1e-6)
    assert (clear & kept).sum() > 5 and (clear & ~kept).sum() > 100


# --- the one-ray searches with the alpha test, against brute force ------------------------------


def _holed_ring(rng):
    """A torus with random uv and a 4 x 4 "nearest" texture whose alpha cuts about half away."""
    from pixelpath.raytrace import BVH
    from pixelpath.raytrace import _traversal_kernels as kernels
    from pixelpath.scene import torus
    from pixelpath.scene.texture import surface_tables

    ring = torus(0.7, 0.25, 24, 12)
    alpha = rng.uniform(0, 1, (4, 4))
    texture = np.ones((4, 4, 4))
    texture[..., 3] = alpha
    uv = rng.uniform(0, 1, (len(ring.vertices), 2))
    holed = pp.Mesh(ring.vertices, ring.faces,
                    pp.Material(texture=texture, texture_filter="nearest", alpha_cutoff=0.5),
                    uv=uv)
    bvh = BVH.build(ring.vertices, ring.triangles)
    count = len(bvh.corners)
    corners = np.ascontiguousarray(uv[ring.triangles][bvh.order].reshape(-1, 2))
    cutouts = kernels.Cutouts(np.ones(count, dtype=np.bool_), np.zeros(count, dtype=np.intp),
                              corners, np.empty((0, 4)), surface_tables([holed]))
    return ring, uv, alpha, bvh, cutouts


def _hits_along(ring, uv, alpha, origin, direction):
    """Every hit of the ray (Möller-Trumbore in NumPy), nearest first: (t, triangle, kept, clear).

    ``kept``: the texel under the hit is at least half opaque; ``clear``: the hit is not within
    a hair of a texel border, where the kernels' rounding may pick the other texel.
    """
    corners = ring.vertices[ring.triangles]
    e1, e2 = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    p = np.cross(direction, e2)
    det = np.einsum("ij,ij->i", e1, p)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = origin - corners[:, 0]
        u = np.einsum("ij,ij->i", s, p) / det
        q = np.cross(s, e1)
        v = (q @ direction) / det
        t = np.einsum("ij,ij->i", e2, q) / det
    hit = (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
    found = []
    for k in np.flatnonzero(hit)[np.argsort(t[hit])]:
        a, b, c = ring.triangles[k]
        tex = (1 - u[k] - v[k]) * uv[a] + u[k] * uv[b] + v[k] * uv[c]
        x, y = tex[0] * 4, (1 - tex[1]) * 4
        clear = min(abs(x - round(x)), abs(y - round(y))) > 1e-6
        kept = alpha[int(np.floor(y)) % 4, int(np.floor(x)) % 4] >= 0.5
        found.append((t[k], int(k), bool(kept), clear))
    return found


def test_one_ray_searches_with_holes_equal_brute_force():
    from pixelpath.raytrace import _traversal_kernels as kernels
    from pixelpath.raytrace._hit_kernels import slab_nan_allowed

    rng = np.random.default_rng(11)
    ring, uv, alpha, bvh, cutouts = _holed_ring(rng)
    pass_through = rng.choice([0.0, 0.5], size=len(bvh.corners))  # in leaf order
    stack = np.empty(bvh.depth + 1, dtype=np.intp)
    checked = through_holes = 0
    for _ in range(300):
        origin = rng.normal(size=3)
        origin *= 3.0 / np.linalg.norm(origin)
        direction = rng.uniform(-0.8, 0.8, 3) - origin
        hits = _hits_along(ring, uv, alpha, origin, direction)
        if not all(clear for *_, clear in hits):
            continue
        checked += 1
        with slab_nan_allowed():
            t, leaf, _, _, _, _ = kernels.closest_triangle(
                bvh.bounds, bvh.links, bvh.corners, bvh.order, np.zeros(0, np.bool_), False,
                *origin, *direction, 0.0, math.inf, stack, np.empty(bvh.depth + 1), cutouts,
            )
            light, blocker, _, _ = kernels.any_triangle(
                bvh.bounds, bvh.links, bvh.corners, pass_through, *origin, *direction, 0.0, 1e9,
                stack, cutouts,
            )
        kept = [(t_hit, k) for t_hit, k, keep, _ in hits if keep]
        if kept:
            assert leaf >= 0 and bvh.order[leaf] == kept[0][1]
            assert t == pytest.approx(kept[0][0], rel=1e-9)
            through_holes += kept[0][1] != hits[0][1]
        else:
            assert leaf == kernels.MISS
        leaf_of = {int(k): i for i, k in enumerate(bvh.order)}
        fractions = [pass_through[leaf_of[k]] for _, k in kept]
        expected = float(np.prod(fractions)) if fractions else 1.0
        assert light == pytest.approx(expected, rel=1e-12)
        assert (blocker >= 0) == (expected == 0.0)
    assert checked > 200 and through_holes > 20
