"""Model files (glTF/GLB, OBJ+MTL, PLY, STL) read through trimesh into a ready-to-render Scene.

trimesh does all the parsing; this module checks the file before trimesh sees it, walks the
node graph trimesh reads and maps what it finds onto pixelpath's scene model. For glTF it takes
the arrays, materials and node edges straight from trimesh's glTF reader (building trimesh's
mesh and scene objects from them would double the time to load), composing each node's world
transform as trimesh's scene graph does, to the bit.

What a model file gives (:func:`read_model`)
--------------------------------------------
- **Objects**: one :class:`~pixelpath.scene.Mesh` per glTF node and primitive (per material
  group for OBJ, per ``solid`` block of an ASCII STL file, as CAD programs write a part of
  several bodies), named after the glTF node, else its mesh, else "node <index>" (the STL
  solid's name), with the node's world transform applied; a node's second primitive is
  "<name>_1", its third "<name>_2", and so on. The graph is walked node by node (in the
  order of trimesh's ``scene.graph.nodes_geometry``), never through ``Scene.dump()``, which
  drops glTF ``COLOR_0`` stored beside a material. glTF triangles, strips and fans are drawn
  (trimesh leaves fans out: they are turned into triangles first); points and lines are not.
- **Skins**: a skinned mesh (glTF ``skins``, which trimesh ignores) is posed by its joints
  at the file's rest pose (linear blend skinning: the weights times ``world(joint) @
  inverseBindMatrix``, the skinned node's own transform ignored, as glTF asks), positions
  and normals; animations are not played.
- **Morph targets** (which trimesh ignores too): a mesh takes the shape of its default weights,
  ``base + sum(weight * target)`` for positions and normals, the weights the node's
  ``weights``, else its mesh's (all zero when neither has any: the base shape), before a skin
  poses it. Targets that move texture coordinates or colours are not applied, with a warning.
- **Instances** (``EXT_mesh_gpu_instancing``, which trimesh ignores as well): a node's mesh is
  drawn once per instance, at the node's world transform times the instance's translation,
  rotation and scale, and not at the node itself; instance k of a part called "tree" is
  called "tree[k]".
- **Normals**: those the file stores, turned by the node's inverse transpose. A glTF part
  without normals is drawn flat, as the glTF specification asks: unless it is planar, each
  triangle gets corners of its own carrying its face's normal (trimesh's own GLB files have
  no normals, so a CAD part exported by trimesh shows its flat faces, not smooth shading
  stretched across its edges). An OBJ, PLY or STL part without normals is smoothed within a
  crease angle of 50 degrees (:func:`~pixelpath.io.creases.crease_normals`): a scanned or
  finely tessellated surface gets the faces' area-weighted normals, as before (now also
  across texture seams, where trimesh splits vertices), while the sharp edges of a CAD part
  (an STL file's cube) stay sharp, its vertices split there. A zero
  vector in the file (some exporters write them at degenerate corners) becomes the faces'
  normal there, and non-finite ones drop the part's stored normals (as if it had none).
- **Texture coordinates**: pixelpath's uv have v up, (0, 0) the bottom-left of the image.
  trimesh already flips glTF's v when it loads a file (OBJ's is v up already), so its uv are
  used as they are (the tests pin this with a 2 x 2 texture in a hand-written glTF).
- **Colours**: glTF ``COLOR_0`` is linear (the glTF specification) and is used as it is; PLY
  and OBJ vertex colours are display values and are decoded from sRGB. A PLY file's face
  colours become vertex colours: every vertex's when all faces share one colour, else each
  face gets corners of its own (keeping the shared corners' normals). Textures are 8-bit sRGB
  pictures (decoded by :class:`~pixelpath.scene.Texture`). The scene's ``encoding`` is
  ``"srgb"``, so a saved picture looks like the model in other viewers.
- **Camera**: the file's first glTF camera (in scene order), at its node's world transform;
  perspective ``yfov`` (radians) becomes ``fov`` (degrees), ``aspectRatio`` sets the width
  beside a height of 600 pixels; orthographic ``ymag`` becomes ``view_height = 2 * ymag``,
  and ``xmag / ymag`` the aspect likewise.
  Otherwise :func:`framing_camera`: the model seen from the front (+Z, glTF's front) and
  22 degrees above, at the distance where the corners of its bounding box fill 90 % of the
  picture, near and far from its bounding sphere.
- **Up axis**: +Y, glTF's. ``read_model(path, up="+z")`` turns a file that stands on another
  axis (most CAD and 3D-printing files stand on +Z) so that it stands on +Y, its parts, camera
  and lights alike (:func:`up_turn`); nothing is guessed.
- **Lights**: glTF ``KHR_lights_punctual`` lights: ``point`` (and ``spot``, drawn as a point
  light) become :class:`~pixelpath.scene.PointLight`, ``directional`` become
  :class:`~pixelpath.scene.DirectionalLight` along the node's -Z axis. pixelpath's lights
  have no fall-off, so a point light's candela are divided by its squared distance to the
  model's centre (a directional light's lux are used as they are), and all are scaled so that
  the brightest gives 1. Otherwise :func:`light_rig`: a key light above left of the camera, a
  fill light from its right, and a rim light from behind, with ambient 0.2.

Materials
---------
Every material gets ``ka = kd`` (so the ambient light shows the surface's colour), except
where an MTL file sets ``Ka`` above 0.

============================  =================================================================
File                          pixelpath ``Material``
============================  =================================================================
glTF ``baseColorFactor``      ``color`` = its RGB (linear); its alpha A gives ``alpha = A``
                              under ``alphaMode`` MASK and ``transparency = 1 - A`` under
                              BLEND
glTF ``baseColorTexture``     ``texture`` (sRGB); its alpha channel is dropped when the
                              ``alphaMode`` is OPAQUE (the default)
glTF ``metallicFactor`` m     ``kd = 1 - 0.6 m``; ``ks = (1 - r)^2 (0.25 + 0.75 m)``
glTF ``roughnessFactor`` r    ``shininess = clip(2 / r^4 - 2, 1, 1000)``; r = 1 (the default)
                              gives ``ks = 0``: no highlight
``metallicRoughnessTexture``  m and r are the factors times the picture's mean blue and
(glTF)                        green: one value per material, as the notes' model has (the
                              picture is decoded when the file is read); trimesh turns
                              ``KHR_materials_pbrSpecularGlossiness`` into these
glTF sampler of the           ``texture_wrap`` from ``wrapS``: REPEAT (10497, the default)
``baseColorTexture``          "repeat", CLAMP_TO_EDGE (33071) "clamp", MIRRORED_REPEAT
                              (33648) "mirror"; pixelpath has one wrap for both axes, so a
                              ``wrapT`` that differs gives a warning (once per material).
                              ``texture_filter`` from ``minFilter``: NEAREST (9728) "nearest"
                              when ``magFilter`` is NEAREST or absent ("bilinear" when it is
                              LINEAR), LINEAR (9729) "bilinear", the mipmap filters
                              (9984-9987) "trilinear", absent "trilinear" (glTF leaves the
                              choice to the viewer). No sampler: "repeat", "trilinear".
``EXT_texture_webp`` (glTF)   the WebP picture is the texture (trimesh reads it, Pillow
                              decodes it)
``KHR_texture_transform``     the base-colour texture's offset, rotation and scale, applied
(glTF)                        to the part's ``uv``
glTF ``texCoord`` of the      the part's ``uv`` are that set's (``TEXCOORD_1``, ...; the
``baseColorTexture``          transform's own ``texCoord`` overrides it); a mesh without the
                              set gives a warning, and set 0 is used
glTF ``doubleSided``          ``double_sided``
glTF ``emissiveFactor``       ``emission`` = the factor × ``KHR_materials_emissive_strength``
                              (1 when absent), linear
MTL ``Ke``                    ``emission`` (decoded from sRGB)
glTF ``emissiveTexture``      ``emission_texture``, which scales ``emission`` point by
                              point, read through the part's texture coordinates (the base
                              colour's set and transform) with the base colour's sampler; one
                              that reads another set or is transformed otherwise is not
                              drawn, nor the colour it scales: a warning names the material
MTL ``map_Ke``                ``emission_texture`` (sRGB), scaling ``Ke``, when its ``-s``
                              and ``-o`` are ``map_Kd``'s (they move the part's texture
                              coordinates); otherwise, or when its file is missing, not
                              drawn, nor ``Ke``: a warning names the material
glTF ``normalTexture``,       not used (the notes' model has no such maps): the surface is
``occlusionTexture``          lit with its interpolated normals; other PBR extensions
                              (clearcoat, sheen, volume, ...) are not used either
glTF transmission             ``transparency`` = ``KHR_materials_transmission``'s
                              ``transmissionFactor`` (the ray tracer's refraction; its
                              texture is not used), ``ka`` and ``kd`` scaled by
                              ``1 - transparency``; ``ior`` 1.5 unless given below
``KHR_materials_ior`` (glTF)  ``ior`` (below 1, as glTF's 0: 1.5)
``KHR_materials_unlit``       ``ka = 1 / AMBIENT`` (5), ``kd = ks = 0``: the surface colour
(glTF)                        under the model's own ambient light (0.2) and no other light,
                              as the extension asks (a scene file with another ``ambient``
                              scales it)
glTF ``alphaMode``            OPAQUE: every alpha ignored (``alpha_cutoff = None``). MASK:
                              ``alpha_cutoff`` = ``alphaCutoff`` (0.5 when absent): where
                              A × texture alpha × ``COLOR_0`` alpha is below it the surface
                              is cut away, in every method and the ray tracer. BLEND is
                              drawn as MASK with ``alpha_cutoff = 0.5`` on the texture's and
                              ``COLOR_0``'s alpha (pixelpath does not blend: texels at least
                              half opaque are drawn opaque, the others cut), A going to the
                              ray tracer's ``transparency`` as above
MTL ``Kd``                    ``color`` (decoded from sRGB), ``kd = 1``
MTL ``Ka``                    ``ka`` = its mean when above 0 (0, a common export, would leave
                              the unlit side black: then ``ka = kd``)
MTL ``Ks``, ``Ns``            ``ks = mean(Ks) * min(1, Ns / 100)``, ``shininess = max(Ns, 1)``:
                              ``Ns 0`` means no highlight
MTL ``map_Kd``                ``texture`` (a missing file: a warning and ``Kd`` alone)
MTL ``d``                     ``transparency = 1 - d`` (``Tr`` is ignored: exporters disagree
                              on its meaning)
no material (PLY, STL, OBJ    light grey ``(0.8, 0.8, 0.8)``, ``kd = 1``, ``ks = 0.2``,
without ``.mtl``, glTF        ``shininess = 32``, texture coordinates or not; ``color`` white
without one)                  under vertex or face colours (they are the surface's colour)
                              and for a PLY file's ``comment TextureFile`` picture
                              (``texture``)
MTL ``map_Kd -s su sv``,      the part's ``uv`` scaled, then moved: u' = su u + ou,
``-o ou ov``                  v' = sv v + ov (as Blender's and three.js's importers read them)
MTL ``map_Kd -clamp on``      ``texture_wrap = "clamp"``
other MTL map options         not applied, with a warning naming them; the picture is read as
(``-bm``, ``-mm``, ...)       it is
============================  =================================================================

trimesh's materials do not say which glTF material they came from, so the sampler is found
through the material's name, as the texture check is: where several glTF materials share the
name (or several have none), which one a part uses is ambiguous and its texture keeps the
defaults ("trilinear", "repeat"). A sampler that is not valid glTF (a texture or sampler index
out of range, a value of the wrong type, an unknown filter or wrap code) is refused with a
``ValueError`` naming the file and the material.

Bad input
---------
Every problem is a ``ValueError`` (``TypeError`` for a wrong argument type) whose message starts
with the file's path:

- glTF buffer and image URIs must be ``data:`` URIs or relative paths inside the file's own
  folder: absolute paths, ``..`` escapes, ``file:``/``http:`` and other schemes are refused,
  checked on the glTF JSON before trimesh reads anything; trimesh then gets a resolver confined
  to the folder (an OBJ's ``mtllib`` and ``map_Kd`` go through it too).
- Extensions that trimesh cannot decode and the file requires (``KHR_draco_mesh_compression``
  without DracoPy, ``EXT_meshopt_compression``, ``KHR_texture_basisu``, ...) are named in the
  error, never loaded as empty geometry.
- Accessors claiming more data than their buffer views hold (a header that says 10^12
  vertices) are refused before anything is allocated. trimesh reads sparse accessors as if
  they were dense, and normalized integers (8- or 16-bit texture coordinates and colours) as
  the integers; those that primitives draw from are decoded first (sparse substitutions
  checked against their accessor's size and their buffer views' lengths), and so are the
  integer positions, normals and texture coordinates of ``KHR_mesh_quantization`` (as
  written by gltfpack and gltf-transform), whose node transforms scale them back.
- Truncated or corrupt files, undecodable textures, faces referring to missing vertices and
  non-finite positions are refused; a texture file that does not exist gives a warning and the
  material colour alone.
"""

from __future__ import annotations

import base64
import binascii
import dataclasses
import functools
import importlib.util
import io
import itertools
import json
import math
import os
import re
import struct
import warnings
from collections.abc import Hashable, Iterator
from pathlib import Path
from typing import Any, BinaryIO, NamedTuple
from urllib.parse import unquote

import numpy as np

from pixelpath import _validate as v
from pixelpath.io.creases import CREASE_ANGLE, crease_normals
from pixelpath.scene.camera import Camera
from pixelpath.scene.lights import DirectionalLight, PointLight
from pixelpath.scene.loader import MODEL_FORMATS
from pixelpath.scene.material import Material
from pixelpath.scene.mesh import Mesh, bounding_box, moved
from pixelpath.scene.scene import Scene
from pixelpath.scene.texture import MAX_SIDE, Texture, srgb_to_linear, wide_grey

__all__ = [
    "MODEL_FORMATS",
    "UP_AXES",
    "depth_range",
    "framing_camera",
    "framing_distance",
    "light_rig",
    "read_model",
    "read_model_objects",
    "up_axis",
    "up_turn",
]

DEFAULT_SIZE = (800, 600)
AMBIENT = 0.2
ELEVATION = 22.0  # degrees above the model's centre for the default camera
FILL = 0.9  # fraction of the picture the default camera lets the bounding box fill
MAX_ACCESSOR_COUNT = 100_000_000  # elements; far beyond any model a CPU renderer draws

# glTF extensions this loader handles (or that change nothing it reads); any other one a file
# *requires* is refused by name, as the glTF specification asks of loaders.
_KNOWN_REQUIRED = {
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_unlit",
    "KHR_mesh_quantization",  # integer vertex attributes, decoded to float32 before trimesh
    "KHR_texture_transform",  # applied to the base-colour texture's coordinates
    "EXT_texture_webp",  # trimesh (4.0 on) reads the WebP source, Pillow decodes it
    "EXT_mesh_gpu_instancing",  # its instances made nodes before trimesh reads the file
}
_COMPONENT_BYTES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
_TYPE_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*:")
_NUMBER_WORD = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def read_model(
    path: str | Path, *, size: tuple[int, int] | None = None, frame: bool = False,
    up: str = "+y",
) -> Scene:
    """Read a model file into a Scene: its parts, camera and lights, or good defaults.

    See the module's documentation for what each file feature becomes.

    Parameters
    ----------
    path : str or Path
        A ``.glb``, ``.gltf``, ``.obj`` (with its ``.mtl`` and textures), ``.ply`` or ``.stl``
        file.
    size : (int, int), optional
        Picture size (width, height) of the camera (default 800 x 600, or the glTF camera's
        aspect ratio at a height of 600).
    frame : bool
        Frame the model with :func:`framing_camera` even when the file has a camera.
    up : str
        The file's up axis: ``"+y"`` (the default: glTF's, and most OBJ and PLY files'),
        ``"+z"`` (most CAD and 3D-printing files), ``"+x"``, ``"-x"``, ``"-y"`` or ``"-z"``
        (``"z"`` for ``"+z"``, and so on). The model is turned so that this axis points up
        (+Y) before it is framed; see :func:`up_turn` for where its front ends up. A file's
        own camera and lights turn with it.

    Returns
    -------
    Scene
        With ``encoding="srgb"``.

    Raises
    ------
    FileNotFoundError
        When ``path`` does not exist.
    ValueError
        For unsupported formats and bad files (see the module's documentation); the message
        starts with the path.

    Examples
    --------
    >>> from pixelpath.io.models import read_model
    >>> scene = read_model("Duck.glb")  # doctest: +SKIP
    >>> [obj.name for obj in scene.objects]  # doctest: +SKIP
    ['LOD3spShape']
    >>> part = read_model("bracket.stl", up="z")  # doctest: +SKIP
    """
    return _model_scene(_model_path(path), size, frame, up)


