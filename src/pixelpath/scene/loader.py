"""TOML scene files: ``load_scene``, and the dict form behind ``Scene.to_dict``/``Scene.from_dict``.

The format is defined in :mod:`pixelpath.scene.schema` and documented in ``docs/scene-format.md``.
The dependency runs one way: this module and the schema know the scene model, the model knows
nothing of its file format (``pixelpath.scene`` attaches :func:`scene_to_dict` and
:func:`scene_from_dict` to ``Scene`` as ``to_dict`` and ``from_dict``).
Every error is a ``ValueError`` (or ``FileNotFoundError`` for missing files) whose message names
the file, the key path (``objects[2].radius``) and, for files, the line near which the key is
written, then says what was expected. ``tomllib`` keeps no positions for parsed values, so the
line is found by looking for the key's section header and the key in the source text: "near
line N" is a pointer, not a guarantee. TOML syntax errors carry tomllib's own line and column.

Transforms (``transform = { translate, rotate, scale }``, see :func:`transform_matrix`) are
applied when the scene is built:

- spheres accept translation, rotation and *uniform* scale; other scales are rejected (use an
  ``icosphere`` object for an ellipsoid);
- planes accept any transform (point by the matrix, normal by its inverse transpose);
- boxes stay boxes under translation and scale; a rotated box becomes a 6-quad ``Mesh``;
- meshes, icospheres and tori are transformed vertex by vertex.
"""

from __future__ import annotations

import contextlib
import itertools
import os
import re
import tomllib
from collections.abc import Iterator
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from pixelpath.scene.animation import Animation, CameraKey, ObjectKey, Turntable
from pixelpath.scene.camera import Camera
from pixelpath.scene.lights import DirectionalLight
from pixelpath.scene.material import Material
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.primitives import Box, Plane, Sphere
from pixelpath.scene.scene import Scene
from pixelpath.scene.schema import (
    ANIMATION,
    CAMERA,
    CAMERA_KEY,
    KINDS,
    LIGHTS,
    MATERIAL,
    OBJECT_KEY,
    OBJECTS,
    TOP_LEVEL,
    TRANSFORM,
    TURNTABLE,
    Key,
)
from pixelpath.scene.transform import transform_matrix, transform_object

# The suffixes load_scene reads as model files (pixelpath.io.models), not as TOML.
MODEL_FORMATS = (".glb", ".gltf", ".obj", ".ply", ".stl")

KeyPath = tuple[str | int, ...]


def load_scene(path: str | Path, *, up: str = "+y") -> Scene:
    r"""Read a TOML scene file (mesh paths in it are relative to its folder) or a model file.

    Parameters
    ----------
    path : str or Path
        The ``.toml`` scene file, or a ``.glb``, ``.gltf``, ``.obj``, ``.ply`` or ``.stl``
        model file, read by :func:`pixelpath.io.models.read_model` (its parts, camera and
        lights, or a camera framing it and a light rig).
    up : str
        A model file's up axis (``"+y"``, ``"+z"``, ... see
        :func:`~pixelpath.io.models.read_model`): ``"z"`` for most CAD and 3D-printing
        files, which otherwise show their top to the camera. Scene files say where things
        are themselves: for them only ``"+y"`` is accepted.

    Returns
    -------
    Scene

    Raises
    ------
    FileNotFoundError
        When the scene file or a mesh file it names does not exist.
    ValueError
        For TOML syntax errors, unknown or missing keys and invalid values; the message names
        the file, the key and the line near which it is written.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pixelpath.scene import load_scene
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "scene.toml"
    >>> _ = path.write_text(
    ...     '[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n'
    ...     '[[objects]]\ntype = "sphere"\ncenter = [0, 0, 0]\nradius = 1\n'
    ... )
    >>> load_scene(path).objects[0].radius
    1.0
    """
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{path} is a folder; name a scene or model file in it")
    if not path.is_file():
        raise FileNotFoundError(f"scene file not found: {path}")
    if path.suffix.lower() in MODEL_FORMATS:
        from pixelpath.io.models import _model_scene  # it builds on this package: import late

        return _model_scene(path, up=up)  # read_model without checking the path again
    if up != "+y":  # checked as for a model file, then refused unless it names +Y
        from pixelpath.io.models import up_axis

        if up_axis(up) != "+y":
            raise ValueError(f"{path}: up={up!r} applies to model files "
                             f"({', '.join(MODEL_FORMATS)}); a scene file places its objects "
                             "itself")
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise ValueError(
            f"{path}: not a UTF-8 text file ({exc.reason}), so not a TOML scene file; model "
            f"files are read by their suffix: {', '.join(MODEL_FORMATS)}"
        ) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: invalid TOML: {exc}") from None
    return scene_from_dict(data, path.parent, source=_Source(str(path), text))


