"""Frames' files written on writer threads: overlap with rendering, errors, PNG levels."""

from __future__ import annotations

import threading

import numpy as np
import pytest
from frame_scenes import animated_scene

import pixelpath as pp
from pixelpath.frames import work
from pixelpath.frames.writer import FrameWriter


def _bytes_at(image, level):
    return work.encode(image, ".png", None, png_level=level)


@pytest.mark.parametrize("level", [0, 1, 6, 9])
def test_files_are_the_encoded_frames_at_the_chosen_level(level, tmp_path):
    scene = animated_scene()
    paths = pp.render_frames(scene, range(4), out=tmp_path / "f_{frame}.png", png_level=level)
    for frame, path in enumerate(paths):
        image = pp.render(scene.at_frame(frame))
        assert path.read_bytes() == _bytes_at(image, level)
        assert np.array_equal(pp.io.read_image(path), image.to_uint8() / np.float32(255))
    assert not list(tmp_path.glob("*.tmp"))


def test_the_default_level_is_the_fast_one(tmp_path):
    scene = animated_scene()
    (path,) = pp.render_frames(scene, [2], out=tmp_path / "f_{frame}.png")
    assert path.read_bytes() == _bytes_at(pp.render(scene.at_frame(2)), 1)


@pytest.mark.parametrize("level", [-1, 10, 1.0, True, "6"])
def test_a_bad_level_is_refused_before_any_work(level, tmp_path):
    with pytest.raises(ValueError, match="png_level must be an int from 0 to 9"):
        pp.render_frames(animated_scene(), [0], out=tmp_path / "f_{frame}.png", png_level=level)
    assert not list(tmp_path.iterdir())


def test_the_next_frame_renders_while_the_last_is_encoded(tmp_path, monkeypatch):
    from pixelpath.io import images

    rendered = [threading.Event() for _ in range(4)]
    overlapped = []
    render_frame, encode = work.render_frame, images.encode_image

    def render_and_tell(scene, frame, *args):
        rendered[frame].set()
        return render_frame(scene, frame, *args)

    def encode_after_the_next_render(image, *args, **kwargs):
        frame = len(overlapped)
        overlapped.append(frame == 3 or rendered[frame + 1].wait(timeout=20))
        return encode(image, *args, **kwargs)

    monkeypatch.setattr(work, "render_frame", render_and_tell)
    monkeypatch.setattr(images, "encode_image", encode_after_the_next_render)
    with FrameWriter(1) as writer:  # one writer: frames are encoded in order
        monkeypatch.setattr("pixelpath.frames.run.FrameWriter", lambda: writer)
        pp.render_frames(animated_scene(), range(4), out=tmp_path / "f_{frame}.png")
    assert overlapped == [True] * 4


def test_an_error_in_a_writer_reaches_the_caller(tmp_path, monkeypatch):
    from pixelpath.io import images

    encode = images.encode_image
    calls = []

    def fail_on_the_second(image, *args, **kwargs):
        calls.append(1)
        if len(calls) == 2:
            raise OSError("disk full")
        return encode(image, *args, **kwargs)

    monkeypatch.setattr(images, "encode_image", fail_on_the_second)
    with pytest.raises(OSError, match="disk full"):
        pp.render_frames(animated_scene(), range(6), out=tmp_path / "f_{frame}.png")
    assert not list(tmp_path.glob(".*.tmp"))


def test_a_failed_write_is_raised_by_close_when_it_was_the_last(tmp_path):
    def broken():
        raise RuntimeError("no bytes")

    writer = FrameWriter(2)
    writer.submit(tmp_path / "a.png", lambda: b"a")
    writer.submit(tmp_path / "b.png", broken)
    with pytest.raises(RuntimeError, match="no bytes"):
        writer.close()
    assert (tmp_path / "a.png").read_bytes() == b"a" and not (tmp_path / "b.png").exists()


def test_a_writer_keeps_a_few_frames_waiting_at_most(tmp_path):
    release = threading.Event()
    started = []

    def slow(n):
        started.append(n)
        release.wait(timeout=20)
        return b"x"

    writer = FrameWriter(1)
    for n in range(2):
        writer.submit(tmp_path / f"{n}", lambda n=n: slow(n))
    blocked = threading.Thread(target=writer.submit, args=(tmp_path / "2", lambda: slow(2)))
    blocked.start()
    blocked.join(timeout=0.5)
    assert blocked.is_alive()  # two frames in hand: the third waits for the first to finish
    release.set()
    blocked.join(timeout=20)
    writer.close()
    assert sorted(path.name for path in tmp_path.iterdir()) == ["0", "1", "2"]
