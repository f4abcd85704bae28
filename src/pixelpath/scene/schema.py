"""The scene-file format, defined once: the loader checks files against it; the JSON Schema too.

A scene file (TOML, or the equivalent dict of :meth:`Scene.to_dict`) has the top-level keys of
:data:`TOP_LEVEL`; each section lists its keys as :class:`Key` records whose ``kind`` names an
entry of :data:`KINDS`. A kind couples the Python check the loader runs (with the phrase used in
its error message) to the JSON Schema fragment published in ``docs/scene.schema.json``.
Defaults come from the constructors themselves, so they cannot drift apart.

The published file is regenerated with::

    python -c "import json; from pixelpath.scene.schema import scene_json_schema; \
print(json.dumps(scene_json_schema(), indent=2))" > docs/scene.schema.json
"""

from __future__ import annotations

import dataclasses
import inspect
import numbers
from collections.abc import Callable
from typing import Any

from pixelpath.scene.animation import INTERPOLATIONS, Animation, Turntable
from pixelpath.scene.camera import PROJECTIONS, Camera
from pixelpath.scene.lights import DirectionalLight, PointLight
from pixelpath.scene.material import Material
from pixelpath.scene.primitives import Box, Plane, Sphere
from pixelpath.scene.procedural import icosphere, torus
from pixelpath.scene.scene import ENCODINGS, Scene
from pixelpath.scene.transform import transform_matrix

SCHEMA_ID = "https://pixelpath.invalid/scene.schema.json"


@dataclasses.dataclass(frozen=True)
class Kind:
    """A kind of value: its Python check, how errors describe it, and its JSON Schema."""

    check: Callable[[Any], bool]
    expected: str
    json: dict[str, Any]


@dataclasses.dataclass(frozen=True)
class Key:
    """One key of a section: its kind, whether it must be present, and what it means."""

    kind: str
    description: str
    required: bool = False


def _is_number(value: Any) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _is_int(value: Any) -> bool:
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def _is_vector3(value: Any) -> bool:
    return isinstance(value, list | tuple) and len(value) == 3 and all(map(_is_number, value))


def _is_points(value: Any) -> bool:
    return isinstance(value, list | tuple) and all(map(_is_vector3, value))


def _is_faces(value: Any) -> bool:
    return isinstance(value, list | tuple) and all(
        isinstance(face, list | tuple) and all(map(_is_int, face)) for face in value
    )


_NUMBER = {"type": "number"}
_VECTOR3 = {"type": "array", "items": _NUMBER, "minItems": 3, "maxItems": 3}

KINDS: dict[str, Kind] = {
    "number": Kind(_is_number, "a number", _NUMBER),
    "integer": Kind(_is_int, "an integer", {"type": "integer"}),
    "string": Kind(lambda x: isinstance(x, str), "a string", {"type": "string"}),
    "vector3": Kind(_is_vector3, "an array of 3 numbers", _VECTOR3),
    "intensity": Kind(
        lambda x: _is_number(x) or _is_vector3(x),
        "a number or an array of 3 numbers (r, g, b)",
        {"oneOf": [_NUMBER, _VECTOR3]},
    ),
    "points": Kind(
        _is_points, "an array of [x, y, z] arrays", {"type": "array", "items": _VECTOR3}
    ),
    "faces": Kind(
        _is_faces,
        "an array of faces, each an array of vertex indices (integers)",
        {
            "type": "array",
            "minItems": 1,
            "items": {"type": "array", "items": {"type": "integer", "minimum": 0}, "minItems": 3},
        },
    ),
    "material": Kind(
        lambda x: isinstance(x, str | dict),
        "a material name (string) or an inline table of material keys",
        {"oneOf": [{"type": "string"}, {"$ref": "#/$defs/material"}]},
    ),
    "transform": Kind(
        lambda x: isinstance(x, dict), "a table of translate, rotate, scale",
        {"$ref": "#/$defs/transform"},
    ),
    "projection": Kind(
        lambda x: x in PROJECTIONS,
        " or ".join(map(repr, PROJECTIONS)),
        {"enum": list(PROJECTIONS)},
    ),
    "encoding": Kind(
        lambda x: x in ENCODINGS,
        " or ".join(map(repr, ENCODINGS)),
        {"enum": list(ENCODINGS)},
    ),
    "interpolation": Kind(
        lambda x: x in INTERPOLATIONS,
        " or ".join(map(repr, INTERPOLATIONS)),
        {"enum": list(INTERPOLATIONS)},
    ),
    "object": Kind(
        lambda x: _is_int(x) or isinstance(x, str),
        "an object index (integer, from 0) or a mesh's name (string)",
        {"oneOf": [{"type": "integer", "minimum": 0}, {"type": "string"}]},
    ),
    "animation": Kind(
        lambda x: isinstance(x, dict), "a table of animation keys", {"$ref": "#/$defs/animation"}
    ),
    "turntable": Kind(
        lambda x: isinstance(x, dict), "a table of turns, center", {"$ref": "#/$defs/turntable"}
    ),
    "table": Kind(lambda x: isinstance(x, dict), "a table", {"type": "object"}),
    "array": Kind(lambda x: isinstance(x, list | tuple), "an array of tables", {"type": "array"}),
}

