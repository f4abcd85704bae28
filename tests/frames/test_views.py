"""Datasets of views: the files, transforms.json, an independent ray caster's agreement, reruns."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from PIL import Image as PILImage

import pixelpath as pp
from pixelpath.cli import main
from pixelpath.frames.views import REQUEST_FILE

DUCK = Path(__file__).parents[1] / "data" / "models" / "Duck.glb"


def _pixels(path: Path) -> np.ndarray:
    with PILImage.open(path) as image:
        return np.asarray(image)


def _files(folder: Path) -> dict[str, bytes]:
    return {
        path.relative_to(folder).as_posix(): path.read_bytes()
        for path in sorted(folder.rglob("*"))
        if path.is_file()
    }


@pytest.fixture(scope="module")
def duck_views(tmp_path_factory):
    folder = tmp_path_factory.mktemp("duck") / "views"
    poses = pp.render_views(
        DUCK, 5, folder, "depth,normal,mask", layout="sphere", size=(96, 72), transparent=True
    )
    return folder, poses, json.loads((folder / "transforms.json").read_text())


def test_transforms_json_has_the_nerf_intrinsics(duck_views):
    folder, poses, document = duck_views
    w, h, fl_x, fl_y = document["w"], document["h"], document["fl_x"], document["fl_y"]
    assert (w, h) == (96, 72) and (document["cx"], document["cy"]) == (48.0, 36.0)
    fov = pp.load_scene(DUCK).camera.fov  # the file's own camera's, by default
    assert fl_x == fl_y == pytest.approx(36.0 / math.tan(math.radians(fov) / 2))
    assert document["camera_angle_x"] == pytest.approx(2 * math.atan(w / (2 * fl_x)))
    assert document["depth_unit_scale_factor"] == 1.0
    assert len(document["frames"]) == 5
    for index, frame in enumerate(document["frames"]):
        assert np.allclose(frame["transform_matrix"], poses[index])
        for key in ("file_path", "depth_file_path", "normal_file_path", "mask_path"):
            assert (folder / frame[key]).is_file()


def test_images_masks_normals_and_depths_agree(duck_views):
    folder, _, document = duck_views
    for frame in document["frames"]:
        rgba = _pixels(folder / frame["file_path"])
        mask = _pixels(folder / frame["mask_path"])
        depth = np.load(folder / frame["depth_file_path"])
        normal = _pixels(folder / frame["normal_file_path"]) / 127.5 - 1.0
        assert rgba.shape == (72, 96, 4) and mask.dtype == np.uint8 and depth.dtype == np.float32
        drawn = mask == 255
        assert set(np.unique(mask)) <= {0, 255} and 0.05 < drawn.mean() < 0.9
        assert np.array_equal(rgba[..., 3] > 0, drawn)  # alpha is coverage: the same pixels
        assert (depth[drawn] > 0).all() and (depth[~drawn] == 0).all()
        lengths = np.linalg.norm(normal[drawn], axis=-1)
        assert np.allclose(lengths, 1.0, atol=0.02)


def _pixel_rays(document, pose, step):
    """World rays through every ``step``-th pixel centre, from the intrinsics and the pose."""
    ys, xs = np.mgrid[0 : document["h"] : step, 0 : document["w"] : step]
    camera = np.stack(
        [
            (xs + 0.5 - document["cx"]) / document["fl_x"],
            -(ys + 0.5 - document["cy"]) / document["fl_y"],  # image rows go down, +Y up
            -np.ones(xs.shape),  # the camera looks down its -Z
        ],
        axis=-1,
    ).reshape(-1, 3)
    directions = camera @ pose[:3, :3].T
    return ys.ravel(), xs.ravel(), np.tile(pose[:3, 3], (len(directions), 1)), directions


def test_an_independent_ray_caster_sees_the_same_depths(duck_views):
    """trimesh casts rays from the dataset's poses and intrinsics: hits, misses and depths agree."""
    trimesh = pytest.importorskip("trimesh")
    pytest.importorskip("rtree", reason="trimesh's ray caster needs rtree (the test extra)")
    folder, _, document = duck_views
    mesh = trimesh.load(DUCK, force="mesh")  # node transforms applied, as in the dataset
    for frame in document["frames"]:
        pose = np.array(frame["transform_matrix"])
        depth = np.load(folder / frame["depth_file_path"])
        ys, xs, origins, directions = _pixel_rays(document, pose, step=3)
        hits, rays, _ = mesh.ray.intersects_location(origins, directions, multiple_hits=False)
        expected = np.zeros(len(ys))
        expected[rays] = (hits - origins[rays]) @ -pose[:3, 2]  # along the viewing axis
        ours = depth[ys, xs]
        same_cover = (ours > 0) == (expected > 0)
        assert same_cover.mean() > 0.98  # silhouettes agree but for a few edge pixels
        both = (ours > 0) & (expected > 0)
        close = np.isclose(ours[both], expected[both], rtol=1e-3)
        assert both.sum() > 50 and close.mean() > 0.98