def _model_scene(
    path: Path, size: tuple[int, int] | None = None, frame: bool = False, up: str = "+y"
) -> Scene:
    """:func:`read_model` of a ``path`` already checked (an existing file of a model format)."""
    axis = up_axis(up)  # a bad value is refused before the file is read
    objects, gltf = _read_objects(path)
    bounds = _bounds_of(objects)
    try:
        camera = _file_camera(gltf, bounds, size) if gltf and not frame else None
        lights = _file_lights(gltf, bounds) if gltf else []
    except (TypeError, ValueError, KeyError, AttributeError, IndexError) as exc:
        raise ValueError(f"{path}: a glTF camera or light is not valid ({exc})") from None
    if axis != "+y":
        turn = up_turn(axis)
        objects, camera, lights = _turned(turn, objects, camera, lights)
        bounds = np.sort(bounds @ turn[:3, :3].T, axis=0)  # the same box, its corners turned
    camera = camera or framing_camera(bounds, size or DEFAULT_SIZE)
    lights = lights or light_rig(camera)
    return Scene(camera, objects, lights, ambient=AMBIENT, encoding="srgb")


UP_AXES = ("+y", "+z", "+x", "-y", "-z", "-x")
# The rotation taking each up axis to +Y (rows: the new x, y and z). A Z-up file's front,
# which faces -Y (as CAD programs and Blender show it), comes to face +Z, where the framing
# camera stands; an X-up file's +Z side stays in front, and a -Y-up file is turned about Z.
# Each row is one axis, signed: the turned coordinates are the file's, exactly.
_UP_TURNS = {
    "+y": ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
    "+z": ((1, 0, 0), (0, 0, 1), (0, -1, 0)),
    "+x": ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    "-y": ((-1, 0, 0), (0, -1, 0), (0, 0, 1)),
    "-z": ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
    "-x": ((0, 1, 0), (-1, 0, 0), (0, 0, 1)),
}


def up_axis(up: Any) -> str:
    """Return ``up`` as one of :data:`UP_AXES` (``"z"`` is ``"+z"``), or raise.

    Examples
    --------
    >>> from pixelpath.io.models import up_axis
    >>> up_axis("z"), up_axis("-X")
    ('+z', '-x')
    """
    if not isinstance(up, str):
        raise TypeError(f"up must be a str such as '+z', got {type(up).__name__}")
    axis = up.strip().lower()
    axis = axis if axis[:1] in ("+", "-") else f"+{axis}"
    if axis not in _UP_TURNS:
        raise ValueError(f"up must be one of {', '.join(UP_AXES)} (or x, y, z), got {up!r}")
    return axis


def up_turn(up: str) -> np.ndarray:
    """Return the (4, 4) rotation that turns a model whose up axis is ``up`` to stand on +Y.

    A proper rotation (no mirror) whose entries are 0 and ±1, so turned coordinates are the
    file's own, reordered and negated. For ``"+z"``, (x, y, z) becomes (x, z, -y): the model's
    top faces up and its front (-Y, as CAD programs show it) faces +Z, the framing camera.

    Examples
    --------
    >>> from pixelpath.io.models import up_turn
    >>> (up_turn("z") @ [1.0, 2.0, 3.0, 1.0]).tolist()
    [1.0, 3.0, -2.0, 1.0]
    """
    turn = np.eye(4)
    turn[:3, :3] = _UP_TURNS[up_axis(up)]
    return turn


def _turned(
    turn: np.ndarray, objects: list[Mesh], camera: Camera | None,
    lights: list[PointLight | DirectionalLight],
) -> tuple[list[Mesh], Camera | None, list[PointLight | DirectionalLight]]:
    """Return the parts, the file's camera (or None) and its lights under ``turn``."""
    rotation = turn[:3, :3]
    if camera is not None:
        camera = dataclasses.replace(camera, eye=rotation @ camera.eye,
                                     target=rotation @ camera.target, up=rotation @ camera.up)
    lights = [
        dataclasses.replace(light, direction=rotation @ light.direction)
        if isinstance(light, DirectionalLight)
        else dataclasses.replace(light, position=rotation @ light.position)
        for light in lights
    ]
    return [mesh.transformed(turn) for mesh in objects], camera, lights


def read_model_objects(path: str | Path, material: Material | None = None) -> list[Mesh]:
    """Read a model file's parts as meshes (world transforms applied), for a scene file.

    Parameters
    ----------
    path : str or Path
        A model file, as for :func:`read_model`.
    material : Material, optional
        Replaces every part's own material.

    Returns
    -------
    list of Mesh

    Examples
    --------
    >>> from pixelpath.io.models import read_model_objects
    >>> len(read_model_objects("fuze.obj"))  # doctest: +SKIP
    1
    """
    if material is not None and not isinstance(material, Material):
        raise TypeError(f"material must be a Material, got {type(material).__name__}")
    objects, _ = _read_objects(_model_path(path))
    if material is None:
        return objects
    return [_with_material(mesh, material) for mesh in objects]


def _with_material(mesh: Mesh, material: Material) -> Mesh:
    return Mesh(mesh.vertices, mesh.faces, material, mesh.normals, mesh.colors, mesh.uv, mesh.name)


def _model_path(path: Any) -> Path:
    if not isinstance(path, str | Path):
        raise TypeError(f"path must be a str or Path, got {type(path).__name__}")
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"model file not found: {path}")
    if path.suffix.lower() not in MODEL_FORMATS:
        raise ValueError(
            f"{path}: unsupported model format {path.suffix!r}; expected one of "
            f"{', '.join(MODEL_FORMATS)}"
        )
    return path


def _read_objects(path: Path) -> tuple[list[Mesh], dict | None]:
    """Return the file's meshes and, for glTF, its checked JSON; every error names the file."""
    try:
        objects, gltf = _read_checked(path)
    except (ValueError, TypeError) as exc:
        if str(path) in str(exc):
            raise
        raise type(exc)(f"{path}: {exc}") from None
    except (KeyError, IndexError, AttributeError, OverflowError, struct.error) as exc:
        # a JSON value of an unexpected kind that slipped past the checks, found by fuzzing
        raise ValueError(f"{path}: malformed file ({type(exc).__name__}: {exc})") from None
    if not objects:
        raise ValueError(f"{path}: the file has no triangle meshes")
    return objects, gltf


def _read_checked(path: Path) -> tuple[list[Mesh], dict | None]:
    suffix = path.suffix.lower()
    if suffix == ".stl":  # no materials; a file of several solids gives one object each
        return _stl_objects(path), None
    if suffix in (".glb", ".gltf"):
        # the JSON is read and checked here, then handed to trimesh's reader with the buffers
        # its bufferViews read: each is read once
        with path.open("rb") as file:
            gltf, chunk = _checked_gltf(path, file)
            # a file that holds all its data reads no other: no resolver to make (25 µs)
            resolver = _confined_resolver(path) if _refers_to_files(gltf) else None
            read = functools.cache(lambda index: _buffer_bytes(path, gltf, index, file, chunk,
                                                               resolver))
            # the parts are named after the nodes trimesh read (instances are nodes of
            # their own)
            named, added = _decoded(path, gltf, read) or (gltf, None)
            given = _views_apart(path, named, added, lambda index, start, length: (
                _buffer_range(path, gltf, index, start, length, file, chunk, read)))
        parts = _trimesh_parts(path, resolver, given)
    else:
        resolver = _confined_resolver(path)
        gltf, named, parts = None, None, _trimesh_parts(path, resolver, None)
        _refuse_dropped_pictures(path, resolver, parts)
    if resolver is not None:
        if resolver.refused:
            raise ValueError(
                f"{path}: refers to {resolver.refused[0]!r}, outside the file's folder")
        for name in resolver.missing:
            warnings.warn(f"{path}: {name!r} not found; using the material colour",
                          stacklevel=3)
    return _meshes(path, parts, named, resolver), gltf


def _refuse_dropped_pictures(path: Path, resolver: Any, parts: list[_Part]) -> None:
    """Refuse an OBJ's or PLY's texture that trimesh read but could not decode.

    trimesh drops such a picture without a word (a corrupt file, or one larger than Pillow
    opens, 16384 x 16384 for one), and the part was drawn in its material colour alone. It
    reads through the resolver the material libraries and the pictures they name: a file it
    read that is not text, and that no part's material holds (dropped, or a material no face
    uses), is opened here and refused if Pillow cannot open it. Text is left alone: a material
    library whatever its name (Blender writes one with no material in it), or text named as a
    picture, which trimesh drops as before.
    """
    drawn = {_held_picture(part) for part in parts}
    for name, data in resolver.served.items():
        if name in drawn or _is_text(data):
            continue
        problem = _picture_problem(data)
        if problem is not None:
            raise ValueError(f"{path}: the texture {name!r} is not a picture pixelpath can "
                             f"read ({problem})")


def _held_picture(part: _Part) -> str | None:
    """Return the name trimesh read the picture of ``part``'s material by (None: it has none)."""
    image = getattr(getattr(part.visual, "material", None), "image", None)
    return getattr(image, "info", {}).get("file_path")


def _is_text(data: bytes) -> bool:
    """Whether ``data`` reads as UTF-8 text (a picture's first bytes never do)."""
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def _picture_problem(picture: bytes | Path) -> str | None:
    """Say why Pillow cannot open ``picture``, its bytes or its file (None when it can).

    Only the header is read: what Pillow checks when it opens a picture.
    """
    import PIL
    import PIL.Image

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", PIL.Image.DecompressionBombWarning)
            PIL.Image.open(io.BytesIO(picture) if isinstance(picture, bytes) else picture).close()
    except PIL.Image.DecompressionBombError as exc:
        return f"{exc} Reduce it: pixelpath draws at most {MAX_SIDE} texels on a side"
    except PIL.UnidentifiedImageError:  # its message names the BytesIO, not the file
        return "not in a picture format Pillow knows, or its header is corrupt"
    except (OSError, ValueError, SyntaxError) as exc:
        return str(exc)
    return None


def _refers_to_files(gltf: dict) -> bool:
    """Whether a checked glTF names a buffer or picture by a file's URI (not a data: URI)."""
    return any(
        "uri" in item and not item["uri"].startswith("data:")
        for kind in ("buffers", "images") for item in gltf.get(kind, [])
    )


def _stl_objects(path: Path) -> list[Mesh]:
    """Return an STL file's solids as meshes of the plain material, named after the solids."""
    from pixelpath.io.meshes import read_stl_solids

    meshes = []
    for name, vertices, faces in read_stl_solids(path):
        vertices, faces, normals, _, _ = _creased(vertices, faces, None, None, CREASE_ANGLE)
        meshes.append(Mesh(vertices, faces, _plain_material(), normals, name=name,
                           source={"path": path}))
    return meshes


class _Part(NamedTuple):
    """One drawable part as trimesh read it: a node's geometry and where the node is."""

    node: str
    geometry: str
    matrix: Any  # the node's world transform, 4 x 4
    vertices: Any
    faces: Any
    normals: Any  # as stored in the file, or None
    visual: Any  # trimesh's visual (its material and uv), or None
    colors: Any  # per-vertex colours as trimesh keeps them, or None
    face_colors: Any = None  # per-face colours (a PLY file's), or None


def _trimesh_parts(
    path: Path, resolver: Any, gltf: tuple[dict, list[bytes]] | None
) -> list[_Part]:
    """Return the parts trimesh reads from ``path``: from a glTF's checked JSON and buffers."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # trimesh's own warnings say nothing about our file
            if gltf is not None:
                return _gltf_parts(resolver, *gltf)
            return _scene_parts(path, resolver)
    except Exception as exc:  # trimesh's parsers raise anything on a broken file
        raise ValueError(
            f"{path}: trimesh could not read this file ({type(exc).__name__}: {exc})"
        ) from None


def _scene_parts(path: Path, resolver: Any) -> list[_Part]:
    """Return the parts of an OBJ or PLY file, from the scene trimesh builds."""
    import trimesh

    loaded = trimesh.load(path, force="scene", process=False, resolver=resolver)
    parts = []
    for node in loaded.graph.nodes_geometry:
        matrix, name = loaded.graph.get(node)
        geometry = loaded.geometry[name]
        if not hasattr(geometry, "faces"):
            continue  # points and paths have nothing to shade
        visual = geometry.visual
        colors = getattr(visual, "vertex_attributes", {}).get("color")
        kind = getattr(visual, "kind", None)
        if colors is None and kind == "vertex":
            colors = visual.vertex_colors
        face_colors = visual.face_colors if colors is None and kind == "face" else None
        normals = geometry.vertex_normals if "vertex_normals" in geometry._cache else None
        parts.append(_Part(node, name, matrix, geometry.vertices, geometry.faces, normals,
                           visual, colors, face_colors))
    return parts


def _gltf_parts(resolver: Any, gltf: dict, buffers: list[bytes]) -> list[_Part]:
    """Return the parts of a glTF file, from what trimesh's glTF reader makes of its JSON.

    trimesh's ``load_glb`` and ``load_gltf`` read the JSON and the buffers, then hand them to
    ``_read_buffers``; the JSON, already read and checked, is handed to it here, with the
    buffers read once (the JSON's second reading was a tenth of the Duck's load). The reader's
    own output (arrays, visuals and the node graph's edges) is used as it is: building
    trimesh's Trimesh and Scene objects from it would double the time to load.
    """
    from trimesh.exchange.gltf import _read_buffers
    from trimesh.visual.color import to_rgba

    if not gltf.get("meshes"):  # nodes alone (Blender's empties): the reader wants accessors
        return []
    loaded = _read_buffers(header=gltf, buffers=buffers, mesh_kwargs={}, resolver=resolver)
    geometries = loaded["geometry"]
    parent: dict[str, tuple[str, np.ndarray]] = {}
    named: dict[str, str] = {}
    order: dict[str, None] = {}  # nodes in the order trimesh's scene graph lists them
    for edge in loaded["graph"]:
        above, node = edge["frame_from"], edge["frame_to"]
        order.update({above: None, node: None})
        parent[node] = (above, edge.get("matrix", _IDENTITY))
        if "geometry" in edge:
            named[node] = edge["geometry"]
    parts = []
    known: dict[tuple, Any] = {}  # what _world_matrix found, for parts under the same nodes
    for node in order:
        name = named.get(node)
        kwargs = geometries.get(name) if name is not None else None
        if kwargs is None or "faces" not in kwargs:
            continue  # no geometry, or points and lines: nothing to shade
        visual = kwargs.get("visual")
        if visual is not None:  # COLOR_0 beside a material
            colors = visual.vertex_attributes.get("color")
        else:  # COLOR_0 alone, as trimesh's Trimesh would keep it
            colors = kwargs.get("vertex_colors")
            colors = None if colors is None else to_rgba(colors)
        normals = kwargs.get("vertex_normals")
        parts.append(
            _Part(
                _gltf_node(parent, node),
                name,
                _world_matrix(parent, node, known),
                kwargs["vertices"],
                kwargs["faces"],
                normals,
                visual,
                colors,
            )
        )
    return parts


def _gltf_node(parent: dict[str, tuple[str, np.ndarray]], frame: str) -> str:
    """Return the glTF node a part's frame stands for in trimesh's graph.

    A node whose mesh has several primitives gets a child frame per primitive, named
    "<node>_<six hex digits>"; the part is the node's all the same.
    """
    above = parent.get(frame, (None,))[0]
    if above is None or not frame.startswith(f"{above}_"):
        return frame
    suffix = frame[len(above) + 1 :]
    return above if len(suffix) == 6 and all(c in _HEX for c in suffix) else frame


_HEX = frozenset("0123456789abcdef")
_IDENTITY = np.eye(4)
_IDENTITY_BYTES = _IDENTITY.tobytes()
_ONES3 = np.ones(3)


def _world_matrix(
    parent: dict[str, tuple[str, np.ndarray]], node: str, known: dict[tuple, Any]
) -> np.ndarray:
    """Return ``node``'s world transform as trimesh's scene graph computes it, to the bit.

    ``known`` keeps, for the nodes' other parts, which edge matrices are identities and the
    transform of each chain of matrices, by the matrices' ids (they live as long as
    ``parent``): the primitives of one glTF mesh are parts under the same node.
    """
    chain = []
    while node in parent:
        node, matrix = parent[node]
        chain.append(matrix)
    if len(chain) > 1:  # trimesh drops identities and multiplies the rest, root first
        chain = [m for m in reversed(chain)
                 if not _once(known, ("identity", id(m)), _is_identity, m)] or [_IDENTITY]
    return _once(known, ("world", *map(id, chain)), _chain_product, chain)


def _chain_product(chain: list[np.ndarray]) -> np.ndarray:
    """Return the product of a node's chain of edge matrices, root first, as trimesh makes it."""
    from trimesh.transformations import fix_rigid

    matrix = np.linalg.multi_dot(chain) if len(chain) > 1 else chain[0]
    return fix_rigid(matrix, max_deviance=1e-5)  # trimesh repairs near-rigid transforms


