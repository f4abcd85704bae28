"""Textures and vertex colours in every method: orientation, agreement, perspective, lighting.

Expected values are derived here by hand or with independent NumPy maths (ray-plane
intersections, screen-space projections), never produced by the renderer itself.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from agreement import check_agreement

import pixelpath as pp
from pixelpath.scene import torus
from pixelpath.scene.texture import srgb_to_linear

RASTER = ["zbuffer", "scanline", "painter", "bsp", "warnock", "octree"]
# (method, shading) pairs: every raster method with every shading, the ray tracer's two.
METHOD_SHADINGS = [(m, s) for m in RASTER for s in ("flat", "gouraud", "phong")] + [
    ("raytrace", "phong"), ("raytrace", "flat"),
]
EVERY_METHOD = [*RASTER, "raytrace"]

# Rows top to bottom: red, green / blue, white.
QUADRANTS = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], np.uint8)
SQUARE = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]  # counter-clockwise seen from +z
SQUARE_UV = [[0, 0], [1, 0], [1, 1], [0, 1]]  # (0, 0) at the bottom-left


def unlit(**options) -> pp.Material:
    """A white material lit by the ambient term alone (ka Ia = 1): the pixel is the colour."""
    return pp.Material(color=(1, 1, 1), ka=1.0, kd=0.0, ks=0.0, **options)


def facing_scene(objects, size=32, ambient=1.0, lights=None, eye=(0, 0, 3)):
    camera = pp.Camera(eye=eye, target=(0, 0, 0), fov=60, width=size, height=size)
    if lights is None:
        lights = [pp.PointLight((0, 0, 5))]
    return pp.Scene(camera, objects=objects, lights=lights, ambient=ambient)


# --- orientation ---------------------------------------------------------------------------


@pytest.mark.parametrize(("method", "shading"), METHOD_SHADINGS)
def test_uv_orientation(method, shading):
    quad = pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(texture=QUADRANTS, texture_filter="nearest"),
                   uv=SQUARE_UV)
    image = pp.render(facing_scene([quad]), method, shading)
    rgb = np.asarray(image)
    # The quad spans pixels ~7..25; (row, col) (8, 8) is its top-left quarter.
    assert rgb[8, 8].tolist() == [1, 0, 0]  # red, top-left of the picture
    assert rgb[8, 23].tolist() == [0, 1, 0]  # green, top-right
    assert rgb[23, 8].tolist() == [0, 0, 1]  # blue, bottom-left
    assert rgb[23, 23].tolist() == [1, 1, 1]  # white, bottom-right
    assert image.object_id[8, 8] == 0 and image.object_id[0, 0] == -1


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_default_filter_keeps_the_quadrants(method):
    quad = pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(texture=QUADRANTS), uv=SQUARE_UV)
    rgb = np.asarray(pp.render(facing_scene([quad]), method))
    for (row, col), channel in {(9, 9): 0, (9, 22): 1, (22, 9): 2}.items():
        assert np.argmax(rgb[row, col]) == channel
        assert rgb[row, col, channel] > 2 * np.delete(rgb[row, col], channel).max()
    assert rgb[22, 22].min() > 0.5


def test_texture_needs_uv_and_vertex_colours_need_no_texture():
    plain = pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(texture=QUADRANTS))  # no uv: no texture
    rgb = np.asarray(pp.render(facing_scene([plain])))
    assert rgb[8, 8].tolist() == [1, 1, 1] and rgb[23, 23].tolist() == [1, 1, 1]
    corners = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]]
    painted = pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(), colors=corners)
    rgb = np.asarray(pp.render(facing_scene([painted]), shading="phong"))
    # Near a corner the colour is close to that corner's (bottom-left is vertex 0: red).
    assert np.argmax(rgb[24, 8]) == 0 and np.argmax(rgb[24, 24]) == 1
    assert np.argmax(rgb[8, 24]) == 2 and rgb[8, 8, 2] < 0.2 < rgb[8, 8, :2].min()


# --- agreement with the z-buffer -----------------------------------------------------------


def _with_surface(mesh: pp.Mesh, rng, material) -> pp.Mesh:
    """The mesh again with random uv, random vertex colours and ``material``."""
    offsets, indices = mesh.face_offsets, mesh.face_indices
    faces = [indices[a:b].tolist() for a, b in itertools.pairwise(offsets)]
    count = len(mesh.vertices)
    return pp.Mesh(mesh.vertices, faces, material, colors=rng.uniform(0.3, 1.0, (count, 3)),
                   uv=rng.uniform(-1.5, 2.5, (count, 2)))


def textured_scene(seed: int) -> pp.Scene:
    rng = np.random.default_rng(seed)
    checker = np.kron((np.indices((8, 8)).sum(axis=0) % 2)[..., None], np.ones(3))
    picture = rng.integers(0, 256, (16, 16, 3), dtype=np.uint8)
    grid = np.linspace(-3, 3, 4)
    gx, gz = np.meshgrid(grid, grid)
    ground_vertices = np.stack([gx.ravel(), np.zeros(16), gz.ravel()], axis=1)
    ground_faces = [[r * 4 + c, r * 4 + c + 4, r * 4 + c + 5, r * 4 + c + 1]
                    for r in range(3) for c in range(3)]
    ground = pp.Mesh(ground_vertices, ground_faces,
                     pp.Material(color=(0.9, 0.8, 0.7), texture=checker, ks=0.2),
                     uv=ground_vertices[:, [0, 2]] / 1.5)
    block = pp.Box((-1.6, 0.0, -0.8), (-0.4, 1.1, 0.4)).to_mesh()
    block = _with_surface(block, rng, pp.Material(texture=picture, texture_filter="bilinear",
                                                  texture_wrap="mirror", ks=0.5))
    ring = torus(0.7, 0.25, 20, 10).transformed(
        pp.scene.transform_matrix(translate=(0.9, 0.6, 0.2), rotate=(60, 20, 0))
    )
    ring = _with_surface(ring, rng, pp.Material(color=(0.7, 0.9, 1.0), texture=picture,
                                                texture_filter="nearest", texture_wrap="clamp"))
    painted = pp.scene.icosphere(1, 0.45, (0.0, 0.5, 1.3))
    painted = pp.Mesh(painted.vertices, painted.triangles, pp.Material(ks=0.6),
                      colors=rng.uniform(0, 1, (len(painted.vertices), 3)))
    camera = pp.Camera(eye=(0.0, 2.4, 5.0), target=(0.0, 0.4, 0.0), fov=45, width=72, height=56)
    lights = [pp.PointLight((3, 5, 4)), pp.DirectionalLight((-1, -1, -0.5), intensity=0.4)]
    return pp.Scene(camera, objects=[ground, block, ring, painted], lights=lights)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
@pytest.mark.parametrize("method", RASTER[1:])
def test_methods_agree_with_the_zbuffer_on_textured_scenes(method, shading):
    check_agreement(textured_scene(1), method, shading)


@pytest.mark.parametrize("method", ["zbuffer", "scanline", "warnock", "raytrace"])
def test_a_region_of_a_textured_scene_equals_that_part_of_the_whole(method):
    # Texture lookups depend on the pixel's place in the whole image (its footprint too),
    # never on the region rendered: tiles stitch without seams.
    scene = textured_scene(2)
    whole = pp.render(scene, method)
    part = pp.render(scene, method, region=(13, 7, 61, 45))
    np.testing.assert_array_equal(np.asarray(part), np.asarray(whole)[7:45, 13:61])
    np.testing.assert_array_equal(part.normal, whole.normal[7:45, 13:61])


def test_textures_change_the_picture():
    # A guard for the agreement test: the scene's surfaces really are textured and painted.
    scene = textured_scene(1)
    plain = pp.Scene(scene.camera, objects=[
        pp.Mesh(o.vertices, o.triangles, pp.Material(color=o.material.color, ks=o.material.ks))
        for o in scene.objects
    ], lights=scene.lights)
    textured, untextured = pp.render(scene), pp.render(plain)
    assert np.array_equal(textured.object_id, untextured.object_id)
    for k in range(4):
        seen = textured.object_id == k
        assert seen.sum() > 30
        gap = np.abs(np.asarray(textured) - np.asarray(untextured))[seen].max()
        assert gap > 0.1, f"object {k} looks untextured"


# --- perspective-correct texture coordinates -------------------------------------------------

FLOOR_SIZE = (64, 48)
FLOOR_EYE = np.array([0.0, 0.5, 2.0])
FLOOR_TARGET = np.array([0.0, 0.0, -4.0])
FLOOR_FOV = 50.0
# The floor y = 0, x in [-2, 2], z in [-14, 1]; u runs with x, v with -z.
FLOOR = np.array([[-2, 0, 1], [2, 0, 1], [2, 0, -14], [-2, 0, -14]], dtype=float)
FLOOR_UV = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
TEXELS = 32


def coded_texture() -> np.ndarray:
    """Red encodes the row and green the column (8-bit codes 8 apart): nearest-filter IDs."""
    codes = np.arange(TEXELS) * 8
    picture = np.zeros((TEXELS, TEXELS, 3), dtype=np.uint8)
    picture[..., 0] = codes[:, None]
    picture[..., 1] = codes[None, :]
    return picture


def camera_frame():
    w = (FLOOR_EYE - FLOOR_TARGET) / np.linalg.norm(FLOOR_EYE - FLOOR_TARGET)
    u = np.cross([0.0, 1.0, 0.0], w)
    u /= np.linalg.norm(u)
    return u, np.cross(w, u), w


def pixel_rays():
    """(H, W, 3) direction of the ray through each pixel centre (independent of the renderer)."""
    width, height = FLOOR_SIZE
    u, v, w = camera_frame()
    half = math.tan(math.radians(FLOOR_FOV) / 2)
    cols, rows = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    x = (2 * cols / width - 1) * half * width / height
    y = (1 - 2 * rows / height) * half
    return x[..., None] * u + y[..., None] * v - w


def true_uv():
    """u, v where each pixel's ray meets the floor plane (NaN off the floor)."""
    rays = pixel_rays()
    t = -FLOOR_EYE[1] / rays[..., 1]
    hit = FLOOR_EYE + t[..., None] * rays
    on = (t > 0) & (np.abs(hit[..., 0]) <= 2) & (hit[..., 2] <= 1) & (hit[..., 2] >= -14)
    uu = (hit[..., 0] + 2) / 4
    vv = (1 - hit[..., 2]) / 15
    return np.where(on, uu, np.nan), np.where(on, vv, np.nan)


