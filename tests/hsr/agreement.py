"""Scenes on which every hidden-surface method must agree with the z-buffer, and the check.

Each scene kind stresses a different part of the methods:

* ``separate``: random meshes (icospheres, tori, rotated boxes) that do not touch;
* ``interpenetrating``: meshes that pass through each other (visibility changes inside
  polygons, so the painter's method must split and the scan line must split spans);
* ``cyclic``: three long triangles each overlapping the next (no depth order exists);
* ``coplanar``: coplanar faces side by side (a subdivided ground grid, boxes sharing a face
  plane), where plane-side tests meet points lying on the plane;
* ``near``: a camera close enough that objects cross the near plane (frustum clipping);
* ``floor``: an infinite plane under objects, seen towards the horizon.

:func:`check_agreement` asserts what issue 7 asks: the method's object ids equal the
z-buffer's on at least 99.5 % of the pixels, every differing pixel lies on an edge of the
z-buffer's id image (a silhouette or an intersection curve), and the colours agree where the
ids do.
"""

from __future__ import annotations

import numpy as np

import pixelpath as pp
from pixelpath.scene import icosphere, torus

KINDS = ("separate", "interpenetrating", "cyclic", "coplanar", "near", "floor")
SIZE = (96, 72)


def _camera(eye=(0.0, 2.5, 5.5), target=(0.0, 0.3, 0.0), size=SIZE, near=0.1):
    return pp.Camera(eye=eye, target=target, fov=45, width=size[0], height=size[1], near=near)


def _material(rng) -> pp.Material:
    return pp.Material(color=rng.uniform(0.2, 1.0, 3), ks=0.4, shininess=16)


def _lights():
    return [pp.PointLight((4, 6, 5)), pp.DirectionalLight(direction=(-1, -1, -0.5), intensity=0.4)]


def _box(rng, center, size) -> pp.Mesh:
    """A box with a random rotation about a random axis, as a mesh."""
    half = np.array(size) / 2
    mesh = pp.Box(-half, half, _material(rng)).to_mesh()
    angles = rng.uniform(0, 360, 3)
    return mesh.transformed(pp.scene.transform_matrix(translate=center, rotate=angles))


def separate(seed: int) -> pp.Scene:
    """Four objects on a 2 × 2 grid of cells, each inside its own cell (they never touch)."""
    rng = np.random.default_rng(seed)
    objects = []
    for k, (x, z) in enumerate([(-1.6, -1.2), (1.6, -1.2), (-1.6, 1.2), (1.6, 1.2)]):
        center = (x + rng.uniform(-0.2, 0.2), rng.uniform(0.2, 0.8), z + rng.uniform(-0.2, 0.2))
        kind = (seed + k) % 3
        if kind == 0:
            objects.append(icosphere(2, rng.uniform(0.5, 0.8), center, _material(rng)))
        elif kind == 1:
            ring = torus(0.6, 0.2, 24, 12, material=_material(rng))
            matrix = pp.scene.transform_matrix(translate=center, rotate=rng.uniform(0, 360, 3))
            objects.append(ring.transformed(matrix))
        else:
            objects.append(_box(rng, center, rng.uniform(0.6, 1.1, 3)))
    return pp.Scene(_camera(), objects=objects, lights=_lights())


def interpenetrating(seed: int) -> pp.Scene:
    """A box, a sphere and a torus pushed into each other near the origin."""
    rng = np.random.default_rng(seed)
    jitter = rng.uniform(-0.15, 0.15, (3, 3))
    ball = icosphere(2, 0.9, (0.3, 0.4, 0.0) + jitter[0], _material(rng))
    block = _box(rng, (-0.4, 0.3, 0.2) + jitter[1], (1.4, 1.0, 1.2))
    ring = torus(0.9, 0.25, 32, 12, material=_material(rng))
    ring = ring.transformed(
        pp.scene.transform_matrix(translate=(0.0, 0.5, 0.3) + jitter[2], rotate=(70, 20, 0))
    )
    return pp.Scene(_camera(), objects=[ball, block, ring], lights=_lights())


def cyclic(seed: int) -> pp.Scene:
    """Three long triangles along the sides of a triangle, each over the next: no depth order.

    Triangle k runs from corner k past corner k + 1, wide at its start and sinking away from
    the eye along its length, so at every corner the triangle that starts there lies over the
    one that ends there: 1 over 0, 2 over 1 and 0 over 2.
    """
    rng = np.random.default_rng(seed)
    turn = np.radians(rng.uniform(0, 120))
    angles = turn + np.radians([90, 210, 330])
    corners = 1.2 * np.stack([np.cos(angles), np.sin(angles)], axis=1)
    objects = []
    for k in range(3):
        start, stop = corners[k], corners[(k + 1) % 3]
        along = (stop - start) / np.linalg.norm(stop - start)
        across = np.array([-along[1], along[0]])
        tail, tip = start - 0.9 * along, stop + 0.9 * along
        points = [(*(tail + 0.35 * across), 0.4), (*(tail - 0.35 * across), 0.4), (*tip, -0.4)]
        u, v = points[1][:2] - tail - 0.35 * across, tip - tail - 0.35 * across
        if u[0] * v[1] - u[1] * v[0] < 0:  # 2-D cross product (NumPy 2 deprecates np.cross)
            points[0], points[1] = points[1], points[0]  # counter-clockwise seen from +z
        objects.append(pp.Mesh(points, [[0, 1, 2]], _material(rng)))
    camera = _camera(eye=(0.1, 0.2, 5.0), target=(0.0, 0.0, 0.0))
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((0, 0, 6))])