def _is_identity(matrix: np.ndarray) -> bool:
    """Whether trimesh's scene graph takes the edge ``matrix`` for the identity (and drops it)."""
    if matrix.tobytes() == _IDENTITY_BYTES:  # the commonest edge, told at a tenth of the cost
        return True
    return not np.abs(matrix - _IDENTITY).max() > 1e-8


@functools.cache  # built on first use, once: trimesh imports slowly, and a class costs 40 µs
def _resolver_class() -> type:
    from trimesh.resolvers import FilePathResolver

    class ConfinedResolver(FilePathResolver):
        """trimesh's folder resolver that records names it refused or could not find."""

        def __init__(self, source: Path) -> None:
            super().__init__(str(source))
            self.refused: list[str] = []
            self.missing: list[str] = []
            self.served: dict[str, bytes] = {}  # what each name read gave

        def get(self, name: str) -> bytes:
            file = self.find(name)
            if file is None and name.lstrip().startswith("-"):
                # an .mtl map line's options (map_Kd -s 2 2 1 wood.png), which trimesh hands
                # on with the file name (the material applies them: _mtl_map)
                bare = _mtl_map_line(name)[0]
                file = self.find(bare) if bare else None
            if file is None:
                self.missing.append(name)
                raise FileNotFoundError(name)
            self.served[name] = file.read_bytes()
            return self.served[name]

        def find(self, name: str) -> Path | None:
            """Return the file ``name`` names in the model's folder (None: there is none)."""
            if _outside(name, Path(self.parent)):
                self.refused.append(name)
                raise ValueError(f"{name!r} is outside the model's folder")
            for candidate in (unquote(name.strip()), name.strip()):
                file = Path(self.parent) / candidate
                if file.is_file():
                    return file
            return None

    return ConfinedResolver


def _confined_resolver(path: Path) -> Any:
    return _resolver_class()(path)


# The options of an .mtl texture line and how many values each takes (-o, -s and -t one to
# three numbers), from the Wavefront MTL specification.
_MTL_OPTIONS = {"-blendu": 1, "-blendv": 1, "-boost": 1, "-cc": 1, "-clamp": 1, "-imfchan": 1,
                "-mm": 2, "-texres": 1, "-bm": 1, "-type": 1, "-o": 3, "-s": 3, "-t": 3}


def _mtl_map_line(line: str) -> tuple[str, list[tuple[str, list[str]]]]:
    """Split an .mtl texture line into its file name and its options with their values.

    ``"-s 2 2 1 -clamp on my wood.png"`` gives
    ``("my wood.png", [("-s", ["2", "2", "1"]), ("-clamp", ["on"])])``.
    """
    words = line.split()
    options = []
    k = 0
    while k < len(words) and words[k] in _MTL_OPTIONS:
        option, count = words[k], _MTL_OPTIONS[words[k]]
        k += 1
        if option in ("-o", "-s", "-t"):  # up to three numbers
            start = k
            while count and k < len(words) - 1 and _NUMBER_WORD.fullmatch(words[k]):
                k, count = k + 1, count - 1
            options.append((option, words[start:k]))
        else:
            options.append((option, words[k : k + count]))
            k += count
    return " ".join(words[k:]), options


class _MtlMap(NamedTuple):
    """What pixelpath applies of an .mtl texture line's options, and the options it does not."""

    scale: tuple[float, float]  # -s u v: uv scaled ...
    offset: tuple[float, float]  # -o u v: ... then moved (Blender's and three.js's reading)
    clamp: bool  # -clamp on: one copy of the picture, its edge texels beyond it
    ignored: str  # the other options, as the file writes them


def _mtl_map_of(source: Any, shared: dict) -> _MtlMap | None:
    """:func:`_mtl_map` of ``source``, worked out once per material (its parts and it share it)."""
    return _once(shared, ("mtl map", id(source)), _mtl_map, source)


def _mtl_map(source: Any) -> _MtlMap | None:
    """Return the options of the ``map_Kd`` line of ``source`` (an MTL material), if it has any.

    trimesh keeps the line's text after ``map_Kd``, options and file name, in the picture's
    ``info["file_path"]``.
    """
    image = getattr(source, "image", None)
    line = getattr(image, "info", {}).get("file_path")
    return _mtl_options(_mtl_map_line(line)[1] if isinstance(line, str) else [])


def _mtl_options(options: list[tuple[str, list[str]]]) -> _MtlMap | None:
    """Return what an .mtl texture line's ``options`` ask (None when there are none)."""
    if not options:
        return None
    given = dict(options)  # a repeated option: its last values count
    scale = [float(value) for value in given.get("-s", [])[:2]]
    offset = [float(value) for value in given.get("-o", [])[:2]]
    ignored = [" ".join([option, *values]) for option, values in options
               if option not in ("-s", "-o", "-clamp")]
    return _MtlMap(
        scale=(*scale, 1.0, 1.0)[:2],
        offset=(*offset, 0.0, 0.0)[:2],
        clamp=[value.lower() for value in given.get("-clamp", [])] == ["on"],
        ignored=" ".join(ignored),
    )


def _outside(uri: str, folder: Path) -> bool:
    """Whether ``uri`` (not a data: URI) names something outside ``folder``."""
    name = unquote(uri.strip())
    if _SCHEME.match(name) or name.startswith(("/", "\\")) or Path(name).is_absolute():
        return True
    root = folder.resolve()
    return not (root / name).resolve().is_relative_to(root)


# --- the glTF JSON, checked before trimesh reads anything ------------------------------------


class _GlbChunk(NamedTuple):
    """Where the chunk after a GLB's JSON lies in the file (its bytes left unread)."""

    start: int  # its data's first byte
    length: int
    type: int  # 0x004E4942 ("BIN"): buffer 0's bytes


_BIN = 0x004E4942


def _checked_gltf(path: Path, file: BinaryIO) -> tuple[dict, _GlbChunk | None]:
    """Return the glTF JSON of ``path``, open as ``file``, after the URI and size checks.

    And, for a GLB, where its chunk after the JSON lies (None for a .gltf or a GLB without).
    """
    glb = path.suffix.lower() == ".glb"
    header, chunk = _glb_parts(path, file) if glb else (file.read(), None)
    try:
        gltf = json.loads(header)
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{path}: the glTF JSON is not valid ({exc})") from None
    if not isinstance(gltf, dict):
        raise ValueError(f"{path}: the glTF JSON is not an object")
    asset = gltf.get("asset")
    version = asset.get("version", "2.0") if isinstance(asset, dict) else "2.0"
    if str(version).split(".", 1)[0] != "2":  # glTF 1.0 is another format
        raise ValueError(f"{path}: glTF version {version!r}; only glTF 2.0 is read")
    for kind in ("buffers", "images"):
        for item in _list(path, gltf, kind):
            uri = item.get("uri")
            if uri is None:
                continue
            if not isinstance(uri, str):
                raise ValueError(f"{path}: {kind} uri must be a string, got {uri!r}")
            if not uri.startswith("data:") and _outside(uri, path.parent):
                raise ValueError(
                    f"{path}: {kind[:-1]} URI {uri!r} points outside the file's folder; "
                    "only data: URIs and relative paths inside it are read"
                )
    _check_extensions(path, gltf)
    _check_accessors(path, gltf, None if chunk is None else chunk.length)
    for key in ("nodes", "meshes"):  # the parts' names are looked up in them
        _list(path, gltf, key)
    return gltf, chunk


def _glb_parts(path: Path, file: BinaryIO) -> tuple[bytes, _GlbChunk | None]:
    """Return a GLB's JSON chunk and where its next (binary) chunk lies (None: no such chunk).

    The chunk lengths are checked against the file's size; the binary chunk is left unread
    (:func:`_buffer_bytes` reads it).
    """
    size = os.fstat(file.fileno()).st_size
    head = file.read(20)
    if len(head) < 20 or head[:4] != b"glTF":
        raise ValueError(f"{path}: not a GLB file (no 'glTF' header)")
    version, length = struct.unpack("<II", head[4:12])
    if version != 2:
        raise ValueError(f"{path}: a GLB of version {version}; only glTF 2.0 is read")
    json_length, json_type = struct.unpack("<II", head[12:20])
    if length > size or json_type != 0x4E4F534A or 20 + json_length > size:
        raise ValueError(f"{path}: truncated or corrupt GLB (the chunk lengths do not fit)")
    header = file.read(json_length)
    rest = 20 + json_length  # where the binary chunk's header starts
    if size - rest < 8:
        return header, None
    chunk = _GlbChunk(rest + 8, *struct.unpack("<II", file.read(8)))
    if chunk.length > size - chunk.start:
        raise ValueError(f"{path}: truncated GLB (the binary chunk is cut short)")
    return header, chunk


def _list(path: Path, gltf: dict, key: str) -> list[dict]:
    items = gltf.get(key, [])
    if not isinstance(items, list) or not all(isinstance(item, dict) for item in items):
        raise ValueError(f"{path}: glTF {key!r} must be a list of objects")
    return items


def _check_extensions(path: Path, gltf: dict) -> None:
    required = gltf.get("extensionsRequired", [])
    if not isinstance(required, list):
        raise ValueError(f"{path}: glTF 'extensionsRequired' must be a list")
    known = _decodable_extensions()
    unsupported = [name for name in required if name not in known]
    if unsupported:
        raise ValueError(
            f"{path}: requires the glTF extension {', '.join(map(str, unsupported))}, which "
            "pixelpath (through trimesh) cannot decode; re-export the model without it "
            "(for example with gltf-transform)"
        )


@functools.cache  # looking for DracoPy costs 50 µs: once per process
def _decodable_extensions() -> frozenset[str]:
    """Return the required glTF extensions a file may name: those trimesh can decode here."""
    if importlib.util.find_spec("DracoPy") is not None:  # trimesh decodes Draco with it
        return frozenset({*_KNOWN_REQUIRED, "KHR_draco_mesh_compression"})
    return frozenset(_KNOWN_REQUIRED)


def _check_accessors(path: Path, gltf: dict, binary_length: int | None) -> None:
    """Refuse accessors that claim more elements than their data holds (absurd counts)."""
    views = _list(path, gltf, "bufferViews")
    buffers = _list(path, gltf, "buffers")
    for index, accessor in enumerate(_list(path, gltf, "accessors")):
        count = accessor.get("count", 0)
        if not isinstance(count, int) or not 0 <= count <= MAX_ACCESSOR_COUNT:
            raise ValueError(f"{path}: accessor {index} has an impossible count {count!r}")
        view_index = accessor.get("bufferView")
        if view_index is None:
            continue
        if not isinstance(view_index, int) or not 0 <= view_index < len(views):
            raise ValueError(f"{path}: accessor {index} names a missing bufferView")
        view = views[view_index]
        item = _COMPONENT_BYTES.get(accessor.get("componentType"), 0) * _TYPE_COMPONENTS.get(
            accessor.get("type"), 0
        )
        stride = view.get("byteStride") or item
        need = accessor.get("byteOffset", 0) + (count - 1) * stride + item if count else 0
        length = view.get("byteLength")
        if not isinstance(length, int) or not isinstance(need, int) or need > length:
            raise ValueError(
                f"{path}: accessor {index} claims {count} elements, more than its bufferView holds"
            )
        buffer = view.get("buffer")
        if not isinstance(buffer, int) or not 0 <= buffer < len(buffers):
            raise ValueError(f"{path}: bufferView {view_index} names a missing buffer")
        end = view.get("byteOffset", 0) + length
        size = buffers[buffer].get("byteLength", 0)
        if "uri" not in buffers[buffer] and binary_length is not None:
            size = min(size, binary_length) if isinstance(size, int) else binary_length
        if not isinstance(end, int) or not isinstance(size, int) or end > size:
            raise ValueError(f"{path}: bufferView {view_index} runs past the end of its buffer")


# --- accessors trimesh would misread: sparse, or normalized integers ---------------------------