def affine_uv():
    """u, v interpolated linearly in screen space over the floor's two triangles (the bug)."""
    u_axis, v_axis, w_axis = camera_frame()
    width, height = FLOOR_SIZE
    half = math.tan(math.radians(FLOOR_FOV) / 2)
    rel = FLOOR - FLOOR_EYE
    depth = -(rel @ w_axis)
    sx = ((rel @ u_axis) / depth / (half * width / height) + 1) * width / 2
    sy = (1 - (rel @ v_axis) / depth / half) * height / 2
    screen = np.stack([sx, sy], axis=1)
    cols, rows = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    points = np.stack([cols, rows], axis=-1)
    out = np.full((height, width, 2), np.nan)
    for tri in ([0, 1, 2], [0, 2, 3]):
        a, b, c = screen[tri]
        m = np.array([b - a, c - a]).T
        wb, wc = np.moveaxis(np.linalg.solve(m, (points - a).reshape(-1, 2).T), 0, -1).reshape(
            height, width, 2).transpose(2, 0, 1)
        wa = 1 - wb - wc
        inside = (wa >= 0) & (wb >= 0) & (wc >= 0)
        uv = (wa[..., None] * FLOOR_UV[tri[0]] + wb[..., None] * FLOOR_UV[tri[1]]
              + wc[..., None] * FLOOR_UV[tri[2]])
        out[inside] = uv[inside]
    return out[..., 0], out[..., 1]