CAMERA = {
    "eye": Key("vector3", "camera position", required=True),
    "target": Key("vector3", "the point the camera looks at", required=True),
    "up": Key("vector3", "approximate up direction"),
    "fov": Key("number", "vertical field of view in degrees, in (0, 180)"),
    "width": Key("integer", "image width in pixels (1..16384)"),
    "height": Key("integer", "image height in pixels (1..16384)"),
    "near": Key("number", "near clipping distance, > 0"),
    "far": Key("number", "far clipping distance, > near"),
    "projection": Key("projection", "'perspective' (default) or 'orthographic'"),
    "view_height": Key("number", "orthographic only, required there: view height in world units"),
}

MATERIAL = {
    "color": Key("vector3", "object colour (r, g, b) in [0, 1]"),
    "ka": Key("number", "ambient coefficient"),
    "kd": Key("number", "diffuse coefficient"),
    "ks": Key("number", "specular coefficient"),
    "shininess": Key("number", "Phong exponent n"),
    "reflectivity": Key("number", "mirror reflection fraction in [0, 1] (ray tracer)"),
    "transparency": Key("number", "transmitted fraction in [0, 1] (ray tracer)"),
    "ior": Key("number", "index of refraction, > 0 (ray tracer)"),
    "alpha": Key("number", "alpha of the colour in [0, 1], for the alpha test (alpha_cutoff)"),
    "alpha_cutoff": Key(
        "number",
        "alpha test: where alpha x vertex-colour alpha x texture alpha is below it, the "
        "surface is cut away (glTF alphaMode MASK); absent: opaque",
    ),
    "emission": Key("vector3", "light the surface emits (r, g, b), >= 0, added to its shading"),
}

TRANSFORM = {
    "translate": Key("vector3", "offset, applied last"),
    "rotate": Key("vector3", "angles in degrees about X, then Y, then Z"),
    "scale": Key("intensity", "uniform factor or per-axis factors, applied first"),
}

_LIGHT_COMMON = {
    "type": Key("string", "light type", required=True),
    "intensity": Key("number", "scalar intensity, >= 0"),
    "color": Key("vector3", "light colour (r, g, b)"),
}
LIGHTS = {
    "point": (PointLight, {**_LIGHT_COMMON, "position": Key("vector3", "position", True)}),
    "directional": (
        DirectionalLight,
        {**_LIGHT_COMMON, "direction": Key("vector3", "direction the light travels", True)},
    ),
}