class _Source:
    """Where a scene dict came from, to name the file, the key and its line in messages."""

    def __init__(self, label: str, text: str | None = None) -> None:
        self.label = label
        self.lines = [] if text is None else text.splitlines()

    def where(self, path: KeyPath) -> str:
        key = _key_text(path)
        line = self._line_of(path) if self.lines else None
        return f"{self.label}: {key}" + (f" (near line {line})" if line else "")

    def error(self, path: KeyPath, message: str, kind: type[Exception] = ValueError) -> Exception:
        return kind(f"{self.where(path)}: {message}")

    def _line_of(self, path: KeyPath) -> int | None:
        """1-based line of the key ``path``: its section header, then the keys below it."""
        start, stop, found = self._section(path)
        if start is None:
            return None
        rest = [part for part in path[found:] if isinstance(part, str)]
        line = start if found else None
        for key in rest:
            pattern = re.compile(rf"(^|[\s{{,]){re.escape(key)}\s*=")
            hit = next((i for i in range(start, stop) if pattern.search(self.lines[i])), None)
            if hit is None:
                break
            line = start = hit
        return None if line is None else line + 1

    def _section(self, path: KeyPath) -> tuple[int | None, int, int]:
        """Return (first line, end line, path parts consumed) of the section holding ``path``.

        The longest leading run of names (and the index after it) that has a header wins:
        ``("animation", "camera", 2, "eye")`` is under the third ``[[animation.camera]]``,
        ``("materials", "red", "ks")`` under ``[materials.red]``.
        """
        headers = [i for i, text in enumerate(self.lines) if text.lstrip().startswith("[")]
        names = list(itertools.takewhile(lambda part: isinstance(part, str), path))
        for count in range(len(names), 0, -1):
            dotted = r"\s*\.\s*".join(rf'"?{re.escape(name)}"?' for name in names[:count])
            indexed = count < len(path) and isinstance(path[count], int)
            if indexed:
                pattern, occurrence, used = rf"\[\[\s*{dotted}\s*\]\]", path[count], count + 1
            else:
                pattern, occurrence, used = rf"\[\s*{dotted}\s*\]", 0, count
            matches = [i for i in headers if re.match(pattern, self.lines[i].strip())]
            if occurrence < len(matches):
                start = matches[occurrence]
                stop = next((i for i in headers if i > start), len(self.lines))
                return start, stop, used
            if indexed:  # an array element whose header is missing: no line to point at
                return None, 0, 0
        return 0, headers[0] if headers else len(self.lines), 0  # top-level keys come first


def _key_text(path: KeyPath) -> str:
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else part)
    return text or "(top level)"


@contextlib.contextmanager
def _reported(source: _Source, path: KeyPath, table: dict | None = None) -> Iterator[None]:
    """Re-raise a constructor's ValueError/TypeError with the file, key and line in front."""
    try:
        yield
    except (ValueError, TypeError) as exc:
        message = str(exc)
        # "camera[2]: frame 0 is ..." names an element of an array of tables in ``table``
        element = re.match(r"(\w+)\[(\d+)\]: ", message)
        if element and table and isinstance(table.get(element[1]), list):
            name, index = element[1], int(element[2])
            path, table = (*path, name, index), table[name][index]
            message = message[element.end() :]
        first_word = message.split(" ", 1)[0].split("[", 1)[0].rstrip(":")
        # "radius must be positive" -> objects[i].radius; "face 3 refers to ..." -> .faces
        key = next((k for k in (first_word, first_word + "s") if table and k in table), None)
        if key is not None:
            path = (*path, key)
        raise source.error(path, message, type(exc)) from None


