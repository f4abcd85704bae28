"""render_frames in this process: same bytes as render(), tiles, resume, and errors up front."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from frame_scenes import animated_scene
from hypothesis import given
from hypothesis import strategies as st

import pixelpath as pp
from pixelpath.frames import frame_is_complete, plan_frames, render_frame
from pixelpath.renderer import METHOD_NAMES

METHODS = list(METHOD_NAMES)


def test_frames_equal_render_of_each_frame():
    scene = animated_scene()
    images = pp.render_frames(scene, range(6), shading="gouraud")
    for frame, image in enumerate(images):
        expected = pp.render(scene.at_frame(frame), shading="gouraud")
        assert np.array_equal(np.asarray(image), np.asarray(expected))
        assert np.array_equal(image.object_id, expected.object_id)
    assert not np.array_equal(np.asarray(images[0]), np.asarray(images[5]))  # it moves


def test_files_are_the_bytes_image_save_writes(tmp_path):
    scene = animated_scene()
    out = tmp_path / "out" / "f_{frame:02d}.png"
    paths = pp.render_frames(scene, [0, 3], out=out, png_level=None)  # Pillow's
    assert [path.name for path in paths] == ["f_00.png", "f_03.png"]
    for frame, path in zip([0, 3], paths, strict=True):
        pp.render(scene.at_frame(frame)).save(tmp_path / "expected.png")
        assert path.read_bytes() == (tmp_path / "expected.png").read_bytes()
    assert not list((tmp_path / "out").glob("*.tmp"))  # atomic writes leave no temporaries


# BSP's case runs in the main pass only: its build in plain Python took 5 s of the pass
# without the JIT, and BSP's tiles are checked there by tests/hsr's region tests.
@pytest.mark.parametrize(
    "method", [pytest.param(m, marks=pytest.mark.slow) if m == "bsp" else m for m in METHODS]
)
def test_tiles_stitch_to_the_untiled_frame(method, tmp_path):
    scene = animated_scene(width=37, height=23)
    whole = pp.render(scene.at_frame(4), method, ssaa=2)
    tiled = pp.render_frames(scene, [4], method=method, ssaa=2, tiles=(3, 4))[0]
    assert np.array_equal(np.asarray(tiled), np.asarray(whole))
    assert np.array_equal(tiled.depth, whole.depth)
    assert np.array_equal(tiled.object_id, whole.object_id)
    path = pp.render_frames(
        scene, [4], out=tmp_path / "t.png", method=method, ssaa=2, tiles=(3, 4), png_level=None
    )[0]
    whole.save(tmp_path / "w.png")
    assert path.read_bytes() == (tmp_path / "w.png").read_bytes()


def test_interrupted_run_resumes_with_the_missing_frames_only(tmp_path):
    scene = animated_scene()
    pattern = str(tmp_path / "f_{frame}.png")
    done = []

    def interrupt(steps):
        done.append(steps)
        if len(done) == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        pp.render_frames(scene, range(6), out=pattern, progress=interrupt)
    first = {path.name: path.stat().st_ino for path in tmp_path.glob("f_*.png")}
    assert sorted(first) == ["f_0.png", "f_1.png"]
    rendered = []
    pp.render_frames(scene, range(6), out=pattern, resume=True, progress=rendered.append)
    assert len(rendered) == 4
    for name, inode in first.items():  # the complete frames were not written again
        assert (tmp_path / name).stat().st_ino == inode
    reference = pp.render_frames(scene, range(6))
    for frame in range(6):
        assert np.array_equal(
            pp.io.read_image(tmp_path / f"f_{frame}.png"), _as_file(reference[frame], tmp_path)
        )


def test_a_truncated_frame_is_rendered_again(tmp_path):
    scene = animated_scene()
    pattern = str(tmp_path / "f_{frame}.png")
    paths = pp.render_frames(scene, range(3), out=pattern)
    good = paths[1].read_bytes()
    paths[1].write_bytes(good[: len(good) // 2])
    assert not frame_is_complete(paths[1], 32, 24)
    assert frame_is_complete(paths[0], 32, 24)
    assert not frame_is_complete(paths[0], 33, 24)  # a frame of another size is not complete
    rendered = []
    pp.render_frames(scene, range(3), out=pattern, resume=True, progress=rendered.append)
    assert len(rendered) == 1 and paths[1].read_bytes() == good


def test_render_frame_is_a_pure_picklable_function():
    import pickle

    scene = animated_scene()
    function, copy = pickle.loads(pickle.dumps((render_frame, scene)))
    again = function(copy, 2, {"shading": "flat"})
    expected = render_frame(scene, 2, {"shading": "flat"})
    assert np.array_equal(np.asarray(again), np.asarray(expected))


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"frames": range(5, 7)}, ValueError, r"frame 6 is outside the animation \(frames 0..5\)"),
        ({"frames": [1, 1]}, ValueError, "frame 1 is listed twice"),
        ({"frames": 3}, TypeError, r"range\(120\)"),
        ({"frames": []}, ValueError, "empty"),
        ({"out": "f.png"}, ValueError, r"put \{frame\} in it"),
        ({"out": "f_{n}.png"}, ValueError, r"only \{frame\} may be used"),
        ({"out": "f_{frame}.xyz"}, ValueError, "unknown image extension"),
        ({"tiles": (33, 1)}, ValueError, "at least one pixel wide"),
        ({"tiles": (1, 0)}, ValueError, "at least one pixel high"),
        ({"resume": True}, ValueError, "needs out="),
        ({"method": "zbufer"}, ValueError, "method must be one of"),
        ({"explain": True}, TypeError, "unknown render option"),
        ({"gamma": -1}, ValueError, "gamma"),
    ],
)
def test_bad_requests_fail_before_any_work(kwargs, error, match, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    options = {"frames": range(3), **kwargs}
    with pytest.raises(error, match=match):
        pp.render_frames(animated_scene(), **options)
    assert not list(tmp_path.iterdir())


def test_a_frame_too_large_for_one_render_asks_for_tiles():
    scene = animated_scene(frames=2, width=16384, height=8192)
    with pytest.raises(ValueError, match="split the frame into more tiles"):
        plan_frames(scene, [0])  # 16384 x 8192 = 2^27 samples, twice the limit
    plan = plan_frames(scene, [0], tiles=(2, 1))
    assert plan.regions == ((0, 0, 8192, 8192), (8192, 0, 16384, 8192))


def test_a_camera_the_animation_breaks_between_keys_is_found_before_work():
    from pixelpath.scene import Animation, CameraKey

    scene = animated_scene()  # the camera looks at (0, 0.5, 0)
    through_target = Animation(
        9, camera=[CameraKey(4, eye=(0, 0.5, 2)), CameraKey(8, eye=(0, 0.5, -2))]
    )
    moving = pp.Scene(scene.camera, scene.objects, animation=through_target)  # keys are valid
    assert plan_frames(moving, range(6)).todo == tuple(range(6))
    with pytest.raises(ValueError, match=r"frames: .*must differ|frames: .*eye"):
        plan_frames(moving, range(9))  # at frame 6 the eye reaches the target


def test_rendering_one_image_does_not_import_dask():
    code = (
        "import sys, pixelpath as pp\n"
        "s = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6),"
        " [pp.Sphere((0, 0, 0), 1.0)])\n"
        "pp.render(s)\n"
        "pp.render_frames(s, [0, 1])\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] in ('dask', 'distributed')))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == "[]"


def _as_file(image, folder):
    image.save(folder / "reference.png")
    return pp.io.read_image(folder / "reference.png")


@given(
    count=st.integers(0, 500),
    workers=st.integers(1, 64),
    most=st.integers(1, 64),
    least=st.integers(1, 64),
)
def test_cluster_batches_keep_every_task_once_in_order(count, workers, most, least):
    from pixelpath.frames.run import _batches

    least = min(least, most)
    tasks = list(range(count))
    batches = _batches(tasks, workers, most, least)
    sizes = [len(batch) for batch in batches]
    assert [task for batch in batches for task in batch] == tasks
    assert all(least <= size <= most for size in sizes[:-1])  # the last takes what is left
    assert all(1 <= size <= most for size in sizes[-1:])
    assert sizes == sorted(sizes, reverse=True)  # large first, the short ones even out the end
    assert not sizes or least > 1 or sizes[-1] == 1
