"""pixelpath.render: the public contract (methods, shading, ssaa, errors, edge cases)."""

from __future__ import annotations

import numpy as np
import pytest

import pixelpath as pp


def small_scene(objects=None, size=(32, 24), background=(0.2, 0.3, 0.4)):
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=size[0], height=size[1])
    if objects is None:
        objects = [pp.Sphere((0, 0, 0), 1.0)]
    return pp.Scene(camera, objects=objects, lights=[pp.PointLight((3, 3, 3))],
                    background=background)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_render_returns_an_image_with_its_buffers(shading):
    img = pp.render(small_scene(), shading=shading)
    assert isinstance(img, pp.Image)
    assert np.asarray(img).shape == (24, 32, 3) and np.asarray(img).dtype == np.float32
    assert img.depth.shape == (24, 32) and img.object_id.dtype == np.int32
    array = np.asarray(img)
    assert 0.0 <= array.min() and array.max() <= 1.0
    drawn = img.object_id == 0
    assert drawn[12, 16] and not drawn[0, 0]
    assert np.all(np.isinf(img.depth[~drawn])) and np.all(img.depth[drawn] >= 3.0 - 1e-3)
    assert np.allclose(array[~drawn], [0.2, 0.3, 0.4])


def test_empty_scene_is_the_background():
    img = pp.render(small_scene(objects=[]))
    assert np.allclose(np.asarray(img), [0.2, 0.3, 0.4])
    assert np.all(img.object_id == -1) and np.all(np.isinf(img.depth))


def test_scene_without_lights_is_ambient_only():
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=16, height=16)
    material = pp.Material(color=(1.0, 0.5, 0.0), ka=0.5)
    scene = pp.Scene(camera, objects=[pp.Sphere((0, 0, 0), 1.0, material)], ambient=0.4)
    img = pp.render(scene)
    assert np.allclose(np.asarray(img)[8, 8], [0.2, 0.1, 0.0])


def test_object_behind_the_camera_is_not_drawn():
    camera = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=16, height=16)
    scene = pp.Scene(camera, objects=[pp.Sphere((0, 0, 8), 1.0)])
    assert np.all(pp.render(scene).object_id == -1)


def test_supersampling_averages_samples():
    # A box edge cuts pixels: ssaa=4 gives intermediate values there, while inside the face
    # pixels keep the flat-shaded value of ssaa=1.
    box = pp.Box((-1, -1, -1), (1, 1, 1))
    scene = small_scene(objects=[box], background=(0, 0, 0))
    plain = pp.render(scene, shading="flat")
    smooth = pp.render(scene, shading="flat", ssaa=4)
    assert np.allclose(np.asarray(smooth)[12, 16], np.asarray(plain)[12, 16], atol=1e-6)
    edge = np.asarray(smooth)[..., 0]
    assert np.any((edge > 0.01) & (edge < np.asarray(plain)[..., 0].max() - 0.01))
    assert np.array_equal(smooth.object_id >= 0, np.isfinite(smooth.depth))


def test_blinn_changes_only_highlights():
    phong = np.asarray(pp.render(small_scene()))
    blinn = np.asarray(pp.render(small_scene(), blinn=True))
    assert not np.array_equal(phong, blinn)
    assert np.allclose(phong[0, 0], blinn[0, 0])


@pytest.mark.parametrize("method", ["painter", "bsp"])
def test_methods_of_later_versions_say_so(method):
    with pytest.raises(NotImplementedError, match=method):
        pp.render(small_scene(), method=method)


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"method": "zbufer"}, ValueError, "method"),
        ({"shading": "toon"}, ValueError, "shading"),
        ({"ssaa": 0}, ValueError, "ssaa"),
        ({"ssaa": 1.5}, TypeError, "ssaa"),
    ],
)
def test_bad_arguments(kwargs, error, match):
    with pytest.raises(error, match=match):
        pp.render(small_scene(), **kwargs)


def test_nan_vertices_never_reach_the_rasterizer():
    with pytest.raises(ValueError, match="finite"):
        pp.Mesh([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])


def test_scene_must_be_a_scene():
    with pytest.raises(TypeError, match="Scene"):
        pp.render({"camera": None})


def test_huge_frames_are_refused_before_any_work():
    big = pp.Camera(eye=(0, 0, 4), target=(0, 0, 0), width=16384, height=16384)
    with pytest.raises(ValueError, match="samples"):
        pp.render(pp.Scene(big))
    with pytest.raises(ValueError, match="ssaa"):
        pp.render(small_scene(size=(4000, 3000)), ssaa=4)


def test_progress_is_reported():
    from pixelpath.renderer import render_steps

    steps = []
    pp.render(small_scene(), progress=steps.append)
    assert sum(steps) == render_steps("zbuffer") == 11


def test_large_frames_render_in_slices_with_the_same_result(monkeypatch):
    import importlib

    pipeline = importlib.import_module("pixelpath.hsr.pipeline")
    zbuffer = importlib.import_module("pixelpath.hsr.zbuffer")
    scene = small_scene(objects=[pp.Sphere((0, 0, 0), 1.0), pp.Box((0, 0, 0), (1, 1, 1))],
                        size=(40, 70))
    whole = pp.render(scene)
    monkeypatch.setattr(pipeline, "SLICED_PIXELS", 0)
    steps = []
    sliced = pp.render(scene, progress=steps.append)
    assert len(steps) == pipeline.FRONT_STEPS + pipeline.SHADE_SLICES
    assert sum(steps) == zbuffer.STEPS
    assert np.array_equal(np.asarray(sliced), np.asarray(whole))
    assert np.array_equal(sliced.object_id, whole.object_id)


def test_stats_count_the_pipeline():
    # The eye (0, 0, 4) is in front of the box's z = 1 face only: the other five faces turn
    # away from it (N.V > 0), so 10 of the 12 triangles are culled and 2 are drawn.
    box = pp.Box((-1, -1, -1), (1, 1, 1))
    stats = pp.render(small_scene(objects=[box])).stats
    assert stats["triangles"] == 12
    assert stats["back faces culled"] == 10
    assert stats["triangles scan-converted"] == 2
    both = pp.render(small_scene(objects=[box]), backface_cull=False).stats
    assert both["back faces culled"] == 0 and both["triangles scan-converted"] == 12
    assert pp.Image(np.zeros((1, 1, 3))).stats == {}


def test_renders_from_several_threads_at_once_agree():
    from concurrent.futures import ThreadPoolExecutor

    scenes = [small_scene(objects=[pp.Sphere((0, 0, 0), 0.5 + 0.1 * k)]) for k in range(6)]
    alone = [np.asarray(pp.render(scene)).copy() for scene in scenes]
    with ThreadPoolExecutor(max_workers=3) as pool:
        together = list(pool.map(lambda scene: np.asarray(pp.render(scene)), scenes * 2))
    for k, image in enumerate(together):
        assert np.array_equal(image, alone[k % len(scenes)])