def _checked(table: Any, keys: dict[str, Key], path: KeyPath, source: _Source) -> dict[str, Any]:
    """Return ``table`` once it has only known keys, the required ones, each of its kind."""
    if not isinstance(table, dict):
        raise source.error(path, f"expected a table, got {_shown(table)}")
    for name in table:
        if name not in keys:
            raise source.error(
                (*path, name), f"unknown key; expected one of: {', '.join(sorted(keys))}"
            )
    for name, key in keys.items():
        if name not in table:
            if key.required:
                raise source.error(path, f"missing key {name!r} ({key.description})")
            continue
        kind = KINDS[key.kind]
        if not kind.check(table[name]):
            got = _shown(table[name])
            raise source.error((*path, name), f"expected {kind.expected}, got {got}")
    return dict(table)


def _shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else f"a {type(value).__name__} ({text[:50]}...)"


def scene_from_dict(
    data: Any, base_dir: str | Path | None = None, *, source: _Source | None = None
) -> Scene:
    """Build a scene from a dict in the scene-file format (as ``tomllib`` or JSON give it).

    Also reached as ``Scene.from_dict(data, base_dir=None)``.

    Parameters
    ----------
    data : dict
        The scene (see ``docs/scene-format.md``).
    base_dir : str or Path, optional
        Folder that relative mesh paths start from (default: the working directory).

    Raises
    ------
    ValueError
        For unknown or missing keys and invalid values, naming the key path.

    Examples
    --------
    >>> from pixelpath.scene import Scene
    >>> scene = Scene.from_dict({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}})
    >>> scene.camera.fov
    45.0
    """
    source = source or _Source("scene dict")
    base = Path.cwd() if base_dir is None else Path(base_dir)
    top = _checked(data, TOP_LEVEL, (), source)
    camera = _built(Camera, CAMERA, top["camera"], ("camera",), source)
    materials = {
        name: _built(partial(Material, name=name), MATERIAL, table, ("materials", name), source)
        for name, table in top.get("materials", {}).items()
    }
    lights = [
        _light(table, ("lights", i), source) for i, table in enumerate(top.get("lights", []))
    ]
    objects = []
    for i, table in enumerate(top.get("objects", [])):
        made = _object(table, ("objects", i), materials, base, source)
        objects.extend(made if isinstance(made, list) else [made])  # a model file's parts
    extras = {name: top[name] for name in ("ambient", "background", "encoding") if name in top}
    if "animation" in top:
        extras["animation"] = _animation(top["animation"], camera, objects, source)
    with _reported(source, (), extras):
        return Scene(camera, objects, lights, **extras)


def _animation(table: Any, camera: Camera, objects: list, source: _Source) -> Animation:
    """Build the ``[animation]`` table and check its keys against the scene."""
    path: KeyPath = ("animation",)
    values = _checked(table, ANIMATION, path, source)
    cameras = [
        _built(CameraKey, CAMERA_KEY, key, (*path, "camera", i), source)
        for i, key in enumerate(values.get("camera", []))
    ]
    moves = [
        _object_key(key, objects, (*path, "objects", i), source)
        for i, key in enumerate(values.get("objects", []))
    ]
    turntable = values.get("turntable")
    if turntable is not None:
        turntable = _built(Turntable, TURNTABLE, turntable, (*path, "turntable"), source)
    interpolation = values.get("interpolation", "linear")
    with _reported(source, path, values):
        animation = Animation(values["frames"], cameras, moves, turntable, interpolation)
        animation.check_scene(camera, objects)
    return animation


def _object_key(table: Any, objects: list, path: KeyPath, source: _Source) -> ObjectKey:
    values = _checked(table, OBJECT_KEY, path, source)
    values["object"] = _object_index(values["object"], objects, (*path, "object"), source)
    with _reported(source, path, values):
        return ObjectKey(**values)


