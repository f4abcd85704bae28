"""The documentation's sources, checked without building them (CI builds the site).

Every name of the public API contract has a page in the API reference, every gallery example
compiles and has the title sphinx-gallery needs, and every gallery picture a page shows comes
from an example that exists.
"""

import ast
import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[1] / "docs"

# The public API contract (shared/SPEC.md, section 2), as "module.name".
CONTRACT = [
    *(f"pixelpath.color.{name}" for name in (
        "rgb_to_hsv", "hsv_to_rgb", "rgb_to_cmy", "cmy_to_rgb", "rgb_to_cmyk", "cmyk_to_rgb",
        "rgb_to_yiq", "yiq_to_rgb", "rgb_to_hsl", "hsl_to_rgb", "rgb_to_ycbcr", "ycbcr_to_rgb",
        "convert")),
    *(f"pixelpath.clip.{name}" for name in (
        "Rect", "sutherland_hodgman", "weiler_atherton", "clip_polygons", "ClipTrace")),
    "pixelpath.lighting.phong_terms", "pixelpath.lighting.reflect",
    *(f"pixelpath.{name}" for name in (
        "Camera", "Material", "PointLight", "Sphere", "Plane", "Mesh", "Scene", "load_scene",
        "render", "render_frames", "render_views", "Image")),
    *(f"pixelpath.exercises.{name}" for name in ("TOPICS", "make", "from_notes", "export")),
    *(f"pixelpath.raytrace.{name}" for name in ("ray_sphere", "ray_plane", "refract", "intersect")),
]


def documented_names() -> set[str]:
    """Names the API reference's sources document: autosummary entries and autodata."""
    names = set()
    for page in (DOCS / "api").glob("*.rst"):
        module = None
        in_summary = False
        for line in page.read_text(encoding="utf-8").splitlines():
            if match := re.match(r"\.\. currentmodule:: ([\w.]+)$", line):
                module = match.group(1)
            elif line.startswith(".. autosummary::"):
                in_summary = True
            elif match := re.match(r"\.\. auto(?:data|class|function):: (\w+)$", line):
                names.add(f"{module}.{match.group(1)}")
            elif in_summary and (match := re.match(r"   (\w+)$", line)):
                names.add(f"{module}.{match.group(1)}")
            elif in_summary and line and not line.startswith(" "):
                in_summary = False
    return names


def test_every_name_of_the_contract_has_a_page_in_the_api_reference():
    missing = sorted(set(CONTRACT) - documented_names())
    assert not missing, f"not in docs/api/*.rst: {missing}"


def test_the_documented_names_exist():
    import importlib

    for name in sorted(documented_names()):
        module, _, attribute = name.rpartition(".")
        assert hasattr(importlib.import_module(module), attribute), name


EXAMPLES = sorted((DOCS / "examples").glob("*.py"))


def test_the_gallery_has_examples():
    assert len(EXAMPLES) >= 5


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda path: path.name)
def test_each_gallery_example_compiles_and_has_a_title(path):
    source = path.read_text(encoding="utf-8")
    tree = ast.parse(source, filename=str(path))
    compile(tree, str(path), "exec")
    docstring = ast.get_docstring(tree)
    assert docstring, "a gallery example starts with a docstring: its title and text"
    title, underline = docstring.splitlines()[:2]
    assert title.strip() and set(underline.strip()) == {"="}, "the docstring starts with a title"
    assert path.name.startswith("plot_"), "sphinx-gallery runs the files named plot_*.py"


def test_the_pages_show_pictures_that_exist_or_that_an_example_draws():
    examples = {path.stem for path in EXAMPLES}
    for page in DOCS.rglob("*.md"):
        if "_build" in page.parts or "auto_examples" in page.parts:
            continue
        for target in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", page.read_text(encoding="utf-8")):
            if match := re.match(r"/auto_examples/images/sphx_glr_(\w+?)_\d{3}\.\w+$", target):
                assert match.group(1) in examples, f"{page.name}: {target}"
            else:
                assert (DOCS / target.lstrip("/")).is_file(), f"{page.name}: {target}"


def test_the_development_page_draws_the_layers_the_layer_test_checks():
    from test_layers import LAYERS

    page = (DOCS / "development.md").read_text(encoding="utf-8")
    section = page.split("## Layers", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| (\d+) \| (.+) \|$", section, flags=re.MULTILINE)
    drawn = [tuple(re.findall(r"`([\w.]+)`", modules)) for _, modules in rows]
    assert [int(number) for number, _ in rows] == list(range(1, len(LAYERS) + 1))
    assert drawn == list(LAYERS)
