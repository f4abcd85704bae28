"""Turn a scene's objects into one triangle soup for the raster methods.

* Spheres become icospheres (``SPHERE_SUBDIVISIONS``: 5120 triangles, silhouette within 0.06 %
  of the radius) with exact normals;
* infinite planes become a square centred under the eye, large enough to cover every point
  of the plane in the view frustum (:func:`view_reach`); frustum clipping cuts it to the view.
  The square is a grid whose cells grow quadratically away from the eye (small near the
  camera, where flat and Gouraud shading need vertices, large far away);
* boxes and meshes are used as they are (meshes keep their polygons: a triangle remembers the
  polygon it was fanned from, for flat shading and back-face culling).
"""

from __future__ import annotations

import collections
import dataclasses
import functools
import math
import threading
from collections.abc import Callable, Hashable

import numpy as np

from pixelpath._validate import frozen
from pixelpath.scene import Box, Camera, Mesh, Plane, Scene, Sphere
from pixelpath.scene._texture_kernels import GLOW, HAS_COLORS, TEXTURE, SurfaceTables
from pixelpath.scene.texture import surface_tables

__all__ = ["SceneGeometry", "scene_geometry"]

SPHERE_SUBDIVISIONS = 4
PLANE_GRID = 32  # cells per side of a plane's square


@dataclasses.dataclass(frozen=True)
class SceneGeometry:
    """All objects of a scene as one mesh, with the bookkeeping the raster stages need.

    Attributes
    ----------
    vertices, normals : (V, 3) float64
        World positions and unit vertex normals.
    triangles : (T, 3) intp
        Vertex indices of each triangle.
    triangle_polygon : (T,) intp
        Polygon each triangle belongs to.
    polygon_normals : (P, 3) float64
        Unit polygon normals (Newell), zero for degenerate polygons; a plane's grid cells
        have the plane's normal.
    polygon_points : (P, 3) float64
        A point of each polygon (its first vertex), for back-face tests.
    polygon_object : (P,) intp
        Index of the scene object each polygon belongs to.
    vertex_object : (V,) intp
        Index of the scene object each vertex belongs to.
    materials : (O, 8) float64
        Packed material of each object (``Material.packed()``).
    meshes : tuple of Mesh
        The mesh of each object.
    surfaces : SurfaceTables
        Textures and which objects have textures or vertex colours
        (:func:`pixelpath.scene.texture.surface_tables`).
    uv : (V, 2) float64
        Texture coordinates (0 for objects without); (0, 2) when no object is textured.
    colors : (V, 4) float64
        Vertex colours (1 for objects without); (0, 4) when no object has them.
    double_sided : (O,) bool
        Objects whose material draws its back faces even when back faces are culled.
    emission : (O, 3) float64
        Light each object's material emits; (0, 3) when no object emits any.
    """

    vertices: np.ndarray
    normals: np.ndarray
    triangles: np.ndarray
    triangle_polygon: np.ndarray
    polygon_normals: np.ndarray
    polygon_points: np.ndarray
    polygon_object: np.ndarray
    vertex_object: np.ndarray
    materials: np.ndarray
    meshes: tuple[Mesh, ...]
    surfaces: SurfaceTables
    uv: np.ndarray
    colors: np.ndarray
    double_sided: np.ndarray
    emission: np.ndarray

    @functools.cached_property
    def coloured(self) -> np.ndarray:
        """(O,) bool: objects whose surface colour varies (a texture or vertex colours)."""
        objects = self.surfaces.objects
        return (objects[:, TEXTURE] >= 0) | (objects[:, HAS_COLORS] != 0)

    @functools.cached_property
    def polygon_centroids(self) -> np.ndarray:
        """(P, 3) vertex average of each polygon, where flat shading evaluates the model."""
        return _stacked([_centroids(m) for m in self.meshes], (0, 3))