def texel_of(rgb: np.ndarray):
    """(col, row) of the texel whose decoded colour each pixel shows."""
    levels = srgb_to_linear(np.arange(TEXELS) * 8 / 255.0)
    row = np.abs(rgb[..., 0, None] - levels).argmin(axis=-1)
    col = np.abs(rgb[..., 1, None] - levels).argmin(axis=-1)
    return col, row


def texel_at(uu, vv):
    return np.floor(uu * TEXELS), np.floor((1 - vv) * TEXELS)


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_texture_coordinates_are_perspective_correct(method):
    material = unlit(texture=coded_texture(), texture_filter="nearest", texture_wrap="clamp")
    floor = pp.Mesh(FLOOR, [[0, 1, 2, 3]], material, uv=FLOOR_UV)
    camera = pp.Camera(eye=FLOOR_EYE, target=FLOOR_TARGET, fov=FLOOR_FOV, width=FLOOR_SIZE[0],
                       height=FLOOR_SIZE[1])
    image = pp.render(pp.Scene(camera, objects=[floor], ambient=1.0), method, "phong")
    uu, vv = true_uv()
    seen = (image.object_id == 0) & np.isfinite(uu)
    assert seen.sum() > 0.4 * seen.size
    col, row = texel_of(np.asarray(image, dtype=np.float64))
    true_col, true_row = texel_at(uu, vv)
    # Pixels whose ray lands on a texel border may read the neighbour; none reads further.
    for got, want in ((col, true_col), (row, true_row)):
        gap = np.abs(got - want)[seen]
        assert gap.max() <= 1, f"{method}: a pixel reads a texel {gap.max():g} away"
        assert (gap == 0).mean() >= 0.97
    # The same check fails for affinely interpolated coordinates: it would catch the bug.
    au, av = affine_uv()
    _, affine_row = texel_at(au, av)
    both = seen & np.isfinite(au)
    assert np.abs(affine_row - true_row)[both].max() >= 6
    assert np.abs(affine_row - row)[both].max() >= 6