def _object_index(ref: int | str, objects: list, path: KeyPath, source: _Source) -> int:
    """Return the index of the object ``ref`` names: an index, or a unique mesh name."""
    if isinstance(ref, int):
        if not 0 <= ref < len(objects):
            raise source.error(
                path, f"no object {ref}: [[objects]] are numbered 0..{len(objects) - 1}"
            )
        return ref
    found = [i for i, obj in enumerate(objects) if getattr(obj, "name", None) == ref]
    if len(found) != 1:
        names = sorted({obj.name for obj in objects if getattr(obj, "name", None)})
        problem = "no object is" if not found else f"{len(found)} objects are"
        raise source.error(
            path,
            f"{problem} named {ref!r}; use an index or one of the names: "
            f"{', '.join(names) or 'none'}",
        )
    return found[0]


def _built(factory: Any, keys: dict[str, Key], table: Any, path: KeyPath, source: _Source) -> Any:
    values = _checked(table, keys, path, source)
    with _reported(source, path, values):
        return factory(**values)


def _light(table: Any, path: KeyPath, source: _Source) -> Any:
    kind = _type_of(table, LIGHTS, path, source)
    factory, keys = LIGHTS[kind]
    values = _checked(table, keys, path, source)
    del values["type"]
    with _reported(source, path, values):
        return factory(**values)


def _type_of(table: Any, choices: dict[str, Any], path: KeyPath, source: _Source) -> str:
    if not isinstance(table, dict):
        raise source.error(path, f"expected a table, got {_shown(table)}")
    expected = ", ".join(repr(name) for name in choices)
    if "type" not in table:
        raise source.error(path, f"missing key 'type'; expected one of {expected}")
    if not isinstance(table["type"], str):  # a list or table is unhashable: say so plainly
        raise source.error((*path, "type"), f"expected a string, got {_shown(table['type'])}")
    if table["type"] not in choices:
        raise source.error((*path, "type"), f"unknown type {table['type']!r}; expected {expected}")
    return table["type"]


def _object(
    table: Any, path: KeyPath, materials: dict[str, Material], base: Path, source: _Source
) -> Any:
    kind = _type_of(table, OBJECTS, path, source)
    values = _checked(table, OBJECTS[kind][1], path, source)
    spec = dict(values)
    del values["type"]
    named = values.get("material")
    material = _material(values.pop("material", None), materials, (*path, "material"), source)
    matrix = None
    if "transform" in values:
        transform = _checked(values.pop("transform"), TRANSFORM, (*path, "transform"), source)
        with _reported(source, (*path, "transform"), transform):
            matrix = transform_matrix(**transform)
    spec.pop("material", None)
    with _reported(source, path, spec):
        if kind == "mesh" and _is_model(values.get("path"), base, named):
            override = None if named is None else material
            return _model_parts(values, override, matrix, spec, base, path, source)
        if kind == "mesh":
            return _mesh(values, material, matrix, spec, base, path, source)
        return _MAKERS[kind](values, material, matrix, spec)


def _material(
    value: Any, materials: dict[str, Material], path: KeyPath, source: _Source
) -> Material:
    if value is None:
        return Material()
    if isinstance(value, dict):
        return _built(Material, MATERIAL, value, path, source)
    if value not in materials:
        defined = ", ".join(sorted(materials)) or "none"
        raise source.error(path, f"unknown material {value!r}; defined materials: {defined}")
    return materials[value]


def _placed(factory: Any) -> Any:
    """Return a maker that builds an analytic object, then applies its transform."""

    def make(values: dict, material: Material, matrix: Any, spec: dict) -> Any:
        obj = factory(material=material, **values)
        if matrix is None:
            return obj
        moved = transform_object(obj, matrix)
        if isinstance(moved, Mesh):  # a rotated box
            return moved._label(name=moved.name, source=spec)
        return moved

    return make


def _generated(factory: Any) -> Any:
    def make(values: dict, material: Material, matrix: Any, spec: dict) -> Mesh:
        name = values.pop("name", None)
        mesh = factory(material=material, **values)
        if matrix is not None:
            mesh = mesh.transformed(matrix)
        return mesh._label(name=name or mesh.name, source=spec)

    return make