def object_mesh(obj: object, camera: Camera) -> Mesh:
    """Return the mesh a raster method draws for one scene object.

    Examples
    --------
    >>> from pixelpath.scene import Camera, Sphere
    >>> from pixelpath.raster.tessellate import object_mesh
    >>> len(object_mesh(Sphere((0, 0, 0), 1.0), Camera(eye=(0, 0, 5), target=(0, 0, 0))).triangles)
    5120
    """
    if isinstance(obj, Mesh):
        return obj
    if isinstance(obj, Box):
        return obj.to_mesh()
    if isinstance(obj, Sphere):
        return _sphere_mesh(obj)
    if isinstance(obj, Plane):
        return _plane_grid(obj, camera)
    raise TypeError(f"cannot rasterize a {type(obj).__name__}: expected Sphere, Plane, Box or Mesh")


class _IdentityCache:
    """The last few values computed from immutable scene objects, keyed by identity.

    Scene objects are immutable but compare by value (unhashable), so re-rendering a scene
    looks its derived arrays up by ``id``; holding the object keeps that id from being reused.
    ``key`` makes the key: ``id``, or :func:`member_ids` for a tuple of objects, which two
    scenes made from the same objects share.
    """

    def __init__(self, size: int, key: Callable[[object], Hashable] = id) -> None:
        self._entries: collections.OrderedDict[Hashable, tuple[object, object]] = (
            collections.OrderedDict()
        )
        self._size = size
        self._key = key
        self._lock = threading.Lock()  # renders may run in several threads at once

    def get(self, obj: object, compute: Callable[[object], object]) -> object:
        key = self._key(obj)  # ids of live objects: this entry holds them, they stay unique
        with self._lock:
            hit = self._entries.get(key)
            if hit is not None:
                self._entries.move_to_end(key)
                return hit[1]
        value = compute(obj)
        with self._lock:
            self._entries[key] = (obj, value)
            if len(self._entries) > self._size:
                self._entries.popitem(last=False)
        return value


def member_ids(objects: tuple) -> tuple[int, ...]:
    """Return the ids of a scene's objects: the key of what is derived from all of them."""
    return tuple(map(id, objects))


_SPHERE_MESHES = _IdentityCache(64)
# Per set of scene objects, in order (the same when only the camera changes: a new size, the
# frames of a turntable, the views of a dataset; or scenes made from the same objects), its
# geometry (see _Geometries).
_GEOMETRIES = _IdentityCache(8, member_ids)


def _sphere_mesh(sphere: Sphere) -> Mesh:
    return _SPHERE_MESHES.get(sphere, lambda s: s.to_mesh(subdivisions=SPHERE_SUBDIVISIONS))


def _plane_grid(plane: Plane, camera: Camera) -> Mesh:
    """Return a square grid on the plane, centred below the eye, covering all it can see."""
    corner, across, _, up = plane.corners(center=camera.eye, half_size=view_reach(camera))
    u, v, quads = _grid_layout()
    points = corner + u * (across - corner) + v * (up - corner)
    normals = np.broadcast_to(plane.normal, points.shape)
    return Mesh(points, quads, plane.material, normals=normals, name="plane")