# --- colour and light ------------------------------------------------------------------------


@pytest.mark.parametrize(("method", "shading"), [
    *((m, s) for m in ("zbuffer", "painter") for s in ("flat", "gouraud", "phong")),
    ("raytrace", "flat"), ("raytrace", "phong"),
])
def test_textured_lit_colour_by_hand(method, shading):
    codes = np.array([[[200, 100, 50], [30, 220, 140]], [[255, 255, 0], [90, 60, 250]]],
                     np.uint8)
    colour = np.array([0.9, 0.6, 0.8])
    ka, kd, ambient, intensity = 0.3, 0.6, 0.5, 0.9
    material = pp.Material(color=colour, ka=ka, kd=kd, ks=0.0, texture=codes,
                           texture_filter="nearest")
    quad = pp.Mesh(SQUARE, [[0, 1, 2, 3]], material, uv=SQUARE_UV)
    to_light = np.array([0.0, 0.6, 0.8])  # cos(theta) = 0.8 against the normal (0, 0, 1)
    light = pp.DirectionalLight(direction=-to_light, intensity=intensity)
    scene = facing_scene([quad], ambient=ambient, lights=[light])
    rgb = np.asarray(pp.render(scene, method, shading), dtype=np.float64)
    light_term = ka * ambient + kd * intensity * 0.8
    texture = srgb_to_linear(codes / 255.0)
    for (row, col), (tr, tc) in {(8, 8): (0, 0), (8, 23): (0, 1), (23, 8): (1, 0),
                                 (23, 23): (1, 1)}.items():
        expected = np.clip(texture[tr, tc] * colour * light_term, 0, 1)
        assert rgb[row, col] == pytest.approx(expected, abs=1e-5)


@pytest.mark.parametrize(("method", "shading"), [
    ("zbuffer", "flat"), ("zbuffer", "gouraud"), ("zbuffer", "phong"), ("scanline", "gouraud"),
    ("raytrace", "phong"), ("raytrace", "flat"),
])
def test_uniform_vertex_colour_is_a_material_colour(method, shading):
    tint = np.array([0.8, 0.5, 0.3])
    colour = np.array([0.9, 0.7, 1.0])
    sphere = pp.scene.icosphere(2, 1.0, (0, 0, 0))
    faces = sphere.triangles
    painted = pp.Mesh(sphere.vertices, faces, pp.Material(color=colour, ks=0.5, shininess=8),
                      colors=np.tile(tint, (len(sphere.vertices), 1)))
    plain = pp.Mesh(sphere.vertices, faces, pp.Material(color=colour * tint, ks=0.5, shininess=8))
    lights = [pp.PointLight((2, 3, 4)), pp.DirectionalLight((1, -1, -1), intensity=0.3)]
    a = pp.render(facing_scene([painted], ambient=0.2, lights=lights, eye=(0, 0, 4)), method,
                  shading)
    b = pp.render(facing_scene([plain], ambient=0.2, lights=lights, eye=(0, 0, 4)), method,
                  shading)
    assert np.array_equal(a.object_id, b.object_id)
    assert np.allclose(np.asarray(a), np.asarray(b), atol=1e-6)
    assert np.asarray(a).max() > 0.75  # the highlight is in the picture