def test_a_scene_of_our_own_renders_and_returns_its_poses(tmp_path):
    scene = pp.Scene(
        pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=24, height=16),
        [pp.Sphere((1, 0, 0), 1.0), pp.Plane((0, -1, 0), (0, 1, 0))],
        [pp.PointLight((2, 3, 4))],
    )
    poses = pp.render_views(scene, 4, tmp_path / "v", elevation=10)
    assert poses.shape == (4, 4, 4)
    assert np.allclose(poses[:, :3, 3].mean(axis=0)[[0, 2]], [1, 0])  # round the sphere
    image = _pixels(tmp_path / "v" / "images" / "view_0000.png")
    assert image.shape == (16, 24, 3)  # RGB, the scene camera's size


def test_the_same_request_gives_the_same_bytes(tmp_path):
    options = {"layout": "random", "seed": 11, "size": (40, 30), "aovs": ("depth", "mask")}
    pp.render_views(DUCK, 3, tmp_path / "a", **options)
    pp.render_views(DUCK, 3, tmp_path / "b", **options)
    first, second = _files(tmp_path / "a"), _files(tmp_path / "b")
    assert first == second and "transforms.json" in first and REQUEST_FILE in first


def test_resume_renders_only_what_is_missing_or_broken(tmp_path):
    folder = tmp_path / "v"
    options = {"size": (40, 30), "aovs": "depth"}
    pp.render_views(DUCK, 4, folder, **options)
    whole = _files(folder)
    (folder / "images" / "view_0001.png").unlink()
    (folder / "depth" / "view_0003.npy").write_bytes(b"\x93NUMPY broken")
    (folder / "transforms.json").unlink()
    (folder / "images" / ".view_0001.png.k3x9_q.tmp").write_bytes(b"\x89PNG")  # a died write
    rendered = []
    pp.render_views(DUCK, 4, folder, resume=True, progress=rendered.append, **options)
    assert sum(rendered) == 2
    assert _files(folder) == whole


def test_the_orbit_height_recorded_is_the_one_used(tmp_path):
    folder = tmp_path / "v"
    pp.render_views(DUCK, 2, folder, size=(24, 24))
    recorded = json.loads((folder / "transforms.json").read_text())["pixelpath"]["elevation"]
    assert recorded == 22.0  # the default orbit's, not "None"
    # the same height asked for by number is the same request: the dataset resumes
    pp.render_views(DUCK, 2, folder, size=(24, 24), elevation=22, resume=True)

def test_a_folder_holding_a_dataset_is_kept_unless_asked(tmp_path):
    folder = tmp_path / "v"
    pp.render_views(DUCK, 3, folder, size=(32, 32))
    with pytest.raises(ValueError, match="already holds a dataset of views"):
        pp.render_views(DUCK, 3, folder, size=(32, 32))
    with pytest.raises(ValueError, match="made with other settings"):
        pp.render_views(DUCK, 3, folder, size=(32, 24), resume=True)
    pp.render_views(DUCK, 2, folder, size=(32, 32), overwrite=True)
    assert sorted(p.name for p in (folder / "images").iterdir()) == [
        "view_0000.png",
        "view_0001.png",
    ]
    document = json.loads((folder / "transforms.json").read_text())
    assert len(document["frames"]) == 2


def test_other_files_in_the_folder_are_left_alone(tmp_path):
    folder = tmp_path / "v"
    folder.mkdir()
    (folder / "notes.txt").write_text("mine")
    pp.render_views(DUCK, 1, folder, size=(16, 16))
    pp.render_views(DUCK, 1, folder, size=(16, 16), overwrite=True)
    assert (folder / "notes.txt").read_text() == "mine"


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"aovs": "depth,albedo"}, ValueError, "unknown AOV 'albedo'"),
        ({"n": 0}, ValueError, "at least 1 view"),
        ({"size": (16384, 16384)}, ValueError, "samples, more than .* smaller views"),
        ({"size": (20000, 20)}, ValueError, "width must be between 1 and 16384"),
        ({"size": (0, 10)}, ValueError, "width must be a whole number"),
        ({"method": "magic"}, ValueError, "magic"),
        ({"distance": -1.0}, ValueError, "distance must be a positive"),
        ({"fov": 180}, ValueError, "fov must be degrees"),
        ({"resume": True, "overwrite": True}, ValueError, "exclude each other"),
        ({"colour": "red"}, TypeError, "unknown render option"),
    ],
)
def test_bad_requests_fail_before_anything_is_written(tmp_path, kwargs, error, message):
    request = {"scene_or_path": DUCK, "n": 2, "out": tmp_path / "v", "size": (16, 16)} | kwargs
    with pytest.raises(error, match=message):
        pp.render_views(**request)
    assert not (tmp_path / "v").exists()