@functools.cache
def _grid_layout() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return a plane grid's (N, 1) steps across and up its quad, and its (F, 4) cells.

    The same for every plane and camera: a turntable's frames, each seen from a new eye, fit
    the floor's grid afresh and only its corners change.
    """
    # Cell borders at s = ±(k / half)^2 of the way out, k = 0..half: fine near the centre.
    half = PLANE_GRID // 2
    ramp = (np.arange(half + 1) / half) ** 2
    steps = 0.5 + 0.5 * np.concatenate([-ramp[:0:-1], ramp])
    u, v = np.meshgrid(steps, steps, indexing="xy")
    n = len(steps)
    row, col = np.divmod(np.arange((n - 1) * (n - 1)), n - 1)
    first = row * n + col
    quads = np.stack([first, first + 1, first + n + 1, first + n], axis=1)
    return frozen(u.reshape(-1, 1)), frozen(v.reshape(-1, 1)), frozen(quads)


def view_reach(camera: Camera) -> float:
    """Return the largest distance from the eye of a point the camera can see.

    That is the distance to the far plane's corners: ``far · sqrt(1 + tan²(h/2) + tan²(v/2))``
    for the horizontal and vertical fields of view h and v; for an orthographic camera, whose
    view is a box ``view_height`` high, ``sqrt(far² + (width/2)² + (height/2)²)`` in world
    units. A square of this half-size centred under the eye contains every visible point of a
    plane.

    Examples
    --------
    >>> from pixelpath.scene import Camera
    >>> from pixelpath.raster.tessellate import view_reach
    >>> round(view_reach(Camera(eye=(0, 0, 1), target=(0, 0, 0), fov=90, far=10,
    ...                         width=1, height=1)), 6)  # sqrt(1 + 1 + 1) * 10
    17.320508
    """
    if camera.orthographic:
        half_v = camera.view_height / 2
        half_h = half_v * camera.aspect
        return math.sqrt(camera.far * camera.far + half_h * half_h + half_v * half_v)
    tan_v = math.tan(math.radians(camera.fov) / 2)
    tan_h = tan_v * camera.width / camera.height
    return camera.far * math.sqrt(1.0 + tan_h * tan_h + tan_v * tan_v)


def scene_geometry(scene: Scene, camera: Camera | None = None) -> SceneGeometry:
    """Collect every object of ``scene`` into one :class:`SceneGeometry`.

    Parameters
    ----------
    scene : Scene
        The scene; its objects' indices become object ids.
    camera : Camera, optional
        The camera planes are fitted to (default ``scene.camera``).

    Returns
    -------
    SceneGeometry
        Shared by later calls for the same objects in the same order (any scene made of
        them: the same scene with another camera, the frames of an animation whose objects
        do not move), so they are not tessellated again; only planes' grids follow the
        camera. Do not modify its arrays.

    Examples
    --------
    >>> from pixelpath.scene import Box, Camera, Scene
    >>> from pixelpath.raster.tessellate import scene_geometry
    >>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0)), objects=[Box((0, 0, 0), (1, 1, 1))])
    >>> scene_geometry(scene).triangles.shape
    (12, 3)
    """
    camera = camera or scene.camera
    built = _GEOMETRIES.get(scene.objects, lambda objects: _Geometries(objects, camera))
    return built.for_camera(camera)


class _Geometries:
    """The geometry of a scene's objects, for each camera in turn.

    Only planes depend on the camera (their grids are centred under the eye and reach as far
    as it sees): the geometry first built is kept, and another camera's is a copy of its
    vertices and polygon points with the planes' rows redrawn (a turntable frame of the
    showcase took 1.8 ms to tessellate afresh); the rest, polygon normals included
    (:func:`_polygon_normals`), is shared. Without planes every camera shares the first. The
    latest camera's is kept too.
    """

    def __init__(self, objects: tuple, camera: Camera) -> None:
        self.first = _build_geometry(objects, camera)
        # (plane, its vertex rows, its polygon rows, its object index) for each plane
        self.planes = [
            (obj, _rows(self.first.vertex_object, index), _rows(self.first.polygon_object, index),
             index)
            for index, obj in enumerate(objects) if isinstance(obj, Plane)
        ]
        self.latest = (_plane_key(camera), self.first)

    def for_camera(self, camera: Camera) -> SceneGeometry:
        """Return the geometry with the planes' grids fitted to ``camera``."""
        if not self.planes:
            return self.first
        key = _plane_key(camera)
        latest_key, latest = self.latest  # one read: a render in another thread may replace it
        if key != latest_key:
            latest = self._with_planes(camera)
            self.latest = (key, latest)
        return latest

    def _with_planes(self, camera: Camera) -> SceneGeometry:
        first = self.first
        vertices = first.vertices.copy()
        polygon_points = first.polygon_points.copy()
        meshes = list(first.meshes)
        for plane, vertex_rows, polygon_rows, index in self.planes:
            grid = _plane_grid(plane, camera)
            vertices[vertex_rows] = grid.vertices
            polygon_points[polygon_rows] = _first_corners(grid)
            meshes[index] = grid
        return dataclasses.replace(
            first, vertices=vertices, polygon_points=polygon_points, meshes=tuple(meshes)
        )


def _rows(owners: np.ndarray, index: int) -> slice:
    """Return the rows of a stacked per-vertex or per-polygon array of object ``index``."""
    return slice(*np.searchsorted(owners, (index, index + 1)).tolist())