def _mesh(
    values: dict,
    material: Material,
    matrix: Any,
    spec: dict | None,
    base: Path,
    path: KeyPath,
    source: _Source,
) -> Mesh:
    inline = {"vertices", "faces"} & set(values)
    if ("path" in values) == bool(inline) or len(inline) == 1:
        raise ValueError("a mesh needs either 'path' or both 'vertices' and 'faces'")
    name = values.pop("name", None)
    if "path" in values:
        if "normals" in values:
            raise ValueError("'normals' is only for inline meshes (a file brings its own)")
        file = (base / values["path"]).resolve()
        spec["path"] = file
        try:
            mesh = Mesh.load(file, material)
        except FileNotFoundError as exc:
            raise source.error((*path, "path"), str(exc), FileNotFoundError) from None
    else:
        mesh = Mesh(values["vertices"], values["faces"], material, values.get("normals"))
        spec = None  # inline meshes are written back from their arrays
    if matrix is not None:
        mesh = mesh.transformed(matrix)
    return mesh._label(name=name or mesh.name, source=spec)


def _is_model(name: Any, base: Path, material: Any) -> bool:
    """Whether a mesh ``path`` is read as a model file (parts with their own materials).

    glTF files always are; an OBJ is when it names an MTL file and the scene gives no
    ``material`` (otherwise it is one mesh with its polygon faces, as PLY and STL files are).
    """
    if not isinstance(name, str):
        return False
    suffix = Path(name).suffix.lower()
    if suffix in (".glb", ".gltf"):
        return True
    if suffix != ".obj" or material is not None:
        return False
    try:
        with (base / name).open("rb") as file:
            return any(line.lstrip().startswith(b"mtllib") for line in file)
    except OSError:
        return False  # the mesh reader reports the missing file with its key and line


def _model_parts(
    values: dict,
    material: Material | None,
    matrix: Any,
    spec: dict,
    base: Path,
    path: KeyPath,
    source: _Source,
) -> list[Mesh]:
    """Read a model file named by a mesh object: one mesh per part, named ``name/part``."""
    if "normals" in values or {"vertices", "faces"} & set(values):
        raise ValueError("a mesh with a 'path' takes no 'vertices', 'faces' or 'normals'")
    from pixelpath.io.models import read_model_objects  # it builds on this package

    file = (base / values["path"]).resolve()
    spec["path"] = file
    try:
        parts = read_model_objects(file, material)
    except FileNotFoundError as exc:
        raise source.error((*path, "path"), str(exc), FileNotFoundError) from None
    prefix = values.get("name")
    parts = [part if matrix is None else part.transformed(matrix) for part in parts]
    spec["_model"] = {"first": parts[0], "own_materials": material is None}
    # all parts share one spec: Scene.to_dict writes the entry once
    return [part._label(name=f"{prefix}/{part.name}" if prefix else part.name, source=spec)
            for part in parts]


_MAKERS = {
    "sphere": _placed(Sphere),
    "plane": _placed(Plane),
    "box": _placed(Box),
    "icosphere": _generated(OBJECTS["icosphere"][0]),
    "torus": _generated(OBJECTS["torus"][0]),
}


def scene_to_dict(scene: Scene, base_dir: str | Path | None = None) -> dict[str, Any]:
    """Return the scene as a dict of plain values in the scene-file format.

    Also reached as ``scene.to_dict(base_dir=None)``. The dict holds only str, float, int,
    list and dict values, so it can be written as JSON or TOML, and
    ``Scene.from_dict(scene.to_dict())`` rebuilds an equal scene. Meshes read from a file, and
    generated ones (icosphere, torus, rotated box) that came from a scene file, are written as
    their file path or parameters with their transform; other meshes are written inline
    (vertices, faces, normals). Materials other than the default are gathered under
    ``materials`` as ``material1``, ``material2``, ...

    Parameters
    ----------
    scene : Scene
    base_dir : str or Path, optional
        Write mesh paths relative to this folder (default: absolute paths).

    Examples
    --------
    >>> from pixelpath.scene import Camera, Scene, Sphere
    >>> scene = Scene(Camera(eye=(0, 0, 5), target=(0, 0, 0)), [Sphere((0, 0, 0), 1.0)])
    >>> scene.to_dict()["objects"]
    [{'type': 'sphere', 'center': [0.0, 0.0, 0.0], 'radius': 1.0}]
    >>> Scene.from_dict(scene.to_dict()) == scene
    True
    """
    materials: dict[str, Material] = {}
    objects = [
        _object_dict(obj, materials, base_dir) for obj in scene.objects if not _later_part(obj)
    ]
    ambient = scene.ambient.tolist()
    data: dict[str, Any] = {
        "camera": {
            name: _plain(getattr(scene.camera, name))
            for name in CAMERA
            if getattr(scene.camera, name) is not None  # a perspective camera's view_height
        },
        "ambient": ambient[0] if len(set(ambient)) == 1 else ambient,
        "background": scene.background.tolist(),
        "lights": [_light_dict(light) for light in scene.lights],
    }
    if materials:
        data["materials"] = {name: _set_fields(material, MATERIAL)
                             for name, material in materials.items()}
    data["objects"] = objects
    if scene.animation is not None:
        data["animation"] = _animation_dict(scene.animation)
    if scene.encoding != "linear":
        data["encoding"] = scene.encoding
    return data


