"""Image.alpha, Image.normal, foreground(), save(alpha=True) and the output encodings."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image as PILImage

import pixelpath as pp
from camera_rays import view_rays
from pixelpath.scene.texture import linear_to_srgb

METHODS = ["zbuffer", "scanline", "painter", "bsp", "warnock", "octree", "raytrace"]
BACKGROUND = (0.2, 0.3, 0.4)


def scene_of(objects, size=(40, 32), eye=(0.0, 0.0, 4.0), **kwargs):
    camera = pp.Camera(eye=eye, target=(0, 0, 0), fov=45, width=size[0], height=size[1])
    kwargs.setdefault("lights", [pp.PointLight((3, 3, 4))])
    kwargs.setdefault("background", BACKGROUND)
    return pp.Scene(camera, objects=objects, **kwargs)


def tilted_square(material=None) -> pp.Mesh:
    """A camera-facing square turned 20 degrees about the view axis: edges cut pixels."""
    square = pp.Mesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2, 3]],
                     material or pp.Material())
    return square.transformed(pp.scene.transform_matrix(rotate=(0, 0, 20)))


# --- alpha ---------------------------------------------------------------------------------


# Without the JIT the BSP method builds its tree over the sphere's 5,120 triangles in plain
# Python (about 40 s): that case runs in the main pass only.
@pytest.mark.parametrize(
    "method", [pytest.param(m, marks=pytest.mark.slow) if m == "bsp" else m for m in METHODS]
)
def test_alpha_is_coverage(method):
    scene = scene_of([pp.Sphere((0.3, 0, 0), 1.0), tilted_square()], eye=(0, 0.5, 4))
    image = pp.render(scene, method)
    assert image.alpha.dtype == np.float32 and image.alpha.shape == (32, 40)
    assert np.array_equal(image.alpha, (image.object_id >= 0).astype(np.float32))
    assert 0 < image.alpha.mean() < 1


@pytest.mark.parametrize("method", ["zbuffer", "warnock", "raytrace"])
def test_alpha_is_fractional_on_edges_with_ssaa(method):
    colour = np.array([0.9, 0.6, 0.1])
    material = pp.Material(color=colour, ka=1.0, kd=0.0, ks=0.0)  # every sample: the colour
    scene = scene_of([tilted_square(material)], ambient=1.0)
    image = pp.render(scene, method, "flat", ssaa=2)
    alpha = image.alpha
    assert set(np.unique(alpha).tolist()) == {0.0, 0.25, 0.5, 0.75, 1.0}
    edge = (alpha > 0) & (alpha < 1)
    assert edge.sum() >= 20
    # The colour of a partly covered pixel is the average of its samples.
    rgb = np.asarray(image, dtype=np.float64)
    expected = alpha[..., None] * colour + (1 - alpha[..., None]) * np.array(BACKGROUND)
    assert np.allclose(rgb, expected, atol=1e-6)
    # foreground() takes the background out again: the surface's colour wherever it shows.
    surface = image.foreground()
    assert np.allclose(surface[alpha > 0], colour, atol=1e-5)
    assert np.all(surface[alpha == 0] == 0)
    # Supersampled pixels fully inside or outside agree with ssaa=1.
    plain = pp.render(scene, method, "flat")
    assert np.array_equal(plain.object_id >= 0, plain.alpha == 1)
    assert np.all(plain.alpha[alpha == 1] == 1) and np.all(plain.alpha[alpha == 0] == 0)


# --- normals -------------------------------------------------------------------------------


@pytest.mark.parametrize(("method", "tolerance"), [("zbuffer", 0.03), ("scanline", 0.03),
                                                   ("raytrace", 1e-4)])
def test_sphere_normals_from_depth(method, tolerance):
    centre, radius = np.array([0.2, -0.1, 0.0]), 1.2
    scene = scene_of([pp.Sphere(centre, radius)], eye=(0.5, 1.0, 4.0))
    image = pp.render(scene, method, "phong")
    drawn = image.object_id == 0
    assert drawn.sum() > 200
    normal = image.normal.astype(np.float64)
    assert image.normal.dtype == np.float32 and image.normal.shape == (32, 40, 3)
    assert np.all(normal[~drawn] == 0)
    assert np.allclose(np.linalg.norm(normal[drawn], axis=1), 1, atol=1e-5)
    # The hit point from the depth (distance along the view axis), then (P - c) / r.
    eye = np.asarray(scene.camera.eye, float)
    points = eye + view_rays(scene.camera) * image.depth[..., None].astype(np.float64)
    expected = (points - centre) / radius
    # Pixels on the silhouette are left out (the tessellated outline differs from the sphere).
    inside = drawn & (np.einsum("ijk,ijk->ij", expected, eye - points) > 0.3)
    assert inside.sum() > 0.7 * drawn.sum()
    gap = np.linalg.norm(normal[inside] - expected[inside], axis=1)
    assert gap.max() < tolerance * 4 and gap.mean() < tolerance
    # Every normal faces the camera.
    assert np.all(np.einsum("ij,ij->i", normal[drawn], (eye - points)[drawn]) > 0)


@pytest.mark.parametrize("method", METHODS)
def test_flat_shading_gives_polygon_normals(method):
    rotation = pp.scene.transform_matrix(rotate=(25, 35, 10))
    box = pp.Box((-0.8, -0.8, -0.8), (0.8, 0.8, 0.8)).to_mesh().transformed(rotation)
    image = pp.render(scene_of([box], eye=(0.3, 0.4, 4.0)), method, "flat")
    drawn = image.object_id == 0
    faces = rotation[:3, :3] @ np.vstack([np.eye(3), -np.eye(3)]).T  # (3, 6) face normals
    normal = image.normal[drawn].astype(np.float64)
    best = (normal @ faces).max(axis=1)
    assert np.all(best > 1 - 1e-5), "a pixel's normal is not one of the box's face normals"
    assert len(np.unique(np.round(normal, 4), axis=0)) == 3  # three faces in view
    assert np.all(image.normal[~drawn] == 0)


def test_phong_normals_are_interpolated_on_meshes():
    ball = pp.scene.icosphere(1, 1.0, (0, 0, 0))
    smooth = pp.render(scene_of([ball]), "zbuffer", "phong").normal
    flat = pp.render(scene_of([ball]), "zbuffer", "flat").normal
    drawn = np.any(flat != 0, axis=2)
    assert len(np.unique(np.round(smooth[drawn], 4), axis=0)) > 3 * len(
        np.unique(np.round(flat[drawn], 4), axis=0))


# --- saving --------------------------------------------------------------------------------


def read_png(path) -> np.ndarray:
    with PILImage.open(path) as img:
        return np.asarray(img)


def test_save_with_alpha_writes_rgba(tmp_path):
    scene = scene_of([tilted_square(pp.Material(color=(0.9, 0.5, 0.1)))])
    image = pp.render(scene, ssaa=2)
    path = tmp_path / "rgba.png"
    image.save(path, alpha=True)
    pixels = read_png(path)
    assert pixels.shape == (32, 40, 4) and pixels.dtype == np.uint8
    assert np.array_equal(pixels[..., 3], np.rint(image.alpha * 255).astype(np.uint8))
    # Colour channels hold the surface alone: black where nothing was drawn.
    assert np.all(pixels[image.alpha == 0][:, :3] == 0)
    inside = image.alpha == 1
    assert np.array_equal(pixels[inside][:, :3], np.rint(np.asarray(image)[inside] * 255))
    plain = tmp_path / "rgb.png"
    image.save(plain)
    assert read_png(plain).shape == (32, 40, 3)
    with pytest.raises(ValueError, match="alpha"):
        image.save(tmp_path / "no.jpg", alpha=True)


@pytest.mark.parametrize(("gamma", "code"), [
    ("srgb", 188), ("linear", 128), (None, 128), (2.2, 186), (1.0, 128),
])
def test_save_encodings(tmp_path, gamma, code):
    image = pp.Image(np.full((2, 3, 3), 0.5))
    assert image.encoding == "linear"
    path = tmp_path / "half.png"
    image.save(path, gamma=gamma)
    assert np.all(read_png(path) == code)


def test_srgb_encoding_by_default(tmp_path):
    image = pp.Image(np.full((1, 2, 3), 0.5), encoding="srgb")
    image.save(tmp_path / "a.png")
    assert np.all(read_png(tmp_path / "a.png") == 188)
    image.save(tmp_path / "b.png", gamma="linear")
    assert np.all(read_png(tmp_path / "b.png") == 128)
    assert image.to_uint8().tolist() == [[[188, 188, 188]] * 2]
    with pytest.raises(ValueError, match="encoding"):
        pp.Image(np.zeros((1, 1, 3)), encoding="gamma")
    with pytest.raises(ValueError, match="encoding"):
        scene_of([], encoding="rec709")
    rendered = pp.render(scene_of([pp.Sphere((0, 0, 0), 1)], encoding="srgb"))
    assert rendered.encoding == "srgb"
    assert pp.render(scene_of([pp.Sphere((0, 0, 0), 1)])).encoding == "linear"


def test_model_file_scene_saves_srgb(tmp_path):
    model = tmp_path / "tri.obj"
    model.write_text("v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n")
    scene = pp.load_scene(model)
    assert scene.encoding == "srgb"
    small = pp.Scene(scene.camera.with_size(24, 18), objects=scene.objects, lights=scene.lights,
                     ambient=scene.ambient, background=scene.background, encoding=scene.encoding)
    image = pp.render(small)
    assert image.encoding == "srgb"
    image.save(tmp_path / "tri.png")
    expected = np.rint(linear_to_srgb(np.asarray(image, dtype=np.float64)) * 255)
    assert np.array_equal(read_png(tmp_path / "tri.png"), expected)
    assert np.any((expected > 0) & (expected < 255))


def test_image_buffers_are_checked_and_read_only():
    rgb = np.zeros((2, 2, 3))
    with pytest.raises(ValueError, match="alpha"):
        pp.Image(rgb, alpha=np.ones((3, 2)))
    with pytest.raises(ValueError, match="normal"):
        pp.Image(rgb, normal=np.ones((2, 2)))
    image = pp.Image(rgb, object_id=[[0, -1], [-1, 2]])
    assert image.alpha.tolist() == [[1, 0], [0, 1]]
    assert np.all(image.normal == 0)
    assert pp.Image(rgb, alpha=[[2, -1], [0.5, 0]]).alpha.tolist() == [[1, 0], [0.5, 0]]
    for buffer in (image.alpha, image.normal):
        with pytest.raises(ValueError):
            buffer[0, 0] = 1