def coplanar(seed: int) -> pp.Scene:
    """A subdivided ground grid and two boxes whose front faces lie in one plane."""
    rng = np.random.default_rng(seed)
    n = 6
    xs = np.linspace(-3, 3, n + 1)
    grid_x, grid_z = np.meshgrid(xs, xs)
    vertices = np.stack([grid_x.ravel(), np.zeros(grid_x.size), grid_z.ravel()], axis=1)
    quads = []
    for row in range(n):
        for col in range(n):
            v = row * (n + 1) + col
            quads.append([v, v + n + 1, v + n + 2, v + 1])  # counter-clockwise seen from above
    ground = pp.Mesh(vertices, quads, _material(rng))
    depth = rng.uniform(0.4, 0.8)
    left = pp.Box((-1.5, 0.0, -depth), (0.0, 1.2, 0.5), _material(rng))
    right = pp.Box((0.0, 0.0, -depth), (1.3, 0.8, 0.5), _material(rng))
    return pp.Scene(_camera(), objects=[ground, left, right], lights=_lights())


def near(seed: int) -> pp.Scene:
    """The camera inside the cluster: several objects cross the near plane."""
    rng = np.random.default_rng(seed)
    objects = [
        icosphere(2, 0.8, (0.2, 0.0, 1.7), _material(rng)),
        _box(rng, (-0.6, 0.2, 0.5), (1.0, 1.0, 1.0)),
        icosphere(2, 1.0, (0.5, -0.2, -1.0), _material(rng)),
    ]
    camera = _camera(eye=(0.0, 0.1, 2.2), target=(0.0, 0.0, -1.0), near=0.5)
    return pp.Scene(camera, objects=objects, lights=_lights())


def floor(seed: int) -> pp.Scene:
    """An infinite plane reaching the horizon, a sphere and a box standing on it."""
    rng = np.random.default_rng(seed)
    objects = [
        pp.Plane((0, 0, 0), (0, 1, 0), _material(rng)),
        pp.Sphere((-1.0, 0.8, 0.0), 0.8, _material(rng)),
        pp.Box((0.6, 0.0, -0.5), (1.6, 1.0, 0.5), _material(rng)),
    ]
    camera = _camera(eye=(0.0, 1.2, 6.0), target=(0.0, 0.6, 0.0))
    return pp.Scene(camera, objects=objects, lights=_lights())


SCENES = {
    "separate": separate,
    "interpenetrating": interpenetrating,
    "cyclic": cyclic,
    "coplanar": coplanar,
    "near": near,
    "floor": floor,
}


def scene_of(kind: str, seed: int = 0) -> pp.Scene:
    """Return the scene of one kind for one seed."""
    return SCENES[kind](seed)


def id_edges(ids: np.ndarray) -> np.ndarray:
    """Pixels whose id differs from one of their 8 neighbours' (silhouettes, intersections)."""
    padded = np.pad(ids, 1, mode="edge")
    height, width = ids.shape
    edge = np.zeros(ids.shape, dtype=bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            edge |= padded[1 + dy : 1 + dy + height, 1 + dx : 1 + dx + width] != ids
    return edge


def check_agreement(scene: pp.Scene, method: str, shading: str = "phong", **options) -> float:
    """Assert that ``method`` draws ``scene`` like the z-buffer; return the agreeing fraction."""
    reference = pp.render(scene, "zbuffer", shading, **options)
    image = pp.render(scene, method, shading, **options)
    same_id = image.object_id == reference.object_id
    fraction = float(same_id.mean())
    assert fraction >= 0.995, f"{method}: only {fraction:.2%} of the object ids agree"
    outside_edges = ~same_id & ~id_edges(reference.object_id)
    assert not outside_edges.any(), (
        f"{method}: {int(outside_edges.sum())} differing pixels are not on an edge of the "
        f"z-buffer's id image, e.g. at (row, col) {np.argwhere(outside_edges)[0].tolist()}"
    )
    colour_gap = np.abs(np.asarray(image) - np.asarray(reference)).max(axis=2)
    same_colour = colour_gap[same_id] <= 1e-5
    assert same_colour.mean() >= 0.995, (
        f"{method}: colours differ on {1 - same_colour.mean():.2%} of the pixels whose ids agree"
    )
    depth_ok = np.isclose(image.depth[same_id], reference.depth[same_id], rtol=1e-5)
    assert depth_ok.mean() >= 0.995, f"{method}: depths differ where the ids agree"
    return fraction