_OBJECT_COMMON = {
    "type": Key("string", "object type", required=True),
    "material": Key("material", "name of a [materials] entry, or an inline material table"),
    "transform": Key("transform", "scale, rotate (X, Y, Z in degrees), then translate"),
}
_MESH_COMMON = {**_OBJECT_COMMON, "name": Key("string", "label shown by pixelpath info")}
OBJECTS = {
    "sphere": (
        Sphere,
        {
            **_OBJECT_COMMON,
            "center": Key("vector3", "centre", required=True),
            "radius": Key("number", "radius, > 0", required=True),
        },
    ),
    "plane": (
        Plane,
        {
            **_OBJECT_COMMON,
            "point": Key("vector3", "a point on the plane", required=True),
            "normal": Key("vector3", "normal (the front side)", required=True),
        },
    ),
    "box": (
        Box,
        {
            **_OBJECT_COMMON,
            "minimum": Key("vector3", "corner with the smallest coordinates", required=True),
            "maximum": Key("vector3", "corner with the largest coordinates", required=True),
        },
    ),
    "mesh": (
        None,
        {
            **_MESH_COMMON,
            "path": Key(
                "string",
                "OBJ, PLY, STL, glTF or GLB file, relative to the scene file (a glTF/GLB, or "
                "an OBJ with an MTL and no 'material', gives one object per part)",
            ),
            "vertices": Key("points", "inline vertex positions (instead of path)"),
            "faces": Key("faces", "inline polygons, counter-clockwise from outside"),
            "normals": Key("points", "inline per-vertex normals (optional)"),
        },
    ),
    "icosphere": (
        icosphere,
        {
            **_MESH_COMMON,
            "subdivisions": Key("integer", "times each triangle is split in four (0..7)"),
            "radius": Key("number", "radius, > 0"),
            "center": Key("vector3", "centre"),
        },
    ),
    "torus": (
        torus,
        {
            **_MESH_COMMON,
            "major_radius": Key("number", "distance from the Y axis to the tube's centre"),
            "minor_radius": Key("number", "tube radius, < major_radius"),
            "major_segments": Key("integer", "segments around the Y axis"),
            "minor_segments": Key("integer", "segments around the tube"),
        },
    ),
}

_KEY_COMMON = {
    "frame": Key("integer", "the frame the values are for (1 .. frames - 1)", required=True),
    "interpolation": Key("interpolation", "how values move to the next key"),
}
CAMERA_KEY = {
    **_KEY_COMMON,
    "eye": Key("vector3", "camera position at this frame"),
    "target": Key("vector3", "the point looked at, at this frame"),
    "fov": Key("number", "vertical field of view at this frame, degrees"),
    "view_height": Key("number", "orthographic view height at this frame, world units"),
}
OBJECT_KEY = {
    "object": Key("object", "the object: index in [[objects]] or a mesh's name", required=True),
    **_KEY_COMMON,
    "translate": Key("vector3", "offset at this frame, applied last"),
    "rotate": Key("vector3", "angles in degrees about X, then Y, then Z, at this frame"),
    "scale": Key("intensity", "positive factor or per-axis factors at this frame"),
}
TURNTABLE = {
    "turns": Key("number", "full turns of the camera over the animation (non-zero)"),
    "center": Key("vector3", "a point on the axis (default: the centre of the scene's bounds)"),
}
ANIMATION = {
    "frames": Key("integer", "number of frames, numbered from 0 (1..1000000)", required=True),
    "interpolation": Key("interpolation", "interpolation of keys that name none"),
    "camera": Key("array", "camera keys: [[animation.camera]]"),
    "objects": Key("array", "object transform keys: [[animation.objects]]"),
    "turntable": Key("turntable", "orbit the camera about the scene: [animation.turntable]"),
}

TOP_LEVEL = {
    "camera": Key("table", "the camera", required=True),
    "lights": Key("array", "light sources"),
    "materials": Key("table", "named materials"),
    "objects": Key("array", "scene objects"),
    "ambient": Key("intensity", "ambient light intensity Ia, scalar or (r, g, b)"),
    "background": Key("vector3", "colour where nothing is drawn"),
    "animation": Key("animation", "keyframes over frames; frame 0 is the scene as written"),
    "encoding": Key(
        "encoding", "how pictures are saved: 'linear' (intensity x 255) or 'srgb' (sRGB curve)"
    ),
}