def _plane_key(camera: Camera) -> tuple[float, ...]:
    """Return what a plane's grid depends on: the eye, and how far the camera sees."""
    return (*camera.eye.tolist(), view_reach(camera))


def _build_geometry(objects: tuple, camera: Camera) -> SceneGeometry:
    meshes = [object_mesh(obj, camera) for obj in objects]
    surfaces = surface_tables(meshes)
    vertex_counts = [len(m.vertices) for m in meshes]
    polygon_counts = [m.face_count for m in meshes]
    vertex_start = np.cumsum([0, *vertex_counts])[:-1]
    polygon_start = np.cumsum([0, *polygon_counts])[:-1]
    ids = np.arange(len(meshes), dtype=np.intp)
    pairs = list(zip(meshes, vertex_start, polygon_start, strict=True))
    return SceneGeometry(
        vertices=_stacked([m.vertices for m in meshes], (0, 3)),
        normals=_stacked([m.vertex_normals for m in meshes], (0, 3)),
        triangles=_stacked([m.triangles + v for m, v, _ in pairs], (0, 3), np.intp),
        triangle_polygon=_stacked([m.triangle_face + p for m, _, p in pairs], (0,), np.intp),
        polygon_normals=_stacked(list(map(_polygon_normals, objects, meshes)), (0, 3)),
        polygon_points=_stacked([_first_corners(m) for m in meshes], (0, 3)),
        polygon_object=np.repeat(ids, polygon_counts),
        vertex_object=np.repeat(ids, vertex_counts),
        materials=_stacked([m.material.packed()[None] for m in meshes], (0, 8)),
        meshes=tuple(meshes),
        surfaces=surfaces,
        uv=_per_vertex(meshes, "uv", (surfaces.objects[:, TEXTURE] >= 0)
                       | (surfaces.objects[:, GLOW] >= 0), 0.0, 2),
        colors=_per_vertex(meshes, "colors", surfaces.objects[:, HAS_COLORS] != 0, 1.0, 4),
        double_sided=np.array([m.material.double_sided for m in meshes], dtype=np.bool_),
        emission=_stacked([m.material.emission[None] for m in meshes], (0, 3))
        if any(m.material.emits for m in meshes) else np.empty((0, 3)),
    )


def _per_vertex(meshes: list[Mesh], name: str, used: np.ndarray, fill: float, width: int):
    """Stack a per-vertex attribute the kernels read for the ``used`` objects only.

    Other objects' rows hold ``fill``; with no object using it the array is empty (the
    kernels never read it), so scenes without textures or vertex colours carry nothing.
    """
    if not np.any(used):
        return np.empty((0, width))
    parts = [
        getattr(m, name) if flag else np.full((len(m.vertices), width), fill)
        for m, flag in zip(meshes, used, strict=True)
    ]
    return _stacked(parts, (0, width))


def _stacked(parts: list[np.ndarray], empty: tuple[int, ...], dtype: type = np.float64):
    """Concatenate per-object arrays (an empty array of shape ``empty`` when there are none)."""
    if not parts:
        return np.empty(empty, dtype=dtype)
    return np.ascontiguousarray(np.concatenate(parts), dtype=dtype)


def _polygon_normals(obj: object, mesh: Mesh) -> np.ndarray:
    """(F, 3) unit normal of each polygon of ``obj``'s ``mesh``.

    A plane's grid cells all lie in the plane: each has the plane's normal, exactly, whatever
    the camera the grid was fitted to (Newell's sums over cells that move with the eye differ
    from it, and from camera to camera, in the last bits), so a new camera changes no normal.
    """
    if isinstance(obj, Plane):
        return np.broadcast_to(obj.normal, (mesh.face_count, 3))
    return mesh.face_normals


def _first_corners(mesh: Mesh) -> np.ndarray:
    """(F, 3) first vertex of each polygon."""
    return mesh.vertices[mesh.face_indices[mesh.face_offsets[:-1]]]


def _centroids(mesh: Mesh) -> np.ndarray:
    """(F, 3) vertex average of each polygon."""
    sums = np.add.reduceat(mesh.vertices[mesh.face_indices], mesh.face_offsets[:-1], axis=0)
    return sums / mesh.face_sizes[:, None]
