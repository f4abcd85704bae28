"""``pixelpath info``: summarize a scene or model file: objects, faces, lights, camera, bounds."""

from __future__ import annotations

import argparse
import json
from typing import Any

from pixelpath.cli._common import add_command, console
from pixelpath.cli.render import add_model_options, load_scene_sized, scene_path


def register(subparsers: Any) -> None:
    """Add the ``info`` subcommand."""
    parser = add_command(
        subparsers,
        "info",
        summary="summarize a scene or model file: objects, faces, lights, camera, bounds",
        description=(
            "Load a TOML scene file (checking it completely, meshes included) and print its "
            "objects with their material, face and triangle counts and bounds, its lights, its "
            "camera and the totals. SCENE may also name a model file (glTF/GLB, OBJ+MTL, PLY, "
            "STL: its parts, named after their nodes) or a bundled demo scene."
        ),
        examples=[
            "pixelpath info scene.toml",
            "pixelpath info Duck.glb --json",
            "pixelpath info part.stl --up z  # the bounds and camera of the turned part",
        ],
        run=run,
    )
    parser.add_argument(
        "scene",
        help="a .toml scene file, a model file (.glb .gltf .obj .ply .stl) or a bundled scene",
    )
    add_model_options(parser)
    parser.add_argument("--json", action="store_true", help="print the summary as JSON")


def run(args: argparse.Namespace) -> int:
    """Load the scene and print its summary."""
    path = scene_path(args.scene)
    summary = summarize(load_scene_sized(str(path), None, args.frame, args.up), str(path))
    if args.json:
        print(json.dumps(summary, indent=2))
    else:
        _print_tables(summary)
    return 0


def summarize(scene: Any, file: str) -> dict[str, Any]:
    """Return a JSON-compatible summary of ``scene`` (what ``--json`` prints)."""
    objects = [_object_summary(index, obj) for index, obj in enumerate(scene.objects)]
    try:
        bounds = scene.bounds().tolist()
    except ValueError:  # only planes, or nothing at all
        bounds = None
    camera = scene.camera
    return {
        "file": file,
        "camera": {
            "eye": camera.eye.tolist(),
            "target": camera.target.tolist(),
            "up": camera.up.tolist(),
            "fov": camera.fov,
            "width": camera.width,
            "height": camera.height,
            "near": camera.near,
            "far": camera.far,
            "projection": camera.projection,
            "view_height": camera.view_height,
        },
        "objects": objects,
        "lights": [_light_summary(light) for light in scene.lights],
        "ambient": scene.ambient.tolist(),
        "background": scene.background.tolist(),
        "totals": {
            "objects": len(objects),
            "faces": sum(obj["faces"] or 0 for obj in objects),
            "triangles": sum(obj["triangles"] or 0 for obj in objects),
            "lights": len(scene.lights),
            "bounds": bounds,
        },
    }


def _object_summary(index: int, obj: Any) -> dict[str, Any]:
    from pixelpath.scene import Mesh, Plane

    kind = type(obj).__name__.lower()
    faces = triangles = None  # spheres and planes are analytic
    if isinstance(obj, Mesh):
        faces, triangles = obj.face_count, len(obj.triangles)
    elif kind == "box":
        faces, triangles = 6, 12
    return {
        "index": index,
        "type": kind,
        "name": getattr(obj, "name", None),
        "material": _material_label(obj.material),
        "faces": faces,
        "triangles": triangles,
        "bounds": None if isinstance(obj, Plane) else obj.bounds().tolist(),
    }


def _material_label(material: Any) -> str:
    """Return the material's name in the scene file, else "default" or "inline"."""
    from pixelpath.scene import Material

    if material.name is not None:
        return material.name
    return "default" if material == Material() else "inline"


def _light_summary(light: Any) -> dict[str, Any]:
    from pixelpath.scene import DirectionalLight

    if isinstance(light, DirectionalLight):
        return {"type": "directional", "direction": light.direction.tolist(),
                "intensity": light.intensity, "color": light.color.tolist()}  # fmt: skip
    return {"type": "point", "position": light.position.tolist(),
            "intensity": light.intensity, "color": light.color.tolist()}  # fmt: skip


def _vector(values: list[float] | None) -> str:
    return "—" if values is None else "(" + ", ".join(f"{x:.3g}" for x in values) + ")"


def _bounds(bounds: list[list[float]] | None) -> str:
    return "infinite" if bounds is None else f"{_vector(bounds[0])} … {_vector(bounds[1])}"


def _view(camera: dict[str, Any]) -> str:
    """Describe the camera's view: its field of view, or an orthographic view's size."""
    if camera["projection"] == "orthographic":
        aspect = camera["width"] / camera["height"]
        return f"orthographic {camera['view_height'] * aspect:g} × {camera['view_height']:g} units"
    return f"fov {camera['fov']:g}°"


def _count(value: int | None) -> str:
    return "analytic" if value is None else f"{value:,}"


def _print_tables(summary: dict[str, Any]) -> None:
    from rich.table import Table

    out = console()
    camera = summary["camera"]
    out.print(f"[bold]{summary['file']}[/]")
    out.print(
        f"camera: eye {_vector(camera['eye'])} → target {_vector(camera['target'])}, "
        f"{_view(camera)}, {camera['width']}×{camera['height']} px, "
        f"near {camera['near']:g}, far {camera['far']:g}"
    )
    objects = Table(title="objects", title_justify="left")
    for column in ("#", "type", "name", "material", "faces", "triangles", "bounds"):
        justify = "right" if column in ("#", "faces", "triangles") else "left"
        objects.add_column(column, justify=justify)
    for obj in summary["objects"]:
        objects.add_row(
            str(obj["index"]), obj["type"], obj["name"] or "", obj["material"],
            _count(obj["faces"]), _count(obj["triangles"]), _bounds(obj["bounds"]),
        )  # fmt: skip
    out.print(objects)
    lights = Table(title="lights", title_justify="left")
    for column in ("type", "position / direction", "intensity", "color"):
        lights.add_column(column)
    for light in summary["lights"]:
        where = light.get("position", light.get("direction"))
        lights.add_row(light["type"], _vector(where), f"{light['intensity']:g}",
                       _vector(light["color"]))  # fmt: skip
    out.print(lights)
    totals = summary["totals"]
    counts = ", ".join(  # "1 object", "4,212 faces": the keys are the nouns' plurals
        f"{totals[key]:,} {key[:-1]}{'s' * (totals[key] != 1)}"
        for key in ("objects", "faces", "triangles", "lights")
    )
    ambient, bounds = _vector(summary["ambient"]), _bounds(totals["bounds"])
    out.print(f"total: {counts}; ambient {ambient}; bounds {bounds}")