def _animation_dict(animation: Animation) -> dict[str, Any]:
    data: dict[str, Any] = {"frames": animation.frames, "interpolation": animation.interpolation}
    for name, keys, fields in (
        ("camera", animation.camera, CAMERA_KEY),
        ("objects", animation.objects, OBJECT_KEY),
    ):
        if keys:
            data[name] = [_set_fields(key, fields) for key in keys]
    if animation.turntable is not None:
        data["turntable"] = _set_fields(animation.turntable, TURNTABLE)
    return data


def _set_fields(record: Any, fields: dict[str, Key]) -> dict[str, Any]:
    """Return the fields of ``record`` that are set (not None), as plain values."""
    values = {name: getattr(record, name) for name in fields}
    return {name: _plain(value) for name, value in values.items() if value is not None}


def _plain(value: Any) -> Any:
    return value.tolist() if isinstance(value, np.ndarray) else value


def _light_dict(light: Any) -> dict[str, Any]:
    kind = "directional" if isinstance(light, DirectionalLight) else "point"
    keys = [key for key in LIGHTS[kind][1] if key != "type"]
    return {"type": kind, **{key: _plain(getattr(light, key)) for key in keys}}


def _later_part(obj: Any) -> bool:
    """Whether ``obj`` is a model file's part other than its first (written with the first)."""
    model = (getattr(obj, "source", None) or {}).get("_model")
    return model is not None and model["first"] is not obj


def _object_dict(obj: Any, materials: dict[str, Material], base_dir: Any) -> dict[str, Any]:
    if isinstance(obj, Mesh):
        data = _mesh_dict(obj, base_dir)
        if obj.source is not None and obj.source.get("_model", {}).get("own_materials"):
            return data  # the parts keep the materials in their file
    else:
        kind = type(obj).__name__.lower()
        keys = [key for key in OBJECTS[kind][1] if key not in ("type", "material", "transform")]
        data = {"type": kind, **{key: _plain(getattr(obj, key)) for key in keys}}
    if obj.material != Material() or obj.material.name is not None:
        data["material"] = _material_name(obj.material, materials)
    return data


def _material_name(material: Material, materials: dict[str, Material]) -> str:
    """Return the name ``material`` is listed under, adding it (its own name first) if new."""
    for name, listed in materials.items():
        if listed == material and listed.name == material.name:
            return name
    name = material.name
    number = len(materials) + 1
    while name is None or name in materials:
        name, number = f"material{number}", number + 1
    materials[name] = material
    return name


def _mesh_dict(mesh: Mesh, base_dir: Any) -> dict[str, Any]:
    if mesh.source is not None:
        data = {key: value for key, value in mesh.source.items() if not key.startswith("_")}
        if "path" in data:
            data["path"] = _relative(Path(data["path"]), base_dir)
        return data
    data = {"type": "mesh", "vertices": mesh.vertices.tolist(), "faces": mesh.faces}
    if mesh.normals is not None:
        data["normals"] = mesh.normals.tolist()
    if mesh.name is not None:
        data["name"] = mesh.name
    return data


def _relative(path: Path, base_dir: Any) -> str:
    if base_dir is None:
        return path.as_posix()
    try:
        return Path(os.path.relpath(path, Path(base_dir).resolve())).as_posix()
    except ValueError:  # another drive on Windows: keep it absolute
        return path.as_posix()