def defaults(factory: Callable[..., Any] | None) -> dict[str, Any]:
    """Return the keyword defaults of a constructor, tuples as lists (as TOML would give them)."""
    if factory is None:
        return {}
    found = {}
    for name, parameter in inspect.signature(factory).parameters.items():
        default = parameter.default
        if default is inspect.Parameter.empty or default is None or name == "material":
            continue
        found[name] = list(default) if isinstance(default, tuple) else default
    return found


def _section_schema(keys: dict[str, Key], factory: Callable[..., Any] | None = None) -> dict:
    known = defaults(factory)
    properties = {}
    for name, key in keys.items():
        prop = {**KINDS[key.kind].json, "description": key.description}
        if name in known:
            prop["default"] = known[name]
        properties[name] = prop
    schema: dict[str, Any] = {
        "type": "object",
        "properties": properties,
        "additionalProperties": False,
    }
    required = [name for name, key in keys.items() if key.required]
    if required:
        schema["required"] = required
    return schema


def _typed(kind: str, factory: Callable[..., Any] | None, keys: dict[str, Key]) -> dict:
    schema = _section_schema(keys, factory)
    schema["properties"]["type"] = {"const": kind, "description": keys["type"].description}
    return schema


def _keyed(keys: dict[str, Key], *values: str) -> dict:
    """Return the schema of a key table, which must set at least one of ``values``."""
    schema = _section_schema(keys)
    schema["anyOf"] = [{"required": [name]} for name in values]
    return schema


def scene_json_schema() -> dict[str, Any]:
    """Return the JSON Schema (draft 2020-12) of scene files and of :meth:`Scene.to_dict`.

    Examples
    --------
    >>> from pixelpath.scene.schema import scene_json_schema
    >>> sorted(scene_json_schema()["properties"])
    ['ambient', 'animation', 'background', 'camera', 'encoding', 'lights', 'materials', 'objects']
    >>> sorted(scene_json_schema()["$defs"]["animation"]["properties"])
    ['camera', 'frames', 'interpolation', 'objects', 'turntable']
    """
    objects = [_typed(name, factory, keys) for name, (factory, keys) in OBJECTS.items()]
    mesh = objects[list(OBJECTS).index("mesh")]
    inline = [{"required": ["vertices"]}, {"required": ["faces"]}]
    mesh["oneOf"] = [
        {"required": ["path"], "not": {"anyOf": inline}},
        {"required": ["vertices", "faces"], "not": {"required": ["path"]}},
    ]
    top = _section_schema(TOP_LEVEL, Scene)
    top["properties"]["camera"] = {"$ref": "#/$defs/camera"}
    top["properties"]["lights"]["items"] = {
        "oneOf": [_typed(name, factory, keys) for name, (factory, keys) in LIGHTS.items()]
    }
    top["properties"]["materials"]["additionalProperties"] = {"$ref": "#/$defs/material"}
    top["properties"]["objects"]["items"] = {"oneOf": objects}
    animation = _section_schema(ANIMATION, Animation)
    animation["properties"]["camera"]["items"] = _keyed(
        CAMERA_KEY, "eye", "target", "fov", "view_height"
    )
    animation["properties"]["objects"]["items"] = _keyed(
        OBJECT_KEY, "translate", "rotate", "scale"
    )
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        "title": "pixelpath scene",
        "description": "A scene file of pixelpath (TOML), or the dict of Scene.to_dict().",
        **top,
        "$defs": {
            "camera": _section_schema(CAMERA, Camera),
            "material": _section_schema(MATERIAL, Material),
            "transform": _section_schema(TRANSFORM, transform_matrix),
            "animation": animation,
            "turntable": _section_schema(TURNTABLE, Turntable),
        },
    }