def test_a_model_that_cannot_be_framed_is_refused(tmp_path):
    camera = pp.Camera(eye=(0, 1, 5), target=(0, 0, 0))
    only_a_floor = pp.Scene(camera, [pp.Plane((0, 0, 0), (0, 1, 0))])
    with pytest.raises(ValueError, match="no bounded objects"):
        pp.render_views(only_a_floor, 2, tmp_path / "v")
    huge = pp.Mesh(np.array([[-1e308, 0, 0], [1e308, 0, 0], [0, 1e308, 0]]), [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"cannot be framed: its bounds .* overflow"):
        pp.render_views(pp.Scene(camera, [huge]), 2, tmp_path / "v")
    assert not (tmp_path / "v").exists()


def test_the_command_line_writes_a_dataset(tmp_path, capsys):
    folder = tmp_path / "duck"
    argv = ["views", str(DUCK), "-o", str(folder), "-n", "3", "--size", "32x24", "--aov",
            "depth,mask", "--layout", "sphere", "--workers", "1"]
    pytest.importorskip("distributed", reason="--workers needs dask (the test extra)")
    assert main(argv) == 0
    document = json.loads((folder / "transforms.json").read_text())
    assert [f["mask_path"] for f in document["frames"]][-1] == "masks/view_0002.png"
    assert "wrote 3 views" in capsys.readouterr().out
    assert main(argv[:-2]) == 2  # the dataset is there: refused, with a way out
    assert "--resume" in capsys.readouterr().err
    assert main([*argv[:-2], "--resume", "-q"]) == 0


def test_the_command_line_refuses_unknown_aovs(tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["views", str(DUCK), "-o", str(tmp_path / "v"), "--aov", "id"])
    assert exit_.value.code == 2 and "unknown AOV 'id'" in capsys.readouterr().err


def test_the_views_page_s_loader_example_lands_on_the_surface(tmp_path, monkeypatch):
    page = (Path(__file__).parents[2] / "docs" / "guide" / "views.md").read_text()
    after = page.split("A dataset opens the way nerfstudio reads it", 1)[1]
    code = after.split("```python\n", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(tmp_path)
    pp.render_views(DUCK, 2, "duck_views", "depth", size=(64, 48))
    names: dict = {}
    exec(compile(code, "docs/guide/views.md loader example", "exec"), names)
    trimesh = pytest.importorskip("trimesh")
    mesh = trimesh.load(DUCK, force="mesh")
    distance = abs(trimesh.proximity.signed_distance(mesh, [names["point"]])[0])
    assert distance < 1e-3 * mesh.scale  # the point lies on the model's surface


def test_png_level_sets_every_pngs_compression_and_keeps_their_pixels(tmp_path):
    scene = pp.Scene(
        pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30),
        [pp.Sphere((0, 0, 0), 1.0)],
        [pp.PointLight((2, 3, 4))],
    )
    folders = {}
    for level in (0, 1, 9, None):
        folders[level] = tmp_path / f"level{level}"
        pp.render_views(scene, 3, folders[level], "normal,mask", png_level=level,
                        transparent=True)
    # the pictures (RGBA), and the AOVs' PNG files as well (RGB normals, 8-bit masks)
    for name, pixel_bytes in (("images", 4), ("normals", 3), ("masks", 1)):
        sizes = {level: len((folder / name / "view_0001.png").read_bytes())
                 for level, folder in folders.items()}
        assert sizes[0] > 40 * 30 * pixel_bytes > sizes[1] >= sizes[9], name
    for folder in folders.values():
        for name in ("images/view_0002.png", "normals/view_0002.png", "masks/view_0002.png"):
            assert np.array_equal(_pixels(folder / name), _pixels(folders[None] / name))
    assert not list(tmp_path.rglob("*.tmp"))
    with pytest.raises(ValueError, match="png_level must be an int from 0 to 9"):
        pp.render_views(scene, 3, tmp_path / "bad", png_level=10)


def test_a_failed_write_of_a_view_reaches_the_caller(tmp_path, monkeypatch):
    from pixelpath.frames.views import ViewOutput

    def broken(self, image, kind):
        raise OSError("disk full")

    monkeypatch.setattr(ViewOutput, "encode", broken)
    scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=8, height=6),
                     [pp.Sphere((0, 0, 0), 1.0)])
    with pytest.raises(OSError, match="disk full"):
        pp.render_views(scene, 4, tmp_path / "views")
    assert not (tmp_path / "views" / "transforms.json").exists()


def test_views_png_level_option(tmp_path):
    folder = tmp_path / "duck"
    assert main(["views", str(DUCK), "-o", str(folder), "-n", "2", "--size", "32x24",
                 "--png-level", "9", "-q"]) == 0
    pp.render_views(DUCK, 2, tmp_path / "api", size=(32, 24), png_level=9)
    assert _files(folder)["images/view_0001.png"] == _files(tmp_path / "api")[
        "images/view_0001.png"]