_COMPONENT_DTYPES = {5120: "<i1", 5121: "<u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}
_INDEX_DTYPES = {5121: "<u1", 5123: "<u2", 5125: "<u4"}  # a sparse block's element indices
_NORMALIZABLE = (5120, 5121, 5122, 5123)  # the integer types an accessor may mark normalized


def _decoded(path: Path, gltf: dict, read: Any) -> tuple[dict, bytes] | None:
    """Return the glTF JSON, for trimesh to read, with the accessors it would misread decoded.

    trimesh reads an accessor's dense data (zeros where it has no bufferView), ignoring its
    ``sparse`` substitutions, and reads integers as they are, ignoring ``normalized``: texture
    coordinates in 8 or 16 bits (fractions of the type's range, as glTF allows) came out as
    0..255 or 0..65535, 16-bit colours were clipped, and ``KHR_mesh_quantization``'s integer
    positions, normals and texture coordinates were not floats. Each such accessor that a
    primitive draws from is decoded here (base values, substitutions, then integers as float32,
    normalized ones as fractions) into a new buffer, after the file's, that the accessor then
    reads (the node transforms that scale quantized positions back are applied as any node's).
    The meshes come with the texture coordinate sets their base colours read as set 0
    (:func:`_base_color_sets`), the skinned and morphed nodes posed (:func:`_posed_nodes`),
    and the instances of ``EXT_mesh_gpu_instancing`` made nodes (:func:`_instance_nodes`).
    ``read(index)`` returns the bytes of the file's buffer ``index``. Returned as the edited
    JSON and the new buffer's bytes; None when nothing needs it (the file is read as it is).
    """
    meshes = _base_color_sets(path, gltf)
    drawn = gltf if meshes is None else {**gltf, "meshes": meshes}
    misread = _misread_accessors(path, drawn)
    fans = [(m, k) for m, k, primitive in _primitives(drawn) if primitive.get("mode") == _FAN]
    posed = _posed_node_indices(path, gltf)
    instanced = [n for n, node in enumerate(_list(path, gltf, "nodes"))
                 if "mesh" in node and _INSTANCING in (node.get("extensions") or ())]
    if not misread and not fans and not posed and not instanced and meshes is None:
        return None
    accessors = list(gltf["accessors"])
    views = list(_list(path, gltf, "bufferViews"))
    buffers = _list(path, gltf, "buffers")
    data = bytearray()

    def stored(values: np.ndarray) -> int:
        """Append ``values`` to the new buffer; return the bufferView that reads them."""
        nonlocal data
        block = values.tobytes()
        views.append({"buffer": len(buffers), "byteOffset": len(data), "byteLength": len(block)})
        data += block + bytes(-len(block) % 4)  # the next block starts 4-byte aligned
        return len(views) - 1

    for index, as_float in misread.items():
        values, accessor = _decoded_accessor(path, gltf, index, read, as_float)
        accessors[index] = {**accessor, "bufferView": stored(values)}
    if fans or posed:
        meshes = meshes or _copied_meshes(path, gltf)
    for m, k in fans:
        primitive = meshes[m]["primitives"][k]
        triangles = _fan_triangles(path, drawn, primitive, read)
        if triangles is None:
            continue  # fewer than three corners: nothing to draw, as trimesh leaves it
        accessors.append({"bufferView": stored(triangles), "componentType": 5125,
                          "count": triangles.size, "type": "SCALAR"})
        meshes[m]["primitives"][k] = {**primitive, "indices": len(accessors) - 1,
                                      "mode": _TRIANGLES}
    nodes = _posed_nodes(path, gltf, posed, meshes, accessors, stored, read) if posed else None
    if instanced:
        nodes = _instance_nodes(path, gltf, instanced, nodes, read)
    edited = {**gltf, "accessors": accessors, "bufferViews": views,
              "buffers": [*buffers, {"byteLength": len(data)}]}
    if meshes is not None:
        edited["meshes"] = meshes
    if nodes is not None:
        edited["nodes"] = nodes
    return edited, bytes(data)


def _views_apart(
    path: Path, gltf: dict, added: bytes | None, cut: Any
) -> tuple[dict, list[bytes]]:
    """Return the JSON and buffers for trimesh's reader: each bufferView a buffer of its own.

    trimesh copies every bufferView out of its buffer, except one that is the whole buffer
    (slicing all of a bytes object returns the object). Handed buffers made of the views' bytes
    alone, it copies nothing, and a GLB's binary chunk is not read whole first (see
    :func:`_buffer_range`): loading the CesiumMilkTruck allocated twice its 0.5 MB file, which
    glibc, depending on the heap's layout, gave back to the system after each load and took
    again at the next, 264 page faults (half a millisecond) a load in some processes.
    ``added`` is the buffer :func:`_decoded` added after the file's (None when it added none);
    ``cut(index, start, length)`` returns bytes of the file's buffer ``index``, shorter than
    ``length`` where the buffer ends first. Only bufferViews read anything: a buffer no view
    reads is not read.
    """
    count = len(_list(path, gltf, "buffers"))
    own = count - (added is not None)  # the file's buffers; ``added``, if any, comes next
    views, buffers = [], []
    for index, view in enumerate(_list(path, gltf, "bufferViews")):
        buffer, start, length = view.get("buffer"), view.get("byteOffset", 0), view.get(
            "byteLength")
        if not (_is_int(buffer) and 0 <= buffer < count):
            raise ValueError(f"{path}: bufferView {index} names a missing buffer")
        if not (_is_int(start) and _is_int(length) and min(start, length) >= 0):
            raise ValueError(f"{path}: bufferView {index} has no valid byteOffset and byteLength")
        data = added[start : start + length] if buffer == own else cut(buffer, start, length)
        if len(data) != length:
            raise ValueError(f"{path}: bufferView {index} runs past the end of its buffer")
        views.append({**view, "buffer": index, "byteOffset": 0})
        buffers.append(data)
    return {**gltf, "bufferViews": views, "buffers": [{"byteLength": len(b)} for b in buffers]}, (
        buffers)


_INSTANCING = "EXT_mesh_gpu_instancing"
_INSTANCE_ATTRIBUTES = {"TRANSLATION": ("translation", "VEC3"),
                        "ROTATION": ("rotation", "VEC4"), "SCALE": ("scale", "VEC3")}


def _instance_nodes(
    path: Path, gltf: dict, instanced: list[int], nodes: list[dict] | None, read: Any
) -> list[dict]:
    """Return the nodes with each ``EXT_mesh_gpu_instancing`` instance a child node of its own.

    trimesh ignores the extension and drew the mesh once, at the node. glTF draws it once per
    instance, at the node's world transform times the instance's translation, rotation (a
    quaternion, x y z w) and scale: a child node with that TRS and the node's mesh (and morph
    weights) is drawn so, and the node keeps its other children but not its mesh. Instance
    k of a node called "tree" is called "tree[k]".
    """
    nodes = nodes or [dict(node) for node in _list(path, gltf, "nodes")]
    for n in instanced:
        node = nodes[n]
        where = f"node {n}: {_INSTANCING}"
        attributes = node["extensions"][_INSTANCING]
        attributes = attributes.get("attributes") if isinstance(attributes, dict) else None
        if not isinstance(attributes, dict):
            raise ValueError(f"{path}: {where} has no attributes object")
        trs = {}
        for name, (key, kind) in _INSTANCE_ATTRIBUTES.items():
            if name in attributes:
                accessor = _accessor_of(path, gltf, attributes[name], f"{where} {name}")
                if accessor.get("type") != kind:
                    raise ValueError(f"{path}: {where} {name} must be a {kind} accessor")
                values = _decoded_accessor(path, gltf, attributes[name], read, True)[0]
                trs[key] = values.astype(np.float64).tolist()
        counts = {len(values) for values in trs.values()}
        if len(counts) != 1:
            raise ValueError(f"{path}: {where} needs TRANSLATION, ROTATION or SCALE, each "
                             "with one value an instance")
        name = _instance_base_name(gltf, n)
        extra = {"weights": node["weights"]} if "weights" in node else {}
        children = node.get("children") if isinstance(node.get("children"), list) else []
        first = len(nodes)
        for k in range(counts.pop()):
            nodes.append({"name": f"{name}[{k}]", "mesh": node["mesh"], **extra,
                          **{key: values[k] for key, values in trs.items()}})
        node["children"] = [*children, *range(first, len(nodes))]
        del node["mesh"]
    return nodes


def _instance_base_name(gltf: dict, n: int) -> str:
    """Return what node ``n`` is called as a part: its name, else its mesh's, else "node n".

    The file's own node and mesh, not the posed copy a morphed node's mesh became.
    """
    node, meshes = gltf["nodes"][n], gltf.get("meshes", [])  # lists of objects (checked)
    mesh = node["mesh"]
    for name in (node.get("name"),
                 meshes[mesh].get("name") if _is_int(mesh) and 0 <= mesh < len(meshes) else None):
        if isinstance(name, str) and name:
            return name
    return f"node {n}"


def _posed_node_indices(path: Path, gltf: dict) -> list[int]:
    """Return the nodes whose mesh a skin poses or morph targets move (at non-zero weights)."""
    meshes = gltf.get("meshes", [])  # a list of objects (checked)
    return [n for n, node in enumerate(_list(path, gltf, "nodes"))
            if "mesh" in node and ("skin" in node or (
                _is_int(node["mesh"]) and 0 <= node["mesh"] < len(meshes)
                and _morph_weights(path, n, node, meshes[node["mesh"]])))]


def _morph_weights(path: Path, n: int, node: dict, mesh: dict) -> list[float] | None:
    """Return the weights of the morph targets node ``n`` draws ``mesh`` with; None if all 0.

    The node's ``weights``, else its mesh's, else zeros (the glTF defaults), one a target.
    """
    weights = node.get("weights", mesh.get("weights"))
    if weights is None:  # most meshes: looked at first, as every file's nodes are
        return None
    primitives = mesh.get("primitives")
    counts = {len(p["targets"]) if isinstance(p.get("targets"), list) else 0
              for p in (primitives if isinstance(primitives, list) else [])
              if isinstance(p, dict)}
    if counts <= {0}:
        return None
    if not (isinstance(weights, list) and counts == {len(weights)} and all(
            isinstance(w, int | float) and not isinstance(w, bool) and math.isfinite(w)
            for w in weights)):
        raise ValueError(f"{path}: node {n}: the morph weights must be one number for each "
                         f"morph target of every primitive, got {weights!r}")
    return weights if any(weights) else None


def _posed_nodes(
    path: Path, gltf: dict, posed: list[int], meshes: list[dict], accessors: list[dict],
    stored: Any, read: Any,
) -> list[dict]:
    """Pose the meshes of skinned and morphed nodes as the file leaves them; return the nodes.

    trimesh ignores skins and morph targets. Morph targets move a mesh's positions and normals
    by their weights (``base + sum(weight * target)``, glTF's rest shape where a weight is not
    0). A skinned mesh's vertices are in the skin's bind space, not in its node's frame: a
    rigged character could lie on its back. glTF places them by their joints alone (the
    skinned node's own transform is ignored): each vertex moves by the sum of its weights
    times ``world(joint) @ inverseBindMatrix`` of its joints (linear blend skinning), its
    normal by that matrix's linear part, after the morph targets. The posed positions and
    normals are written back in the node's frame (``inverse(world(node))``), so that
    trimesh's placing of the node leaves them where the joints put them. Each posed node gets
    a mesh of its own (appended to ``meshes``, read by the edited ``nodes`` returned).
    Animations are not played: the pose is that of the nodes and weights the file states.
    """
    nodes = [dict(node) for node in _list(path, gltf, "nodes")]
    skins = _list(path, gltf, "skins")
    world = _world_matrices(gltf)
    unmoved: set[str] = set()  # attributes morph targets move that pixelpath does not
    for n in posed:
        node = nodes[n]
        if n not in world:
            continue  # not in the scene: not drawn
        mesh = _item(meshes, node["mesh"], f"node {n}", "mesh", "meshes")
        weights = _morph_weights(path, n, node, mesh)
        matrices = None
        if "skin" in node:
            skin = _item(skins, node.pop("skin"), f"node {n}", "skin", "skins")
            matrices = _skin_matrices(path, gltf, skin, world, read)
        meshes.append({**mesh, "primitives": [
            _posed_primitive(path, gltf, primitive, weights, matrices, world[n], accessors,
                             stored, read, unmoved)
            if isinstance(primitive, dict) else primitive
            for primitive in mesh.get("primitives", [])
        ]})
        node["mesh"] = len(meshes) - 1
    if unmoved:
        warnings.warn(f"{path}: morph targets move {', '.join(sorted(unmoved))}, which "
                      "pixelpath does not morph (it morphs POSITION and NORMAL)", stacklevel=2)
    return nodes


def _skin_matrices(path: Path, gltf: dict, skin: dict, world: dict, read: Any) -> np.ndarray:
    """Return (J, 4, 4) ``world(joint) @ inverseBindMatrix`` for a skin's joints."""
    joints = skin.get("joints")
    if not isinstance(joints, list) or not joints:
        raise ValueError(f"{path}: a skin has no joints")
    missing = [joint for joint in joints if not (_is_int(joint) and joint in world)]
    if missing:
        raise ValueError(f"{path}: skin joint {missing[0]!r} is not a node of the scene")
    inverse = np.broadcast_to(np.eye(4), (len(joints), 4, 4))
    if skin.get("inverseBindMatrices") is not None:
        index = skin["inverseBindMatrices"]
        accessor = _accessor_of(path, gltf, index, "a skin's inverseBindMatrices")
        if accessor.get("type") != "MAT4" or accessor.get("count") != len(joints):
            raise ValueError(f"{path}: a skin's inverseBindMatrices must be a MAT4 accessor "
                             "with a matrix for each joint")
        values, _ = _decoded_accessor(path, gltf, index, read, True)
        inverse = values.astype(np.float64).reshape(-1, 4, 4).transpose(0, 2, 1)  # column-major
    return np.stack([world[joint] for joint in joints]) @ inverse


def _posed_primitive(
    path: Path, gltf: dict, primitive: dict, weights: list[float] | None,
    matrices: np.ndarray | None, node_world: np.ndarray, accessors: list[dict], stored: Any,
    read: Any, unmoved: set[str],
) -> dict:
    """Return ``primitive`` with its positions (and normals) morphed, then posed by a skin.

    ``weights`` are its morph targets' (None: not morphed), ``matrices`` its skin's joint
    matrices (None: no skin).
    """
    attributes = primitive.get("attributes")
    if not isinstance(attributes, dict) or "POSITION" not in attributes:
        return primitive

    def values(index: Any, name: str) -> np.ndarray:
        _accessor_of(path, gltf, index, f"attribute {name}")  # the file's own accessors
        return _decoded_accessor(path, gltf, index, read, True)[0].astype(np.float64)

    def morphed(name: str) -> np.ndarray:
        base = values(attributes[name], name)
        if weights is None:
            return base
        # every primitive has one target for each weight (_morph_weights)
        for weight, target in zip(weights, primitive["targets"], strict=True):
            if not isinstance(target, dict):
                raise ValueError(f"{path}: a morph target must be an object, got {target!r}")
            if weight:
                unmoved.update(key for key in target if key not in _MORPHED)
            if weight and name in target:
                moved = values(target[name], f"{name} of a morph target")
                if moved.shape != base.shape:
                    raise ValueError(f"{path}: a morph target's {name} does not match the "
                                     "primitive's vertices")
                base += weight * moved
        return base

    positions = morphed("POSITION")
    normals = morphed("NORMAL") if "NORMAL" in attributes else None
    if matrices is not None:
        positions, normals = _skinned(path, attributes, values, matrices, node_world,
                                      positions, normals)
    edited = dict(attributes)
    edited["POSITION"] = _new_accessor(accessors, stored, positions.astype("<f4"), "VEC3")
    if normals is not None:
        edited["NORMAL"] = _new_accessor(accessors, stored, normals.astype("<f4"), "VEC3")
    return {**primitive, "attributes": edited}


_MORPHED = frozenset({"POSITION", "NORMAL", "TANGENT"})  # TANGENT: pixelpath draws none


def _skinned(
    path: Path, attributes: dict, values: Any, matrices: np.ndarray, node_world: np.ndarray,
    positions: np.ndarray, normals: np.ndarray | None,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Return positions and normals posed by a skin's joint ``matrices``, in the node's frame."""
    blend = np.zeros((len(positions), 4, 4))
    for set_number in itertools.count():
        joints_name, weights_name = f"JOINTS_{set_number}", f"WEIGHTS_{set_number}"
        if joints_name not in attributes or weights_name not in attributes:
            break
        joints = values(attributes[joints_name], joints_name).astype(np.intp)
        weights = values(attributes[weights_name], weights_name)
        if joints.shape != weights.shape or len(joints) != len(positions):
            raise ValueError(f"{path}: {joints_name} and {weights_name} do not match the "
                             "vertices")
        if joints.min(initial=0) < 0 or joints.max(initial=0) >= len(matrices):
            raise ValueError(f"{path}: {joints_name} names a joint its skin lacks")
        blend += np.einsum("vi,vijk->vjk", weights, matrices[joints])
    unweighted = ~blend.any(axis=(1, 2))
    blend[unweighted] = node_world  # no weights: the node's own placement, as unskinned
    back = np.linalg.inv(node_world)
    local = back @ blend  # each vertex's matrix into the node's frame
    posed = np.einsum("vjk,vk->vj", local[:, :3, :3], positions) + local[:, :3, 3]
    if normals is not None:
        normals = np.einsum("vjk,vk->vj", blend[:, :3, :3], normals) @ node_world[:3, :3]
    return posed, normals


def _new_accessor(accessors: list[dict], stored: Any, values: np.ndarray, kind: str) -> int:
    """Append a float32 accessor reading ``values`` from the new buffer; return its index."""
    accessors.append({"bufferView": stored(values), "componentType": 5126,
                      "count": len(values), "type": kind})
    return len(accessors) - 1


_TRIANGLES, _FAN = 4, 6  # glTF primitive modes


def _primitives(gltf: dict) -> Iterator[tuple[int, int, dict]]:
    """Yield (mesh, primitive number, primitive) for every primitive that is an object."""
    for m, mesh in enumerate(gltf.get("meshes", [])):  # a list of objects (checked)
        primitives = mesh.get("primitives")
        for k, primitive in enumerate(primitives if isinstance(primitives, list) else []):
            if isinstance(primitive, dict):
                yield m, k, primitive


def _copied_meshes(path: Path, gltf: dict) -> list[dict]:
    """Return the glTF meshes copied down to their primitives, to edit those."""
    meshes = [dict(mesh) for mesh in _list(path, gltf, "meshes")]
    for mesh in meshes:
        if isinstance(mesh.get("primitives"), list):
            mesh["primitives"] = [dict(p) if isinstance(p, dict) else p
                                  for p in mesh["primitives"]]
    return meshes


def _accessor_of(path: Path, gltf: dict, index: Any, what: str) -> dict:
    """Return the file's accessor ``index`` that ``what`` names, refusing a missing one."""
    accessors = gltf["accessors"]
    if not (_is_int(index) and 0 <= index < len(accessors)):
        raise ValueError(f"{path}: {what} names a missing accessor")
    return accessors[index]


def _fan_triangles(path: Path, gltf: dict, primitive: dict, read: Any) -> np.ndarray | None:
    """Return the (n - 2, 3) uint32 triangles of a triangle fan: (c0, c_i, c_i+1).

    trimesh leaves fans (mode 6) out; the corners are the primitive's indices, or its vertices
    in order when it has none. None for a fan of fewer than three corners.
    """
    index = primitive.get("indices")
    if index is None:
        attributes = primitive.get("attributes")
        position = attributes.get("POSITION") if isinstance(attributes, dict) else None
        count = _accessor_of(path, gltf, position, "a triangle fan's POSITION").get("count", 0)
        corners = np.arange(count, dtype="<u4")
    else:
        _accessor_of(path, gltf, index, "a triangle fan's indices")
        corners = _dense_accessor(path, gltf, index, read)[:, 0].astype("<u4")
    if len(corners) < 3:
        return None
    triangles = np.empty((len(corners) - 2, 3), "<u4")
    triangles[:, 0] = corners[0]
    triangles[:, 1] = corners[1:-1]
    triangles[:, 2] = corners[2:]
    return triangles


def _base_color_sets(path: Path, gltf: dict) -> list[dict] | None:
    """Return the glTF meshes with each primitive's ``TEXCOORD_0`` the set its base colour reads.

    trimesh reads texture coordinates from set 0 alone; a material whose base-colour texture
    reads another set (``texCoord``, or ``KHR_texture_transform``'s own ``texCoord``, which
    overrides it) gets that set's accessor as set 0. None when every primitive reads set 0. A
    primitive without the set keeps set 0, with a warning.
    """
    materials = _list(path, gltf, "materials")
    sets = [_texture_set(material) for material in materials]
    if not any(sets):
        return None
    meshes = _copied_meshes(path, gltf)
    for number, _, primitive in _primitives({"meshes": meshes}):
        material, attributes = primitive.get("material"), primitive.get("attributes")
        if not (_is_int(material) and 0 <= material < len(sets) and sets[material]
                and isinstance(attributes, dict)):
            continue
        name = f"TEXCOORD_{sets[material]}"
        if name in attributes:
            primitive["attributes"] = {**attributes, "TEXCOORD_0": attributes[name]}
        else:
            warnings.warn(
                f"{path}: mesh {number}: material {materials[material].get('name')!r} "
                f"reads texture coordinates {name}, which the mesh lacks; set 0 is used",
                stacklevel=4,
            )
    return meshes


def _texture_set(material: dict) -> int:
    """Return the texture coordinate set a glTF material's base-colour texture reads."""
    pbr = material.get("pbrMetallicRoughness")
    return _reference_set(pbr.get("baseColorTexture") if isinstance(pbr, dict) else None)


def _reference_set(ref: Any) -> int:
    """Return the texture coordinate set a glTF texture reference reads (0 for none)."""
    if not isinstance(ref, dict):
        return 0
    transform = _reference_transform(ref)
    number = ref.get("texCoord", 0)
    if isinstance(transform, dict) and "texCoord" in transform:
        number = transform["texCoord"]
    return number if _is_int(number) and number > 0 else 0


def _reference_transform(ref: Any) -> Any:
    """Return a glTF texture reference's ``KHR_texture_transform`` (None when it has none)."""
    extensions = ref.get("extensions") if isinstance(ref, dict) else None
    return extensions.get("KHR_texture_transform") if isinstance(extensions, dict) else None


def _misread_accessors(path: Path, gltf: dict) -> dict[int, bool]:
    """Return the accessors primitives draw from that trimesh would misread.

    Each maps to whether its values become float32: sparse ones (their type kept, unless they
    are also one of the next kinds); integer positions, normals, tangents and texture
    coordinates (``KHR_mesh_quantization``'s, normalized or not); normalized integer colours
    (but for 8-bit ones, which trimesh takes as fractions of 255 already).
    """
    accessors = _list(path, gltf, "accessors")
    if not any("sparse" in accessor or (accessor.get("componentType") in _NORMALIZABLE
                                        and accessor.get("type") != "SCALAR")
               for accessor in accessors):
        return {}  # only float attributes (and integer indices): nothing to decode
    misread: dict[int, bool] = {}
    for _, _, primitive in _primitives(gltf):
        attributes = primitive.get("attributes")
        used = [*attributes.items()] if isinstance(attributes, dict) else []
        for name, index in [*used, ("indices", primitive.get("indices"))]:
            if not (_is_int(index) and 0 <= index < len(accessors)):
                continue
            accessor = accessors[index]
            as_float = _misread_as_integers(name, accessor)
            if "sparse" in accessor or as_float:
                misread[index] = misread.get(index, False) or as_float
    return misread


_QUANTIZABLE = ("POSITION", "NORMAL", "TANGENT")  # and TEXCOORD_n: KHR_mesh_quantization's


def _misread_as_integers(name: Any, accessor: dict) -> bool:
    """Whether trimesh would misread an attribute's integers (to be decoded as float32).

    They stand for fractions (normalized) or for coordinates trimesh must get as floats
    (quantized).
    """
    kind = accessor.get("componentType")
    if kind not in _NORMALIZABLE or not isinstance(name, str):
        return False
    if name in _QUANTIZABLE or name.startswith("TEXCOORD_"):
        return True
    return name.startswith("COLOR_") and accessor.get("normalized") is True and kind != 5121


def _decoded_accessor(
    path: Path, gltf: dict, index: int, read: Any, as_float: bool
) -> tuple[np.ndarray, dict]:
    """Return accessor ``index``'s values (count, components) and its JSON to read them by.

    The values are its base data with its sparse substitutions made and, ``as_float``, as
    float32: normalized integers as the fractions they stand for (c / (2^b - 1) unsigned,
    max(c / (2^(b-1) - 1), -1) signed, the glTF rule), others as they are. The JSON has no
    ``sparse`` or ``byteOffset`` left.
    """
    accessor = gltf["accessors"][index]
    values = _dense_accessor(path, gltf, index, read)
    edited = {k: v for k, v in accessor.items() if k not in ("sparse", "byteOffset")}
    if as_float and accessor.get("componentType") in _NORMALIZABLE:
        if edited.pop("normalized", None) is True:
            values = np.maximum(values / float(np.iinfo(values.dtype).max), -1.0)
            for key in ("min", "max"):
                edited.pop(key, None)  # in the integers' units
        values = values.astype("<f4")
        edited.update(componentType=5126)
    return values, edited


def _dense_accessor(path: Path, gltf: dict, index: int, read: Any) -> np.ndarray:
    """Return accessor ``index``'s elements, (count, components): its base, then substitutions."""
    accessor = gltf["accessors"][index]
    where = f"accessor {index}"
    dtype = _COMPONENT_DTYPES.get(accessor.get("componentType"))
    components = _TYPE_COMPONENTS.get(accessor.get("type"))
    if dtype is None or components is None:
        raise ValueError(f"{path}: {where} has an unknown componentType or type")
    count = accessor.get("count", 0)  # an int in range (_check_accessors)
    dense = np.zeros((count, components), dtype)
    if accessor.get("bufferView") is not None:
        dense[:] = _elements(path, gltf, read, accessor["bufferView"],
                             accessor.get("byteOffset", 0), count, dtype, components, where)
    if "sparse" not in accessor:
        return dense
    sparse = accessor["sparse"]
    indices = sparse.get("indices") if isinstance(sparse, dict) else None
    values = sparse.get("values") if isinstance(sparse, dict) else None
    changed = sparse.get("count") if isinstance(sparse, dict) else None
    if not isinstance(indices, dict) or not isinstance(values, dict) or not (
        _is_int(changed) and 1 <= changed <= count
    ):
        raise ValueError(f"{path}: {where}: its sparse block needs indices, values and a count "
                         f"from 1 to the accessor's count ({count})")
    index_dtype = _INDEX_DTYPES.get(indices.get("componentType"))
    if index_dtype is None:
        raise ValueError(f"{path}: {where}: sparse indices must be unsigned bytes, shorts or ints")
    where = f"{where}'s sparse block"
    positions = _elements(path, gltf, read, indices.get("bufferView"),
                          indices.get("byteOffset", 0), changed, index_dtype, 1, where)[:, 0]
    if positions.max() >= count:
        raise ValueError(f"{path}: {where} substitutes element {positions.max()}, past the "
                         f"accessor's {count}")
    dense[positions] = _elements(path, gltf, read, values.get("bufferView"),
                                 values.get("byteOffset", 0), changed, dtype, components, where)
    return dense


def _elements(
    path: Path, gltf: dict, read: Any, view_index: Any, offset: Any, count: int, dtype: str,
    components: int, where: str,
) -> np.ndarray:
    """Return ``count`` elements of ``components`` numbers of ``dtype`` from a bufferView."""
    views = _list(path, gltf, "bufferViews")
    if not (_is_int(view_index) and 0 <= view_index < len(views)):
        raise ValueError(f"{path}: {where} names a missing bufferView")
    view = views[view_index]
    item = np.dtype(dtype).itemsize * components
    stride = view.get("byteStride") or item
    length, start = view.get("byteLength"), view.get("byteOffset", 0)
    if not all(_is_int(n) for n in (stride, length, start, offset)) or min(
        start, offset
    ) < 0 or stride < item:
        raise ValueError(f"{path}: {where}: bufferView {view_index} is not valid")
    need = (count - 1) * stride + item
    data = read(view.get("buffer"))
    if offset + need > length or start + offset + need > len(data):
        raise ValueError(f"{path}: {where} claims more elements than bufferView {view_index} "
                         "holds")
    raw = np.frombuffer(data, np.uint8, count=need, offset=start + offset)
    rows = np.lib.stride_tricks.as_strided(raw, (count, item), (stride, 1))
    return np.ascontiguousarray(rows).view(dtype).reshape(count, components)


def _buffer_range(
    path: Path, gltf: dict, index: int, start: int, length: int, file: BinaryIO,
    chunk: _GlbChunk | None, read: Any,
) -> bytes:
    """Return ``length`` bytes of buffer ``index`` from ``start`` (fewer where it ends first).

    A GLB's binary chunk is read from the file a range at a time; any other buffer is read
    whole by ``read(index)`` (:func:`_buffer_bytes`, once per buffer) and cut.
    """
    if index == 0 and _in_chunk(gltf, chunk):
        return _read_at(file, chunk.start + start, max(min(length, chunk.length - start), 0))
    return read(index)[start : start + length]


def _read_at(file: BinaryIO, offset: int, length: int) -> bytes:
    """Return ``length`` bytes of ``file`` from ``offset`` (fewer at its end).

    One ``pread`` call where the system has it: a seek then a read took twice as long for the
    Duck's four bufferViews (9.6 µs against 4.4). A short read (the system's limit of 2 GiB a
    call) is read again the buffered way, which reads on to the end.
    """
    if hasattr(os, "pread"):  # not on Windows
        data = os.pread(file.fileno(), length, offset)
        if len(data) == length:
            return data
    file.seek(offset)
    return file.read(length)


def _in_chunk(gltf: dict, chunk: _GlbChunk | None) -> bool:
    """Whether buffer 0 is a GLB's binary chunk: the file has one and the buffer has no uri."""
    return chunk is not None and chunk.type == _BIN and "uri" not in gltf["buffers"][0]


def _buffer_bytes(
    path: Path, gltf: dict, index: Any, file: BinaryIO, chunk: _GlbChunk | None, resolver: Any
) -> bytes:
    """Return the bytes of buffer ``index``: a GLB's binary chunk, a data: URI or a file."""
    buffers = _list(path, gltf, "buffers")
    if not (_is_int(index) and 0 <= index < len(buffers)):
        raise ValueError(f"{path}: a bufferView names a missing buffer")
    uri = buffers[index].get("uri")
    if uri is None:
        if index != 0 or not _in_chunk(gltf, chunk):
            raise ValueError(f"{path}: buffer {index} has neither a uri nor a binary chunk")
        return _read_at(file, chunk.start, chunk.length)
    if uri.startswith("data:"):
        head, _, payload = uri.partition(",")
        try:
            if not head.endswith(";base64"):
                raise ValueError("not base64")
            return base64.b64decode(payload, validate=True)
        except (ValueError, binascii.Error):
            raise ValueError(f"{path}: buffer {index}'s data: URI is not base64 data") from None
    try:
        return resolver.get(uri)  # confined to the file's folder, as trimesh's reads are
    except FileNotFoundError:
        raise ValueError(f"{path}: buffer {index}'s file {uri!r} was not found") from None


# --- meshes and materials ---------------------------------------------------------------------


def _meshes(path: Path, parts: list[_Part], gltf: dict | None, resolver: Any) -> list[Mesh]:
    node_names = {n.get("name") for n in (gltf or {}).get("nodes", []) if isinstance(n, dict)}
    meshes = []
    # Parts share trimesh's material and image objects: each is mapped (and each picture
    # decoded) once, and parts sharing a picture share one Texture, packed once to render.
    # (and the resolver, which reads the pictures trimesh leaves unread: an .mtl's map_Ke)
    shared: dict[Any, Any] = {"resolver": resolver}
    primitives: dict[str, int] = {}  # parts named after each node so far
    for part in parts:
        if len(part.faces) == 0:
            continue
        name = _node_name(part.node, gltf, node_names)
        if name is None:
            name = part.geometry
        else:  # a node's second primitive is "name_1", its third "name_2", as trimesh does
            count = primitives.get(part.node, 0)
            primitives[part.node] = count + 1
            name = f"{name}_{count}" if count else name
        try:
            meshes.append(_mesh(path, part, name, gltf, shared))
        except (ValueError, TypeError) as exc:
            message = str(exc).removeprefix(f"{path}: ")  # the file is named once
            raise type(exc)(f"{path}: part {name!r}: {message}") from None
    return meshes


def _node_name(node: str, gltf: dict | None, node_names: set) -> str | None:
    """Return the name a part takes from its node, or None to take its mesh's name.

    A node named in the file gives its name (every part of a file without a node graph,
    OBJ or PLY, is named so too); an unnamed node (trimesh calls it by its index) whose mesh
    has no name either, for which trimesh makes up "GLTF", gives "node <index>".
    """
    if gltf is None or node in node_names:
        return node
    nodes, meshes = gltf.get("nodes", []), gltf.get("meshes", [])  # lists of objects (checked)
    index = int(node) if node.isdigit() else -1
    mesh = nodes[index].get("mesh") if 0 <= index < len(nodes) else None
    if isinstance(mesh, int) and 0 <= mesh < len(meshes) and not meshes[mesh].get("name"):
        return f"node {index}"
    return None


def _mesh(path: Path, part: _Part, name: str, gltf: dict | None, shared: dict) -> Mesh:
    vertices = np.asarray(part.vertices, dtype=np.float64)
    faces = np.asarray(part.faces, dtype=np.int64)
    if vertices.ndim != 2 or vertices.shape[1] != 3 or faces.ndim != 2 or faces.shape[1] != 3:
        raise ValueError(f"vertices {vertices.shape} and faces {faces.shape} are not triangles")
    normals = None
    if part.normals is not None and np.shape(part.normals) == vertices.shape:
        # stored in the file: computing them would be a guess
        normals = np.asarray(part.normals, dtype=np.float64)
        normals = normals if v.all_finite(normals) else None
    vertices, normals, faces = _placed(part.matrix, vertices, normals, faces, shared)
    uv = _uv(part.visual, len(vertices))
    if uv is not None:
        uv = (_texture_transformed(uv, part.visual, gltf) if gltf is not None
              else _mtl_moved(uv, _mtl_map_of(getattr(part.visual, "material", None), shared)))
    colors = _vertex_colors(part.colors, len(vertices), linear=gltf is not None)
    if normals is None:  # glTF asks for flat normals; other files are smoothed up to creases
        angle = FLAT_ANGLE if gltf is not None else CREASE_ANGLE
        vertices, faces, normals, uv, colors = _creased(vertices, faces, uv, colors, angle)
    if colors is None and part.face_colors is not None:
        face_colors = _vertex_colors(part.face_colors, len(faces), linear=False)
        if face_colors is not None:
            vertices, faces, normals, uv, colors = _face_colored(vertices, faces, normals, uv,
                                                                 face_colors)
    material = _material(path, part.visual, gltf, shared, colored=colors is not None)
    try:
        return Mesh(vertices, faces, material, normals, colors, uv, name)
    except ValueError:
        # A Mesh refuses zero normals, which some exporters write; looked for only now, as
        # the test costs 6 µs a part where the mesh's own check of its normals is free.
        filled = None if normals is None else _without_zero_normals(normals, vertices, faces)
        if filled is normals:
            raise
        return Mesh(vertices, faces, material, filled, colors, uv, name)


def _face_colored(
    vertices: np.ndarray, faces: np.ndarray, normals: np.ndarray | None,
    uv: np.ndarray | None, face_colors: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, np.ndarray | None, np.ndarray]:
    """Return a part whose faces are coloured one colour each, with vertex colours.

    One colour for every face (the commonest: a PLY file written with a single colour) gives
    every vertex that colour. Otherwise each face gets corners of its own carrying its colour,
    with the normals the shared corners had (given, or the area-weighted normals of the faces
    around them), so that shading stays smooth across faces of different colours.
    """
    if (face_colors == face_colors[0]).all():
        return vertices, faces, normals, uv, np.repeat(face_colors[:1], len(vertices), axis=0)
    corners = faces.ravel()
    if normals is None:
        normals = Mesh(vertices, faces).vertex_normals
    return (vertices[corners], np.arange(len(corners)).reshape(-1, 3), normals[corners],
            None if uv is None else uv[corners], np.repeat(face_colors, 3, axis=0))


def _creased(
    vertices: np.ndarray, faces: np.ndarray, uv: np.ndarray | None, colors: np.ndarray | None,
    angle: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, np.ndarray | None, np.ndarray | None]:
    """Return a part without normals with normals smoothed within ``angle`` degrees.

    Vertices are split along the edges sharper than that (:func:`crease_normals`), with their
    texture coordinates and colours. A part with no such edge whose vertices each have a point
    of their own is kept as it is, its normals left to the Mesh (the same area-weighted
    normals).
    """
    found = crease_normals(vertices, faces, angle)
    if found is None:
        return vertices, faces, None, uv, colors
    source, faces, normals = found
    return (vertices[source], faces, normals, None if uv is None else uv[source],
            None if colors is None else colors[source])


# The glTF specification asks for flat normals where a primitive has none: a crease angle of 0.
FLAT_ANGLE = 0.0


def _placed(
    node_matrix: Any, vertices: np.ndarray, normals: np.ndarray | None, faces: np.ndarray,
    shared: dict,
) -> tuple[np.ndarray, np.ndarray | None, np.ndarray]:
    """Return a part's vertices, normals and faces in world space, under its node's matrix."""
    matrix = np.asarray(node_matrix, dtype=np.float64)
    if matrix.tobytes() == _IDENTITY_BYTES:
        # Most nodes do not move their parts: the products below give these bits (x + 0.0 is
        # x, but for -0.0, which becomes +0.0), without their 70 µs a file (the truck's).
        return vertices + 0.0, None if normals is None else normals + 0.0, faces
    linear, shift = matrix[:3, :3], matrix[:3, 3]
    vertices = moved(vertices, linear, shift)
    # parts under one node share its matrix (the same object): invert it once
    node = id(node_matrix)
    if normals is not None:  # the inverse transpose, row by row
        normals = normals @ _once(shared, ("inverse", node), np.linalg.inv, linear)
    if _once(shared, ("det", node), np.linalg.det, linear) < 0.0:
        faces = faces[:, ::-1]  # a mirroring node: keep faces counter-clockwise outside
    return vertices, normals, faces


def _without_zero_normals(
    normals: np.ndarray, vertices: np.ndarray, faces: np.ndarray
) -> np.ndarray:
    """Return a part's normals from its file with its zero vectors filled in.

    Some exporters write (0, 0, 0) at corners of degenerate faces, which a Mesh refuses: each
    becomes the area-weighted normal of the faces around its vertex, as where a file has no
    normals, or +Z where those faces have no area either (such a vertex is never seen).
    """
    # |x| + |y| + |z| is 0 for the zero vector alone (the normals are finite)
    zero = np.abs(normals) @ _ONES3 == 0.0
    if not zero.any():
        return normals
    filled = normals.copy()
    filled[zero] = Mesh(vertices, faces).vertex_normals[zero]
    filled[np.abs(filled) @ _ONES3 == 0.0] = (0.0, 0.0, 1.0)
    return filled


def _once(shared: dict, key: tuple, function: Any, argument: Any) -> Any:
    """Return ``function(argument)``, computed once per ``key`` in the loader's per-file cache."""
    if key not in shared:
        shared[key] = function(argument)
    return shared[key]


def _uv(visual: Any, count: int) -> np.ndarray | None:
    uv = getattr(visual, "uv", None)
    if uv is None or np.shape(uv) != (count, 2):
        return None
    uv = np.asarray(uv, dtype=np.float64)
    return uv if v.all_finite(uv) else None


def _texture_transformed(uv: np.ndarray, visual: Any, gltf: dict) -> np.ndarray:
    """Return ``uv`` moved by the base-colour texture's ``KHR_texture_transform``, if it has one.

    The extension maps glTF texture coordinates (v down) by ``T(offset) R(rotation) S(scale)``:
    u' = cos r sx u + sin r sy v + ox and v' = -sin r sx u + cos r sy v + oy. trimesh does not
    apply it; pixelpath's uv (v up, ``1 - v`` of glTF's) are turned back, moved and turned again.
    """
    used = gltf.get("extensionsUsed")
    if not isinstance(used, list) or "KHR_texture_transform" not in used:
        return uv  # glTF lists every extension a file uses
    transform = _reference_transform(_base_color_texture(gltf, getattr(visual, "material", None)))
    if not isinstance(transform, dict):
        return uv
    ox, oy = _numbers(transform, "offset", (0.0, 0.0))
    sx, sy = _numbers(transform, "scale", (1.0, 1.0))
    (rotation,) = _numbers(transform, "rotation", (0.0,))
    cos, sin = math.cos(rotation), math.sin(rotation)
    u, v = uv[:, 0], 1.0 - uv[:, 1]
    moved = np.empty_like(uv)
    moved[:, 0] = cos * sx * u + sin * sy * v + ox
    moved[:, 1] = 1.0 - (-sin * sx * u + cos * sy * v + oy)
    return moved


def _mtl_moved(uv: np.ndarray, options: _MtlMap | None) -> np.ndarray:
    """Return ``uv`` scaled, then moved, by an .mtl map line's ``-s`` and ``-o`` options.

    u' = su u + ou and v' = sv v + ov (v up in both); trimesh does not apply them.
    """
    if options is None or (options.scale, options.offset) == ((1.0, 1.0), (0.0, 0.0)):
        return uv
    moved = np.empty_like(uv)
    for axis in range(2):
        moved[:, axis] = options.scale[axis] * uv[:, axis] + options.offset[axis]
    return moved


def _base_color_texture(gltf: dict | None, source: Any) -> Any:
    """Return the glTF texture reference of ``source``'s base colour, None when there is none.

    trimesh's material is matched to the one glTF material of the same name. The reference
    is returned as the file has it, checked by its readers.
    """
    index = _gltf_material_index(gltf, getattr(source, "name", None))
    if index is None:
        return None
    pbr = gltf["materials"][index].get("pbrMetallicRoughness")
    return pbr.get("baseColorTexture") if isinstance(pbr, dict) else None


def _numbers(values: dict, key: str, default: tuple[float, ...]) -> tuple[float, ...]:
    """Return ``values[key]``: ``len(default)`` finite numbers (one may stand alone)."""
    found = values.get(key, default)
    if len(default) == 1 and not isinstance(found, list | tuple):
        found = [found]
    if not (
        isinstance(found, list | tuple)
        and len(found) == len(default)
        and all(isinstance(x, int | float) and not isinstance(x, bool) for x in found)
        and all(math.isfinite(x) for x in found)
    ):
        raise ValueError(f"KHR_texture_transform {key} must be {len(default)} finite number(s)")
    return tuple(float(x) for x in found)


def _vertex_colors(colors: Any, count: int, *, linear: bool) -> np.ndarray | None:
    """Per-vertex colours in linear light: glTF's COLOR_0 as stored, others decoded from sRGB."""
    if colors is None or len(colors) != count:
        return None
    colors = np.asarray(colors)
    values = colors / 255.0 if colors.dtype.kind in "ui" else colors.astype(np.float64)
    values = np.clip(np.nan_to_num(values), 0.0, 1.0)
    if not linear:
        values[:, :3] = srgb_to_linear(values[:, :3])
    return values


def _plain_material(colored: bool = False) -> Material:
    """Return the material of a part whose file gives none.

    Light grey, or white under vertex colours (which are then the surface's colour, as other
    viewers show them).
    """
    color = (1.0, 1.0, 1.0) if colored else (0.8, 0.8, 0.8)
    return Material(color=color, ka=1.0, kd=1.0, ks=0.2, shininess=32.0)


def _material(
    path: Path, visual: Any, gltf: dict | None, shared: dict, *, colored: bool = False
) -> Material:
    """Map the part's material (see the table); ``colored``: the part has vertex colours."""
    source = getattr(visual, "material", None)
    if source is None:
        return _plain_material(colored)
    key = ("material", id(source))
    if key not in shared:
        if type(source).__name__ == "PBRMaterial":
            shared[key] = _pbr_material(path, source, gltf, shared)
        elif _stands_in(source):
            shared[key] = None
        else:
            shared[key] = _simple_material(path, source, shared)
    material = shared[key]
    return _plain_material(colored) if material is None else material


def _stands_in(source: Any) -> bool:
    """Whether ``source`` is the material trimesh makes up for texture coordinates without one.

    A PLY file with ``s, t`` columns, or an OBJ file with ``vt`` lines and no (or a missing)
    ``.mtl`` file, has no material; trimesh gives it ``empty_material()``: no MTL values and a
    2 x 2 picture of one grey (100/255), which, taken for a texture, darkened the model to a
    tenth of the light grey of a file without texture coordinates.
    """
    from trimesh.visual.material import color_image

    image = getattr(source, "image", None)
    return (
        not getattr(source, "kwargs", None)
        and image is not None
        and image.size == (2, 2)
        and image.tobytes() == color_image().tobytes()
    )


def _pbr_material(path: Path, source: Any, gltf: dict | None, shared: dict) -> Material:
    """Map a glTF metallic-roughness material onto the notes' Phong model (see the table)."""
    rgba = _base_color(source.baseColorFactor)
    metallic, roughness = _metal_and_roughness(path, source, shared)
    mode = (source.alphaMode or "OPAQUE").upper()
    alpha_cutoff = _alpha_cutoff(source, mode)
    texture = _texture(path, source.baseColorTexture, shared, keep_alpha=mode != "OPAQUE")
    if texture is None:
        _refuse_lost_texture(path, source, gltf, shared["resolver"])
        texture_filter, texture_wrap = "trilinear", "repeat"  # nothing to sample
    else:
        texture_filter, texture_wrap = _sampler(path, source, gltf, shared)
    kd = 1.0 - 0.6 * metallic
    ka, ks = kd, (1.0 - roughness) ** 2 * (0.25 + 0.75 * metallic)
    transparency = _fraction(1.0 - rgba[3]) if mode == "BLEND" else 0.0
    transmission = _extension_number(gltf, source, "KHR_materials_transmission",
                                     "transmissionFactor", 0.0)
    ior = _extension_number(gltf, source, "KHR_materials_ior", "ior", 1.5, minimum=1.0)
    if transmission is not None:  # glass: what is transmitted is not diffused
        transparency = min(transmission, 1.0)
        ka, kd = ka * (1.0 - transparency), kd * (1.0 - transparency)
        ior = 1.5 if ior is None else ior  # glTF's index of refraction when none is given
    if _is_unlit(gltf, source):  # the ambient term alone shows the colour as it is
        ka, kd, ks, transparency = 1.0 / AMBIENT, 0.0, 0.0, 0.0
    factor = source.emissiveFactor
    if factor is not None:
        strength = _emissive_strength(gltf, source)
        factor = [float(channel) * strength for channel in factor]
    glow = _texture(path, source.emissiveTexture, shared, keep_alpha=False)
    unread = None if glow is None else _unread_emission(gltf, source)
    emission = _emission(path, source.name, ("emissiveFactor", factor), unread)
    return Material(
        color=rgba[:3],
        ka=ka,
        kd=kd,
        ks=ks,
        shininess=_shininess(roughness),
        transparency=transparency,
        ior=1.0 if ior is None else ior,
        name=source.name if isinstance(source.name, str) else None,
        texture=texture,
        texture_filter=texture_filter,
        texture_wrap=texture_wrap,
        double_sided=bool(source.doubleSided),
        alpha=_fraction(rgba[3]) if mode == "MASK" else 1.0,
        alpha_cutoff=alpha_cutoff,
        emission=emission,
        emission_texture=None if unread else glow,
    )


def _metal_and_roughness(path: Path, source: Any, shared: dict) -> tuple[float, float]:
    """Return a glTF material's metalness and roughness: its factors × its texture's means.

    The notes' model gives a material one ``kd``, ``ks`` and shininess, so a
    ``metallicRoughnessTexture`` (roughness in green, metalness in blue, linear values) counts
    by its average over the picture. Without it, a texture's factors (1 when absent, as they
    usually are) would make every such surface a rough metal: a wooden bed whose texture says
    metalness 0.008 drew with 40 % of its diffuse light.
    """
    metallic = 1.0 if source.metallicFactor is None else float(source.metallicFactor)
    roughness = 1.0 if source.roughnessFactor is None else float(source.roughnessFactor)
    metallic, roughness = _fraction(metallic), _fraction(roughness)
    image = getattr(source, "metallicRoughnessTexture", None)
    if image is not None:
        green, blue = _once(shared, ("means", id(image)), _green_and_blue, (path, image))
        metallic, roughness = metallic * blue, roughness * green
    return metallic, roughness


def _green_and_blue(file_and_image: tuple[Path, Any]) -> tuple[float, float]:
    """Return a picture's mean green and blue values as fractions of full scale."""
    import PIL.Image
    import PIL.ImageStat

    path, image = file_and_image
    if not isinstance(image, PIL.Image.Image):
        raise ValueError(f"{path}: a metallic-roughness texture is not a picture "
                         f"({type(image).__name__})")
    try:
        grey = wide_grey(image)
        if grey is not None:  # one channel of 16-bit integers or floats
            mean = float(grey.mean())
            return mean, mean
        if not {"G", "B"} <= set(image.getbands()):
            image = image.convert("RGB")
        means = PIL.ImageStat.Stat(image).mean  # counted from the histogram: no float copy
        bands = image.getbands()
        return means[bands.index("G")] / 255.0, means[bands.index("B")] / 255.0
    except (OSError, SyntaxError, PIL.Image.DecompressionBombError) as exc:
        # truncated or corrupt data is found when the pixels are decoded
        raise ValueError(f"{path}: the metallic-roughness texture is not a readable image "
                         f"({exc})") from None


def _unread_emission(gltf: dict | None, source: Any) -> str | None:
    """Say why a glTF emissiveTexture cannot be drawn; None when it can.

    A part has one set of texture coordinates, the base colour's (its ``texCoord``, moved by
    its ``KHR_texture_transform``): an emissiveTexture reading another set, or transformed
    otherwise, would be read in the wrong places.
    """
    index = _gltf_material_index(gltf, getattr(source, "name", None))
    if index is None:
        return None  # no (or no single) glTF material of that name: set 0, as trimesh reads
    material = gltf["materials"][index]
    glow = material.get("emissiveTexture")
    pbr = material.get("pbrMetallicRoughness")
    base = pbr.get("baseColorTexture") if isinstance(pbr, dict) else None
    glow_set, base_set = _reference_set(glow), _reference_set(base)
    if glow_set != base_set:
        return (f"an emissiveTexture reading texture coordinates TEXCOORD_{glow_set} where the "
                f"base colour reads TEXCOORD_{base_set}")
    if _reference_transform(glow) != _reference_transform(base):
        return "an emissiveTexture with a KHR_texture_transform other than the base colour's"
    return None


def _emission(path: Path, name: Any, color: tuple[str, Any], unread: str | None) -> list[float]:
    """Return the light a file's material emits (linear r, g, b), zero when it emits none.

    ``color`` is the file's key for the emitted colour and its value (None when absent), in
    linear light; ``unread`` names an emission texture that cannot be drawn (None when there
    is none, or it can). Then neither is the colour, which only scales it (a factor of 1
    would light the whole surface evenly): a warning says so.
    """
    key, value = color
    try:  # three Python floats: NumPy's calls cost more than the arithmetic on a 3-vector
        emitted = [float(channel) for channel in (value if value is not None else (0, 0, 0))]
        usable = len(emitted) == 3 and all(map(math.isfinite, emitted))
    except (TypeError, ValueError):
        usable = False
    emitted = [max(channel, 0.0) for channel in emitted] if usable else [0.0, 0.0, 0.0]
    if unread is None:
        return emitted
    if any(emitted):
        warnings.warn(
            f"{path}: material {name!r} emits light ({key} {emitted}) through {unread}, which "
            "is not drawn, nor the colour it scales",
            stacklevel=3,
        )
    return [0.0, 0.0, 0.0]


def _emissive_strength(gltf: dict | None, source: Any) -> float:
    """Return the ``KHR_materials_emissive_strength`` of ``source``'s glTF material (1 if none)."""
    strength = _extension_number(gltf, source, "KHR_materials_emissive_strength",
                                 "emissiveStrength", 1.0)
    return 1.0 if strength is None else strength


def _extension_number(
    gltf: dict | None, source: Any, extension: str, key: str, default: float,
    minimum: float = 0.0,
) -> float | None:
    """Return the number ``key`` of ``extension`` on ``source``'s glTF material.

    None when the material has no such extension (or no single glTF material has its name);
    ``default`` where the extension leaves the number out or gives anything but a finite number
    of at least ``minimum`` (trimesh drops these extensions: the JSON is read here).
    """
    index = _gltf_material_index(gltf, getattr(source, "name", None))
    if index is None:
        return None
    extensions = gltf["materials"][index].get("extensions")
    table = extensions.get(extension) if isinstance(extensions, dict) else None
    if not isinstance(table, dict):
        return None
    value = table.get(key, default)
    number = isinstance(value, int | float) and not isinstance(value, bool)
    return float(value) if number and math.isfinite(value) and value >= minimum else default


def _is_unlit(gltf: dict | None, source: Any) -> bool:
    """Whether ``source``'s glTF material has ``KHR_materials_unlit``.

    trimesh drops the extension; its material is matched to the glTF material of the same
    name, and where that is ambiguous (several unnamed materials), it is unlit when every
    material of the file is.
    """
    materials = (gltf or {}).get("materials")
    if not isinstance(materials, list) or not materials:
        return False
    index = _gltf_material_index(gltf, getattr(source, "name", None))
    chosen = materials if index is None else [materials[index]]
    return all(
        isinstance(material, dict)
        and isinstance(material.get("extensions"), dict)
        and "KHR_materials_unlit" in material["extensions"]
        for material in chosen
    )


def _base_color(factor: Any) -> np.ndarray:
    """Return trimesh's ``baseColorFactor`` (None or 8-bit RGBA) as floats, RGB within [0, 1]."""
    if factor is None:
        return np.ones(4)
    raw = np.asarray(factor)
    if raw.dtype == np.uint8:  # as trimesh keeps it: k / 255 lies in [0, 1], nothing to clip
        return raw / 255.0
    rgba = raw.astype(np.float64)
    if rgba.max() > 1.0 or raw.dtype.kind in "ui":
        rgba = rgba / 255.0  # 8-bit values
    rgba[:3] = np.clip(rgba[:3], 0.0, 1.0)
    return rgba


def _fraction(value: Any) -> float:
    """Return ``value`` as a float clamped to [0, 1] (NaN stays NaN, as with ``np.clip``)."""
    value = float(value)
    return value if math.isnan(value) else min(max(value, 0.0), 1.0)


# BLEND is drawn as MASK with this cutoff: a texel at least half opaque is drawn, others cut.
BLEND_CUTOFF = 0.5


def _alpha_cutoff(source: Any, mode: str) -> float | None:
    """Return the ``alpha_cutoff`` of a glTF material's ``alphaMode`` (see the table).

    A cutoff that is not a number >= 0 is refused (the caller names the file and the part).
    """
    if mode == "BLEND":
        return BLEND_CUTOFF
    if mode != "MASK":
        return None
    value = 0.5 if source.alphaCutoff is None else source.alphaCutoff
    try:
        cutoff = float(value)
    except (TypeError, ValueError):
        cutoff = math.nan
    if not (math.isfinite(cutoff) and cutoff >= 0.0):
        raise ValueError(
            f"material {source.name!r} has alphaCutoff {value!r}; glTF asks for a number >= 0"
        )
    return cutoff


def _shininess(roughness: float) -> float:
    """Phong exponent of a GGX roughness, ``2 / r^4 - 2`` (Blinn's mapping), kept in [1, 1000]."""
    if roughness <= 0.0:
        return 1000.0
    return min(max(2.0 / roughness**4 - 2.0, 1.0), 1000.0)


def _simple_material(path: Path, source: Any, shared: dict) -> Material:
    """Map an MTL material (trimesh's SimpleMaterial and its raw MTL values) (see the table)."""
    raw = {key.lower(): value for key, value in (getattr(source, "kwargs", None) or {}).items()}
    # A picture with no MTL values (a PLY file's "comment TextureFile") is the colour itself.
    plain = (1.0, 1.0, 1.0) if not raw and getattr(source, "image", None) is not None else (
        0.8, 0.8, 0.8)
    kd_color = _mtl_color(raw.get("kd"), plain)
    ka_color = _mtl_color(raw.get("ka"), (0.0, 0.0, 0.0))
    ks_color = _mtl_color(raw.get("ks"), (0.0, 0.0, 0.0))
    ns = _mtl_number(raw.get("ns"), 0.0)
    opacity = _fraction(_mtl_number(raw.get("d"), 1.0))
    ka = float(np.mean(ka_color))
    ke = _mtl_color(raw.get("ke"), (0.0, 0.0, 0.0))  # a display colour, as Kd's
    options = _mtl_map_of(source, shared)
    glow, unread = _mtl_glow(raw.get("map_ke"), options, shared)
    emission = _emission(path, source.name, ("Ke", srgb_to_linear(ke)), unread)
    if options is not None and options.ignored:
        warnings.warn(f"{path}: material {source.name!r}: the .mtl texture options "
                      f"{options.ignored!r} are not applied", stacklevel=2)
    return Material(
        color=srgb_to_linear(kd_color),
        ka=ka if ka > 0.0 else 1.0,
        kd=1.0,
        ks=float(np.mean(ks_color)) * min(1.0, max(ns, 0.0) / 100.0),
        shininess=max(ns, 1.0),
        transparency=1.0 - opacity,
        name=source.name if isinstance(source.name, str) else None,
        texture=_texture(path, getattr(source, "image", None), shared, keep_alpha=True),
        texture_wrap="clamp" if options is not None and options.clamp else "repeat",
        emission=emission,
        emission_texture=glow,
    )


def _uv_moves(options: _MtlMap | None) -> tuple:
    """Return how an .mtl texture line's options move texture coordinates: (scale, offset)."""
    return ((1.0, 1.0), (0.0, 0.0)) if options is None else (options.scale, options.offset)


def _mtl_glow(
    words: Any, options: _MtlMap | None, shared: dict
) -> tuple[Texture | None, str | None]:
    """Return an .mtl ``map_Ke`` line's picture as a texture, or why it is not drawn.

    trimesh keeps the line's words and leaves the picture unread: it is read here through
    the model's resolver (confined to its folder), and drawn through the part's texture
    coordinates, which ``map_Kd``'s ``-s`` and ``-o`` move, so ``map_Ke`` must move them alike.
    """
    if words is None:
        return None, None
    line = " ".join(map(str, words)) if isinstance(words, list) else str(words)
    name, given = _mtl_map_line(line)
    if _uv_moves(_mtl_options(given)) != _uv_moves(options):
        return None, "a map_Ke texture whose -s or -o differ from map_Kd's"
    try:
        data = shared["resolver"].get(name)
    except FileNotFoundError:  # after the missing-file warnings: the emission's names it
        return None, "a map_Ke texture that was not found"
    import PIL.Image

    try:
        picture = PIL.Image.open(io.BytesIO(data))
    except (OSError, ValueError):
        raise ValueError(f"map_Ke {name!r} is not a picture Pillow can read") from None
    return Texture.deferred(picture, name=f"{name} (map_Ke)", opaque=True), None


def _mtl_color(value: Any, default: tuple[float, ...]) -> np.ndarray:
    try:
        color = np.asarray(value if value is not None else default, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        return np.asarray(default)
    if color.size == 1:
        color = np.repeat(color, 3)
    if color.size < 3 or not v.all_finite(color[:3]):
        return np.asarray(default)
    return np.clip(color[:3], 0.0, 1.0)


def _mtl_number(value: Any, default: float) -> float:
    if isinstance(value, list | tuple):
        value = value[0] if value else None
    try:
        number = float(value) if value is not None else default
    except (TypeError, ValueError):
        return default
    return number if math.isfinite(number) else default


def _texture(path: Path, image: Any, shared: dict, *, keep_alpha: bool) -> Texture | None:
    """Return the picture as a Texture (with alpha only when it matters), shared by materials."""
    if image is None:
        return None
    import PIL.Image

    if not isinstance(image, PIL.Image.Image):
        raise ValueError(f"{path}: a texture is not a picture ({type(image).__name__})")
    key = ("texture", id(image), keep_alpha)
    if key in shared:
        return shared[key]
    # Decoded at first use (as trimesh leaves it): a truncated picture raises its ValueError
    # naming the file then, and loading costs little more than trimesh's.
    shared[key] = Texture.deferred(image, name=f"{path.name} texture", opaque=not keep_alpha)
    return shared[key]


def _refuse_lost_texture(path: Path, source: Any, gltf: dict | None, resolver: Any) -> None:
    """Refuse a material whose texture trimesh skipped (it drops what it cannot decode).

    A picture in a file of the model's folder (``resolver`` finds it) is opened to say why.
    """
    for index in _gltf_materials_named(gltf, source.name):
        material = gltf["materials"][index]
        pbr = material.get("pbrMetallicRoughness")
        if isinstance(pbr, dict) and "baseColorTexture" in pbr:
            uri = _image_uri(gltf, pbr["baseColorTexture"])
            file = None if uri is None else resolver.find(uri)
            if uri is not None and file is None:
                return  # a missing file, already warned of: the material colour alone is drawn
            problem = None if file is None else _picture_problem(file)
            raise ValueError(
                f"{path}: material {source.name!r} has a base-colour texture that could not "
                "be read (" + (problem or "missing, or not a PNG/JPEG trimesh can decode") + ")"
            )


# glTF sampler codes (the values of WebGL's constants)
_WRAPS = {10497: "repeat", 33071: "clamp", 33648: "mirror"}
_NEAREST, _LINEAR = 9728, 9729
_MIN_FILTERS = {
    _NEAREST: "nearest",
    _LINEAR: "bilinear",
    9984: "trilinear",
    9985: "trilinear",
    9986: "trilinear",
    9987: "trilinear",
}


def _sampler(path: Path, source: Any, gltf: dict | None, shared: dict) -> tuple[str, str]:
    """Return ``(texture_filter, texture_wrap)`` of the material's base-colour texture sampler.

    Parameters
    ----------
    path : Path
        The model file, named in the warning.
    source : trimesh.visual.material.PBRMaterial
        The material trimesh read; matched to the glTF material of the same name.
    gltf : dict or None
        The checked glTF JSON (None for other formats: the defaults).
    shared : dict
        The loader's per-file cache; records which materials were warned about.

    Returns
    -------
    (str, str)
        The filter and wrap (see the module's material table); ``("trilinear", "repeat")``
        when there is no sampler or no single glTF material has the material's name.

    Raises
    ------
    ValueError
        When the texture reference or the sampler is not valid glTF.
    """
    ref = _base_color_texture(gltf, source)
    if ref is None:
        return "trilinear", "repeat"
    name = source.name
    sampler = _sampler_json(gltf, ref, f"material {name!r}")
    wrap_s = _code(sampler, "wrapS", _WRAPS, 10497, name)
    wrap_t = _code(sampler, "wrapT", _WRAPS, 10497, name)
    minify = _code(sampler, "minFilter", _MIN_FILTERS, None, name)
    magnify = _code(sampler, "magFilter", {_NEAREST: "nearest", _LINEAR: "bilinear"}, None, name)
    if wrap_t != wrap_s and ("sampler warned", name) not in shared:
        shared["sampler warned", name] = True
        warnings.warn(
            f"{path}: material {name!r}: the texture's wrapT ({wrap_t}, {_WRAPS[wrap_t]!r}) "
            f"differs from its wrapS ({wrap_s}, {_WRAPS[wrap_s]!r}); pixelpath has one wrap "
            f"for both axes and uses {_WRAPS[wrap_s]!r}",
            stacklevel=2,
        )
    if minify is None:
        texture_filter = "trilinear"  # glTF leaves the choice to the viewer
    elif minify == _NEAREST and magnify == _LINEAR:
        texture_filter = "bilinear"
    else:
        texture_filter = _MIN_FILTERS[minify]
    return texture_filter, _WRAPS[wrap_s]


def _gltf_material_index(gltf: dict | None, name: Any) -> int | None:
    """Return the index of the one glTF material named ``name`` (None: none or ambiguous)."""
    found = _gltf_materials_named(gltf, name)
    return found[0] if len(found) == 1 else None


# The last glTF materials list looked in, and the indices of its materials by name. Every
# material's mapping asks for its glTF material several times (sampler, unlit, extensions,
# emission) and each part's texture transform once more: a scan each made a file of M
# materials cost M^2 look-ups (600 materials: 1,800 scans of the list).
_names_seen: tuple[Any, dict] = (None, {})


def _gltf_materials_named(gltf: dict | None, name: Any) -> tuple[int, ...]:
    """Return the indices of the glTF materials named ``name``, in the file's order."""
    global _names_seen
    materials = (gltf or {}).get("materials")
    if not isinstance(materials, list) or not isinstance(name, Hashable):
        return ()
    seen, indices = _names_seen
    if seen is not materials:  # another file (a reading thread's, or the next one)
        indices = {}
        for i, material in enumerate(materials):
            key = material.get("name") if isinstance(material, dict) else _NOT_A_NAME
            if isinstance(key, Hashable):  # a name that is a JSON list or object names nothing
                indices[key] = (*indices.get(key, ()), i)
        _names_seen = (materials, indices)
    return indices.get(name, ())


_NOT_A_NAME = object()  # the key of list entries that are not material objects


def _sampler_json(gltf: dict, ref: Any, where: str) -> dict:
    """Return the sampler object a texture reference leads to (``{}``: the default sampler)."""
    if not isinstance(ref, dict):
        raise ValueError(f"{where}: baseColorTexture must be an object, got {ref!r}")
    textures = gltf.get("textures")
    texture = _item(textures, ref.get("index"), where, "baseColorTexture index", "textures")
    if texture.get("sampler") is None:
        return {}
    return _item(gltf.get("samplers"), texture.get("sampler"), where, "texture sampler", "samplers")


def _item(items: Any, index: Any, where: str, what: str, kind: str) -> dict:
    """Return ``items[index]``, an object, refusing a bad index with a ValueError."""
    what = f"{where}: {what}"
    if not _is_int(index):
        raise ValueError(f"{what} must be an integer, got {index!r}")
    if not isinstance(items, list) or not 0 <= index < len(items):
        count = len(items) if isinstance(items, list) else 0
        raise ValueError(f"{what} {index} is out of range (the file has {count} {kind})")
    if not isinstance(items[index], dict):
        raise ValueError(f"{where}: glTF {kind}[{index}] must be an object")
    return items[index]


def _code(sampler: dict, key: str, codes: dict, default: int | None, name: Any) -> int | None:
    value = sampler.get(key)
    if value is None:
        return default
    if not _is_int(value) or value not in codes:
        raise ValueError(
            f"material {name!r}: sampler {key} {value!r} is not one of {', '.join(map(str, codes))}"
        )
    return value


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _image_uri(gltf: Any, ref: Any) -> str | None:
    """Return the file URI of the image the texture ``ref`` names (None: data, or nothing)."""
    try:
        uri = gltf["images"][gltf["textures"][ref["index"]]["source"]]["uri"]
    except (KeyError, IndexError, TypeError):
        return None
    return uri if isinstance(uri, str) and not uri.startswith("data:") else None


# --- camera and lights ------------------------------------------------------------------------


def _bounds_of(objects: list[Mesh]) -> np.ndarray:
    if len(objects) == 1:  # the same box, kept by the mesh for its renders
        return objects[0].bounds()
    return bounding_box(np.vstack([mesh.vertices for mesh in objects]))


def _center(bounds: np.ndarray) -> np.ndarray:
    """Return the centre of the (2, 3) box ``bounds``: ``bounds.mean(axis=0)``, bit for bit.

    NumPy's mean sums the two rows onto a zero, then divides by 2, at several times the cost
    of that sum. The zero matters only to signs: two corners at -0.0 have a centre at +0.0.
    """
    return (bounds[0] + bounds[1] + 0.0) / 2.0


def framing_camera(bounds: Any, size: tuple[int, int] = DEFAULT_SIZE, fov: float = 45.0) -> Camera:
    """Return a camera that shows the whole box ``bounds`` from the front and a little above.

    The camera looks at the box's centre from +Z, raised by 22 degrees, at the smallest distance
    where every corner of the box lies within the middle 90 % of the picture (in both
    directions); near and far enclose the box's bounding sphere.

    Parameters
    ----------
    bounds : (2, 3) array_like
        The box's minimum and maximum corners.
    size : (int, int)
        Picture width and height in pixels.
    fov : float
        Vertical field of view in degrees.

    Examples
    --------
    >>> from pixelpath.io.models import framing_camera
    >>> camera = framing_camera([[-1, -1, -1], [1, 1, 1]], (800, 600))
    >>> camera.target.tolist(), camera.width, camera.height
    ([0.0, 0.0, 0.0], 800, 600)
    """
    bounds = np.asarray(bounds, dtype=np.float64)
    center = _center(bounds)
    radius = max(v.vector_length(bounds[1] - bounds[0]) / 2.0, 1e-9)
    elevation = math.radians(ELEVATION)
    back = np.array([0.0, math.sin(elevation), math.cos(elevation)])  # from the centre to the eye
    distance = framing_distance(bounds, back, size, fov)
    near, far = depth_range(distance, radius)
    return Camera(
        eye=center + distance * back,
        target=center,
        fov=fov,
        width=size[0],
        height=size[1],
        near=near,
        far=far,
    )


def framing_distance(
    bounds: Any, back: Any, size: tuple[int, int], fov: float, up: Any = (0.0, 1.0, 0.0)
) -> Any:
    """Return how far from the box's centre, along ``back``, a camera sees all of ``bounds``.

    The smallest distance at which every corner of the box lies within the middle 90 % of a
    ``size`` picture with vertical field of view ``fov`` (degrees), for a camera looking back
    along the unit vector ``back`` with ``up`` as its up direction. ``back`` and ``up`` may be
    (n, 3) arrays of n cameras: the result is then an (n,) array.

    Examples
    --------
    >>> from pixelpath.io.models import framing_distance
    >>> round(framing_distance([[-1, -1, -1], [1, 1, 1]], (0, 0, 1), (100, 100), 90.0), 4)
    2.1111
    """
    bounds = np.asarray(bounds, dtype=np.float64)
    back = np.asarray(back, dtype=np.float64)
    right = v.cross3(np.asarray(up, dtype=np.float64), back)
    right /= v.row_lengths(right)
    camera_up = v.cross3(back, right)
    width, height = size
    tan_v = math.tan(math.radians(fov) / 2.0) * FILL
    tan_h = tan_v * width / height
    # the box's 8 corners, x slowest, laid out column by column as np.meshgrid gave them: the
    # products with the axes below go through BLAS, whose rounding depends on the layout
    corners = np.array(list(zip(*itertools.product(*bounds.T.tolist()), strict=True))).T
    offset = corners - _center(bounds)  # (8, 3), against axes (3,) or (n, 3)
    x, y, z = ((offset @ axis.T).T for axis in (right, camera_up, back))  # (8,) or (n, 8)
    radius = max(v.vector_length(bounds[1] - bounds[0]) / 2.0, 1e-9)
    # a corner at (x, y, z) in the camera's frame is inside when |x| <= tan_h (d - z), ...
    distance = np.maximum(z + np.abs(x) / tan_h, z + np.abs(y) / tan_v).max(axis=-1)
    distance = np.maximum(distance, radius * 1.01)
    return float(distance) if distance.ndim == 0 else distance


def depth_range(distance: float, radius: float) -> tuple[float, float]:
    """Return (near, far) enclosing a sphere of ``radius`` seen from ``distance`` away.

    Examples
    --------
    >>> from pixelpath.io.models import depth_range
    >>> depth_range(10.0, 1.0)
    (8.95, 11.05)
    """
    return max(distance - radius * 1.05, distance * 1e-3), distance + radius * 1.05


def light_rig(camera: Camera) -> list[DirectionalLight]:
    """Return the default three lights, placed relative to ``camera``.

    A key light from above left of the camera (intensity 0.75), a fill light from its right
    and slightly below (0.3) and a rim light from behind the model and above (0.25), all
    directional so that they do not depend on the model's size.

    Examples
    --------
    >>> from pixelpath.io.models import framing_camera, light_rig
    >>> [light.intensity for light in light_rig(framing_camera([[0, 0, 0], [1, 1, 1]]))]
    [0.75, 0.3, 0.25]
    """
    axes = list(zip(*(axis.tolist() for axis in camera.basis()), strict=True))
    rig = (((-0.6, 0.7, 0.8), 0.75), ((0.8, -0.1, 0.6), 0.3), ((0.2, 0.8, -0.9), 0.25))
    # -(a right + b up + c back) in Python floats: NumPy's operations on 3-vectors cost more
    return [
        DirectionalLight(
            direction=[-(a * right + b * up + c * back) for right, up, back in axes],
            intensity=intensity,
        )
        for (a, b, c), intensity in rig
    ]


def _world_matrices(gltf: dict) -> dict[int, np.ndarray]:
    """Return the world matrix of every node reachable from the file's default scene."""
    nodes = gltf.get("nodes", [])
    scenes = gltf.get("scenes", [])
    index = gltf.get("scene", 0)
    roots = (
        scenes[index].get("nodes", [])
        if isinstance(index, int) and 0 <= index < len(scenes) and isinstance(scenes[index], dict)
        else range(len(nodes))
    )
    world: dict[int, np.ndarray] = {}
    stack = [(root, np.eye(4)) for root in roots]
    while stack:
        node, parent = stack.pop()
        if not isinstance(node, int) or not 0 <= node < len(nodes) or node in world:
            continue  # a bad reference or a cycle: trimesh has read the file already
        matrix = parent @ _local_matrix(nodes[node])
        world[node] = matrix
        stack.extend((child, matrix) for child in nodes[node].get("children", []))
    return world


def _local_matrix(node: dict) -> np.ndarray:
    if "matrix" in node:
        return np.asarray(node["matrix"], dtype=np.float64).reshape(4, 4).T  # column-major
    if not _TRS.intersection(node):  # what the product below gives, without its 50 µs
        return np.eye(4)
    import trimesh.transformations as tf

    matrix = tf.translation_matrix(node.get("translation", (0.0, 0.0, 0.0)))
    x, y, z, w = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    matrix = matrix @ tf.quaternion_matrix((w, x, y, z))
    return matrix @ np.diag([*node.get("scale", (1.0, 1.0, 1.0)), 1.0])


_TRS = frozenset({"translation", "rotation", "scale"})


def _file_camera(gltf: dict, bounds: np.ndarray, size: tuple[int, int] | None) -> Camera | None:
    """Return the file's first camera (in scene order), or None when it has none."""
    cameras = gltf.get("cameras", [])
    if not cameras:
        return None
    for node, matrix in sorted(_world_matrices(gltf).items()):
        index = gltf["nodes"][node].get("camera")
        if isinstance(index, int) and 0 <= index < len(cameras):
            return _camera(cameras[index], matrix, bounds, size)
    return None


def _camera(spec: dict, matrix: np.ndarray, bounds: np.ndarray, size: Any) -> Camera | None:
    eye = matrix[:3, 3]
    axes = matrix[:3, :3] / v.row_lengths(matrix[:3, :3].T)[:, 0]  # the node's scale is ignored
    forward, up = -axes[:, 2], axes[:, 1]
    center = _center(bounds)
    radius = v.vector_length(bounds[1] - bounds[0]) / 2.0
    reach = v.vector_length(center - eye) + radius  # beyond it nothing is drawn
    target = eye + forward * max(float(np.dot(center - eye, forward)), 1e-3 * reach, 1e-6)
    if spec.get("type") == "orthographic":
        ortho = spec["orthographic"]
        xmag, ymag = float(ortho["xmag"]), float(ortho["ymag"])
        width, height = _camera_size(xmag / ymag if xmag > 0.0 and ymag > 0.0 else None, size)
        return Camera(
            eye=eye,
            target=target,
            up=up,
            width=width,
            height=height,
            near=max(float(ortho.get("znear", 0.0)), 1e-6),
            far=float(ortho["zfar"]),
            projection="orthographic",
            view_height=2.0 * ymag,
        )
    perspective = spec["perspective"]
    aspect = perspective.get("aspectRatio")
    size = _camera_size(float(aspect) if aspect else None, size)
    near = float(perspective["znear"])
    far = float(perspective.get("zfar") or max(2.0 * reach, near * 2.0))
    return Camera(
        eye=eye,
        target=target,
        up=up,
        fov=math.degrees(float(perspective["yfov"])),
        width=size[0],
        height=size[1],
        near=near,
        far=far,
    )


def _camera_size(aspect: float | None, size: tuple[int, int] | None) -> tuple[int, int]:
    """Return ``size``, else the file camera's aspect beside a height of 600 pixels."""
    if size is not None:
        return size
    width = round(DEFAULT_SIZE[1] * aspect) if aspect else DEFAULT_SIZE[0]
    return min(max(width, 1), v.MAX_IMAGE_SIDE), DEFAULT_SIZE[1]


def _file_lights(gltf: dict, bounds: np.ndarray) -> list[PointLight | DirectionalLight]:
    """Return the file's KHR_lights_punctual lights (see the module's documentation)."""
    defined = gltf.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    if not defined:
        return []
    center = _center(bounds)
    found: list[tuple[str, Any, float, Any]] = []
    for node, matrix in sorted(_world_matrices(gltf).items()):
        ref = gltf["nodes"][node].get("extensions", {}).get("KHR_lights_punctual", {})
        index = ref.get("light") if isinstance(ref, dict) else None
        if not isinstance(index, int) or not 0 <= index < len(defined):
            continue
        light = defined[index]
        color = light.get("color", (1.0, 1.0, 1.0))
        intensity = float(light.get("intensity", 1.0))
        if light.get("type") == "directional":
            found.append(("directional", -matrix[:3, 2], intensity, color))
        else:  # point, and spot drawn as a point light
            position = matrix[:3, 3]
            distance2 = max(float(np.sum((position - center) ** 2)), 1e-12)
            found.append(("point", position, intensity / distance2, color))
    brightest = max((item[2] for item in found), default=0.0)
    scale = 1.0 / brightest if brightest > 0.0 else 0.0
    return [
        DirectionalLight(where, intensity * scale, color)
        if kind == "directional"
        else PointLight(where, intensity * scale, color)
        for kind, where, intensity, color in found
    ]
