"""``pixelpath ray`` and ``pixelpath render --method raytrace``: output, options, errors."""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

import pixelpath as pp
from pixelpath.cli import main
from pixelpath.io import read_image
from pixelpath.io.models import read_model
from pixelpath.renderer import METHOD_NAMES

DUCK = Path(__file__).resolve().parents[1] / "data" / "models" / "Duck.glb"

SCENE = textwrap.dedent(
    """\
    background = [0, 0, 0.5]

    [camera]
    eye = [0, 0, 5]
    target = [0, 0, 0]
    width = 24
    height = 16

    [[lights]]
    type = "point"
    position = [2, 3, 4]

    [materials.glass]
    transparency = 0.9
    ior = 1.5

    [[objects]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 1
    material = "glass"

    [[objects]]
    type = "plane"
    point = [0, 0, -3]
    normal = [0, 0, 1]
    """
)


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def test_ray_explain_prints_the_tree_with_the_sphere_quadratic(scene_file, capsys):
    assert main(["ray", str(scene_file), "--pixel", "12,8", "--explain"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("pixel (12, 8) of 24×16")
    assert "b² − 4ac" in out
    assert "refracted ray (depth 1" in out and "refracted ray (depth 2" in out
    assert "hits object 1 (plane" in out


def test_ray_without_explain_prints_one_line_matching_the_render(scene_file, tmp_path, capsys):
    assert main(["ray", str(scene_file), "--pixel", "3,2"]) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith("pixel (3, 2): rgb (") and "object 1" in line
    output = tmp_path / "traced.png"
    assert main(["render", str(scene_file), "-o", str(output), "--method", "raytrace", "-q"]) == 0
    expected = pp.render(pp.load_scene(scene_file), "raytrace")
    assert np.array_equal(read_image(output), expected.to_uint8() / np.float32(255))


@pytest.mark.parametrize(
    ("model", "options", "read"),
    [
        ("block", ["--up", "z"], {"up": "z"}),  # a Z-up part stood up
        ("duck", ["--frame"], {"frame": True}),  # framed in place of the file's own camera
    ],
)
def test_ray_reads_a_model_file_as_render_does(block, capsys, model, options, read):
    path = {"block": block, "duck": DUCK}[model]
    assert main(["ray", str(path), "--size", "32x24", "--pixel", "16,12", *options]) == 0
    line = capsys.readouterr().out
    image = pp.render(read_model(path, size=(32, 24), **read), "raytrace")
    assert image.object_id[12, 16] == 0
    assert f"object 0 at depth {image.depth[12, 16]:.6g};" in line
    # the option changed what the pixel sees: without it the ray ends elsewhere
    plain = pp.render(read_model(path, size=(32, 24)), "raytrace")
    assert f"{plain.depth[12, 16]:.6g}" != f"{image.depth[12, 16]:.6g}"


def test_render_passes_samples_and_max_depth(scene_file, tmp_path):
    output = tmp_path / "traced.png"
    args = ["render", str(scene_file), "-o", str(output), "--method", "raytrace", "-q"]
    assert main([*args, "--samples", "4", "--max-depth", "0", "--fresnel"]) == 0
    scene = pp.load_scene(scene_file)
    expected = pp.render(scene, "raytrace", samples=4, max_depth=0, fresnel=True)
    assert np.array_equal(read_image(output), expected.to_uint8() / np.float32(255))


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--pixel", "24,0"], "pixel must lie"),
        (["--pixel", "a,b"], "--pixel must look like"),
        (["--pixel", "1,1", "--max-depth", "-1"], "max_depth"),
        (["--pixel", "1,1", "--samples", "0"], "samples"),
    ],
)
def test_ray_errors_are_clean(scene_file, capsys, args, message):
    assert main(["ray", str(scene_file), *args]) == 2
    assert message in capsys.readouterr().err


def test_render_refuses_samples_for_a_raster_method(scene_file, tmp_path, capsys):
    args = ["render", str(scene_file), "-o", str(tmp_path / "z.png"), "--samples", "4", "-q"]
    assert main(args) == 2
    assert "raytrace" in capsys.readouterr().err


@pytest.mark.slow  # every method on the showcase, the BSP build included: minutes without JIT
def test_demo_ray_traces_the_showcase_and_draws_every_method(tmp_path):
    assert main(["demo", "-o", str(tmp_path), "--size", "32x20", "--ssaa", "1", "-q"]) == 0
    traced = read_image(tmp_path / "showcase-raytrace.png")
    plain = read_image(tmp_path / "showcase.png")
    assert traced.shape == plain.shape == (20, 32, 3)
    assert not np.array_equal(traced, plain)  # shadows, mirror and glass
    # Seven methods in rows of four, each row: gap 8, caption 22, a 150-pixel picture, gap 8.
    assert len(METHOD_NAMES) == 7
    assert read_image(tmp_path / "methods.png").shape[0] == 2 * (8 + 22 + 150 + 8)