@pytest.mark.parametrize(("method", "shading"), [
    ("zbuffer", "flat"), ("zbuffer", "gouraud"), ("zbuffer", "phong"), ("warnock", "gouraud"),
    ("raytrace", "phong"), ("raytrace", "flat"),
])
def test_highlight_is_not_tinted_by_the_texture(method, shading):
    red = np.zeros((2, 2, 3), np.uint8)
    red[..., 0] = 255

    def render(ks):
        material = pp.Material(ka=0.1, kd=0.4, ks=ks, shininess=4, texture=red)
        # A finely divided quad, so Gouraud's vertices catch the highlight too.
        n = 8
        xs = np.linspace(-1, 1, n + 1)
        gx, gy = np.meshgrid(xs, xs)
        vertices = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
        faces = [[r * (n + 1) + c, r * (n + 1) + c + 1, (r + 1) * (n + 1) + c + 1,
                  (r + 1) * (n + 1) + c] for r in range(n) for c in range(n)]
        grid = pp.Mesh(vertices, faces, material, uv=(vertices[:, :2] + 1) / 2)
        scene = facing_scene([grid], ambient=0.1, lights=[pp.PointLight((0.1, 0.1, 2.5))])
        return np.asarray(pp.render(scene, method, shading), dtype=np.float64)

    shiny, matte = render(0.5), render(0.0)
    assert matte[..., 1:].max() == 0.0  # red texture: no green or blue without a highlight
    gain = shiny - matte
    assert gain[..., 1].max() > 0.1, "no highlight"
    # The highlight is white: it adds the same to green and blue, and to red where red does
    # not reach 1.
    assert np.allclose(gain[..., 1], gain[..., 2], atol=1e-6)
    unclipped = shiny[..., 0] < 1.0 - 1e-6
    assert np.allclose(gain[..., 0][unclipped], gain[..., 1][unclipped], atol=1e-5)


# --- mip-mapping ------------------------------------------------------------------------------


@pytest.mark.parametrize("method", ["zbuffer", "raytrace"])
def test_mipmapping_averages_a_far_checkerboard(method):
    board = np.kron(np.indices((64, 64)).sum(axis=0) % 2, 255).astype(np.uint8)
    board = np.repeat(board[..., None], 3, axis=2)  # one-texel squares: average linear 0.5

    def render(texture_filter):
        quad = pp.Mesh(SQUARE, [[0, 1, 2, 3]], unlit(texture=board, texture_filter=texture_filter),
                       uv=np.array(SQUARE_UV) * 8)  # 512 texels across the quad
        scene = facing_scene([quad], size=32, eye=(0, 0, 12))  # ~5 pixels across: ~100 texels
        image = pp.render(scene, method, "phong")
        return np.asarray(image, dtype=np.float64)[image.object_id == 0]

    smooth, aliased = render("trilinear"), render("nearest")
    assert len(smooth) >= 9 and len(aliased) == len(smooth)
    assert np.allclose(smooth, 0.5, atol=0.01)  # 0.5 is stored as sRGB code 188 (0.503)
    assert set(np.unique(aliased)) <= {0.0, 1.0}


# --- double-sided materials ------------------------------------------------------------------


@pytest.mark.parametrize("method", EVERY_METHOD)
def test_double_sided_quad_seen_from_behind(method):
    def render(double_sided):
        material = pp.Material(color=(1, 0.5, 0.2), double_sided=double_sided)
        quad = pp.Mesh(SQUARE, [[0, 1, 2, 3]], material)
        # A plane under it whose normal points away from the eye too.
        plane = pp.Plane((0, -1.2, 0), (0, -1, 0), material)
        # (An eye off the plane's tessellation grid: a grid point in the eye's plane maps to
        # infinity, which the no-JIT pass reports as a division warning.)
        scene = facing_scene([quad, plane], eye=(0.1, 0.2, -3.1),
                             lights=[pp.PointLight((1, 1, -4))])
        return pp.render(scene, method, "phong")

    two_sided = render(True)
    middle = (16, 16)
    assert two_sided.object_id[middle] == 0
    assert two_sided.normal[middle] == pytest.approx([0, 0, -1], abs=1e-6)  # towards the eye
    # Lit from behind as from the front: diffuse light, not the ambient term alone.
    assert np.asarray(two_sided)[middle][0] > 0.1 + 0.2
    floor = two_sided.object_id == 1
    assert floor.sum() > 20
    assert np.allclose(two_sided.normal[floor], [0, 1, 0], atol=1e-6)
    one_sided = render(False)
    assert np.all(one_sided.object_id == -1)
