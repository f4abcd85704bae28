"""One pixel's tree of rays, as data and as the notes would write it out (``pixelpath ray``).

:func:`ray_tree` runs the renderer's own per-pixel kernel with a log switched on, so the tree is
exactly what ``render(scene, method="raytrace")`` traced for that pixel: every ray with its
origin and direction, every hit with t, point and normal, the local Phong terms with each
light's shadow test, the reflected and refracted rays with their weights, and, where a sphere
is hit, the notes' quadratic with its discriminant and roots. Summing ``weight × I_local`` over
the tree in the order the rays were traced gives the rendered pixel bit for bit
(:attr:`RayTree.color`); each node's :attr:`RayNode.color` is the notes' recursive form
``I = I_local + kr I_R + kt I_T``.

Examples
--------
>>> import pixelpath as pp
>>> from pixelpath.raytrace import ray_tree
>>> mirror = pp.Material(color=(0.9, 0.9, 0.9), kd=0.2, reflectivity=0.7)
>>> scene = pp.Scene(
...     pp.Camera(eye=(0, 1, 5), target=(0, 0.5, 0), width=64, height=48),
...     [pp.Sphere((0, 0.5, 0), 1, mirror), pp.Plane((0, -0.5, 0), (0, 1, 0))],
...     lights=[pp.PointLight((3, 5, 4))],
... )
>>> tree = ray_tree(scene, (32, 24))
>>> tree.root.kind, tree.root.object, tree.root.reflected.kind, tree.rays
('primary', 0, 'reflected', 2)
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from pixelpath.scene import Plane, Scene, Sphere

__all__ = ["LightTest", "RayNode", "RayTree", "SphereQuadratic", "ray_tree", "sphere_quadratic"]

LOG_LIMIT = 1 << 14  # rays logged per pixel at most (the colour is exact beyond it)
_KINDS = ("primary", "reflected", "refracted")


@dataclasses.dataclass(frozen=True)
class SphereQuadratic:
    """The notes' ray-sphere equation ``a t² + b t + c = 0`` for one ray and sphere.

    ``a = d·d``, ``b = 2 d·(P0 − C)``, ``c = |P0 − C|² − r²``; ``discriminant = b² − 4ac`` and
    ``roots = (−b ∓ √discriminant) / 2a`` (empty when it is negative).
    """

    a: float
    b: float
    c: float
    discriminant: float
    roots: tuple[float, ...]


@dataclasses.dataclass(frozen=True)
class LightTest:
    """One light at one hit: its direction, the shadow test, and its diffuse and specular terms.

    ``let_through`` is the fraction of the light the shadow ray lets through (1 unobstructed,
    0 blocked by the opaque object ``blocker``, between for transparent ones); no shadow ray is
    cast (``tested`` False) when the light is behind the surface (N·L <= 0).
    """

    light: int
    to_light: np.ndarray
    n_dot_l: float
    tested: bool
    let_through: float
    blocker: int | None
    diffuse: np.ndarray
    specular: np.ndarray


@dataclasses.dataclass(frozen=True)
class RayNode:
    """One ray of the tree and what it found.

    Attributes
    ----------
    kind : {"primary", "reflected", "refracted"}
    depth : int
        0 for the eye's ray, one more per bounce.
    weight : float
        Product of the coefficients (kr or kt) on the way from the eye: this ray's share of the
        pixel.
    origin, direction : (3,) ndarray
        The ray as traced (secondary rays start ``epsilon`` off the surface).
    t : float
        Distance of the hit in units of ``|direction|``; ``inf`` when nothing is hit.
    object : int
        Index into ``scene.objects``; -1 when nothing is hit.
    point, normal : (3,) ndarray or None
        Hit point and the unit shading normal turned towards the ray.
    entering : bool
        The ray hits the outside of the surface (False: it leaves an object, or sees a back face).
    local : (3,) ndarray
        ``I_local``, the local Phong intensity plus the material's emission (the background
        colour on a miss).
    ambient : (3,) ndarray
        ``ka·Ia·C``, C the surface colour at the hit (the material's, times its texture and
        vertex colours there), as in the lights' diffuse terms.
    lights : tuple of LightTest
    quadratic : SphereQuadratic or None
        Where a sphere is hit.
    kr, kt : float
        Weights given to the reflected and refracted rays (after total internal reflection
        or Fresnel moved light from one to the other).
    total_internal_reflection : bool
    fresnel : float
        Schlick's reflectance (0 unless ``fresnel=True`` and the surface is transparent).
    eta : float
        n1/n2 at this surface (1 unless it is transparent).
    reflected, refracted : RayNode or None
        The child rays (None where not traced: depth, weight, or a zero coefficient).
    sample : int
        Which sample of the pixel this tree belongs to.
    surface : (3,) ndarray or None
        C, the surface colour at the hit: the material's colour times its texture and vertex
        colours there (the material's colour alone on a plain surface); None on a miss.
    """

    kind: str
    depth: int
    weight: float
    origin: np.ndarray
    direction: np.ndarray
    t: float
    object: int
    point: np.ndarray | None
    normal: np.ndarray | None
    entering: bool
    local: np.ndarray
    ambient: np.ndarray
    lights: tuple[LightTest, ...]
    quadratic: SphereQuadratic | None
    kr: float
    kt: float
    total_internal_reflection: bool
    fresnel: float
    eta: float
    reflected: RayNode | None
    refracted: RayNode | None
    sample: int
    surface: np.ndarray | None = None

    @property
    def hit(self) -> bool:
        """Whether the ray hit an object."""
        return self.object >= 0

    @property
    def color(self) -> np.ndarray:
        """``I = I_local + kr·I_R + kt·I_T`` over this node's subtree (unclamped)."""
        total = self.local.copy()
        if self.reflected is not None:
            total += self.kr * self.reflected.color
        if self.refracted is not None:
            total += self.kt * self.refracted.color
        return total

    def walk(self):
        """Yield this node and its descendants, depth first, reflected before refracted."""
        yield self
        for child in (self.reflected, self.refracted):
            if child is not None:
                yield from child.walk()


@dataclasses.dataclass(frozen=True)
class RayTree:
    """The rays traced for one pixel, one tree per sample.

    Attributes
    ----------
    pixel : (int, int)
        (x, y), column and row (row 0 at the top).
    roots : tuple of RayNode
        The eye ray of each sample.
    color : (3,) ndarray of float64
        The pixel: the mean over samples of the clamped sum of ``weight × I_local`` over the
        sample's rays, in the order they were traced (exactly the renderer's arithmetic).
    rgb : (3,) ndarray of float32
        The pixel as the rendered image holds it.
    depth : float
        Depth of the nearest sample's first hit along the viewing axis (inf on a miss).
    object : int
        The object that sample hit (-1 for none).
    rays : int
        Rays traced (shadow rays not counted; they are in each node's ``lights``).
    truncated : bool
        More than ``LOG_LIMIT`` rays: only the first ones are in ``roots``.
    """

    pixel: tuple[int, int]
    roots: tuple[RayNode, ...]
    color: np.ndarray
    rgb: np.ndarray
    depth: float
    object: int
    rays: int
    truncated: bool
    scene: Scene = dataclasses.field(repr=False)

    @property
    def root(self) -> RayNode:
        """The eye ray of the first sample (the only one with ``samples=1``)."""
        return self.roots[0]

    def __str__(self) -> str:
        return "\n".join(_describe_tree(self))

    def figure(self, overview: Any = None):
        """Return the tree drawn over the scene, by its camera and from aside (a PIL image).

        Each kind of ray has its colour (see :mod:`pixelpath.figures.ray_tree`); ``overview``
        is the second panel's camera (by default one looking across the view).

        Examples
        --------
        >>> import pixelpath as pp
        >>> from pixelpath.raytrace import ray_tree
        >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=40, height=30),
        ...                  [pp.Sphere((0, 0, 0), 1)], lights=[pp.PointLight((2, 3, 4))])
        >>> ray_tree(scene, (20, 15)).figure().mode
        'RGB'
        """
        from pixelpath.figures.ray_tree import ray_tree_figure

        return ray_tree_figure(self, overview)

    def _repr_png_(self) -> bytes:
        from pixelpath.figures._canvas import png_bytes

        return png_bytes(self.figure())


def ray_tree(
    scene: Scene,
    pixel: tuple[int, int],
    *,
    max_depth: int = 5,
    samples: int = 1,
    shading: str = "phong",
    backface_cull: bool = True,
    blinn: bool = False,
    fresnel: bool = False,
) -> RayTree:
    """Return the tree of rays the ray tracer follows for one pixel.

    Parameters
    ----------
    scene : Scene
    pixel : (int, int)
        (x, y): column and row of the camera's image, row 0 at the top.
    max_depth, samples, shading, backface_cull, blinn, fresnel
        As for ``pixelpath.render(scene, method="raytrace", ...)``; the tree is the one that
        call traces for this pixel.

    Returns
    -------
    RayTree
        ``str(tree)`` prints it the way the notes work an example.

    Raises
    ------
    ValueError
        A pixel outside the image, ``max_depth`` < 0, ``samples`` < 1, unknown shading.

    Examples
    --------
    >>> import pixelpath as pp
    >>> from pixelpath.raytrace import ray_tree
    >>> scene = pp.Scene(pp.Camera(eye=(0, 0, 5), target=(0, 0, 0), width=9, height=9),
    ...                  [pp.Sphere((0, 0, 0), 1)], lights=[pp.PointLight((0, 0, 5))])
    >>> tree = ray_tree(scene, (4, 4))
    >>> tree.root.t, tree.root.quadratic.discriminant, tree.root.quadratic.roots
    (4.0, 4.0, (4.0, 6.0))
    >>> print(tree)  # doctest: +ELLIPSIS
    pixel (4, 4) of 9×9: rgb (1, 1, 1)
    1 rays traced
    ...
    """
    from pixelpath._validate import choice, int_in
    from pixelpath.contract import RenderOptions
    from pixelpath.raytrace import _whitted_kernels as wk
    from pixelpath.raytrace._records import new_work
    from pixelpath.raytrace.tracer import pack

    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a pixelpath Scene, got {type(scene).__name__}")
    x, y = _pixel(pixel, scene.camera)
    choice(shading, "shading", ("flat", "gouraud", "phong"))
    options = RenderOptions(
        shading=shading,
        backface_cull=bool(backface_cull),
        blinn=bool(blinn),
        max_depth=int_in(max_depth, "max_depth", 0, 64, "reflection/refraction bounces"),
        samples=int_in(samples, "samples", 1, 1024, "samples per pixel"),
        fresnel=bool(fresnel),
    )
    world, settings, bvh_depth, _ = pack(scene, scene.camera, options)
    bound = options.samples * (2 ** min(options.max_depth + 1, 20) - 1)
    work = new_work(world, settings, bvh_depth, min(bound, LOG_LIMIT), 1)
    pixel_fields = wk.trace_pixel(x, y, world, settings, work)
    red, green, blue, depth, obj = pixel_fields[: wk.PIXEL_NORMAL].tolist()
    logged = int(work.logged[0])
    count = min(logged, len(work.log))
    roots = _nodes(scene, world, settings, work.log[:count], work.log_lights[:count])
    color = np.array([red, green, blue])
    return RayTree(
        pixel=(x, y),
        roots=roots,
        color=color,
        rgb=color.astype(np.float32),
        depth=float(np.float32(depth)),
        object=int(obj),
        rays=logged,
        truncated=logged > count,
        scene=scene,
    )


def _pixel(pixel: Any, camera: Any) -> tuple[int, int]:
    try:
        x, y = pixel
    except (TypeError, ValueError):
        raise TypeError(f"pixel must be (x, y), two ints, got {pixel!r}") from None
    if not all(isinstance(c, int | np.integer) and not isinstance(c, bool) for c in (x, y)):
        raise TypeError(f"pixel must be (x, y), two ints, got {pixel!r}")
    if not (0 <= x < camera.width and 0 <= y < camera.height):
        raise ValueError(
            f"pixel must lie in the {camera.width}×{camera.height} image (0 <= x < "
            f"{camera.width}, 0 <= y < {camera.height}), got {(int(x), int(y))}"
        )
    return int(x), int(y)


def _nodes(scene, world, settings, log, log_lights) -> tuple[RayNode, ...]:
    """Rebuild the trees from the log (rows in the order traced, each naming its parent)."""
    from pixelpath.raytrace import _records as rec

    children: dict[int, dict[str, RayNode]] = {}
    nodes: dict[int, RayNode] = {}
    for row in range(len(log) - 1, -1, -1):  # children were traced after their parent
        record = log[row]
        node = _node(scene, world, settings, record, log_lights[row], children.get(row, {}))
        nodes[row] = node
        parent = int(record[rec.PARENT])
        if parent >= 0:
            children.setdefault(parent, {})[node.kind] = node
    return tuple(nodes[row] for row in range(len(log)) if log[row, rec.PARENT] < 0)


def _node(scene, world, settings, record, light_records, children) -> RayNode:
    from pixelpath.raytrace import _records as rec

    origin = record[rec.ORIGIN : rec.ORIGIN + 3].copy()
    direction = record[rec.DIRECTION : rec.DIRECTION + 3].copy()
    obj = int(record[rec.OBJECT])
    hit = obj >= 0
    point = record[rec.POINT : rec.POINT + 3].copy() if hit else None
    normal = record[rec.NORMAL : rec.NORMAL + 3].copy() if hit else None
    local = record[rec.LOCAL : rec.LOCAL + 3].copy()
    ambient = np.zeros(3)
    lights: tuple[LightTest, ...] = ()
    quadratic = None
    surface = record[rec.COLOR : rec.COLOR + 3].copy() if hit else None
    if hit:
        # the material with the surface colour C the tracer used at the hit (its texture and
        # vertex colours included)
        material = world.materials[obj].copy()
        material[:3] = surface
        ambient = material[3] * world.ambient * material[:3]
        lights = tuple(
            _light_test(world, settings, material, k, point, normal, origin, light_records[k])
            for k in range(len(world.lights))
        )
        if isinstance(scene.objects[obj], Sphere):
            sphere = scene.objects[obj]
            quadratic = sphere_quadratic(origin, direction, sphere.center, sphere.radius)
    return RayNode(
        kind=_KINDS[int(record[rec.KIND])],
        depth=int(record[rec.DEPTH]),
        weight=float(record[rec.WEIGHT]),
        origin=origin,
        direction=direction,
        t=float(record[rec.T]),
        object=obj,
        point=point,
        normal=normal,
        entering=hit and bool(record[rec.ENTERING]),
        local=local,
        ambient=ambient,
        lights=lights,
        quadratic=quadratic,
        kr=float(record[rec.KR]) if hit else 0.0,
        kt=float(record[rec.KT]) if hit else 0.0,
        total_internal_reflection=hit and bool(record[rec.TOTAL_REFLECTION]),
        fresnel=float(record[rec.FRESNEL]) if hit else 0.0,
        eta=float(record[rec.ETA]) if hit else 1.0,
        reflected=children.get("reflected"),
        refracted=children.get("refracted"),
        sample=int(record[rec.SAMPLE]),
        surface=surface,
    )


def _light_test(world, settings, material, k, point, normal, eye, record) -> LightTest:
    """Light k's terms at a hit, by the public Phong model, scaled by its shadow test."""
    from pixelpath.lighting import phong_terms

    light = world.lights[k]
    if light[0] == 0.0:
        to_light = light[1:4] - point
        length = np.linalg.norm(to_light)
        to_light = to_light / length if length > 0 else np.zeros(3)
    else:
        to_light = -light[1:4]
    n_dot_l = float(normal @ to_light)
    tested = record[0] >= 0.0
    through = float(record[0]) if tested else 0.0
    zero = np.zeros(3)
    if not tested or through == 0.0:
        return LightTest(k, to_light, n_dot_l, tested, through, _blocker(record), zero, zero)
    to_eye = eye - point
    to_eye = to_eye / np.linalg.norm(to_eye)
    if settings.blinn:
        halfway = to_light + to_eye
        cosine = float(normal @ halfway / np.linalg.norm(halfway))
    else:
        cosine = float((2.0 * n_dot_l * normal - to_light) @ to_eye)
    terms = phong_terms(
        ka=0.0, kd=material[4] * material[:3], ks=material[5], shininess=material[6],
        ambient=0.0, light=light[4:7] * through, n_dot_l=min(max(n_dot_l, -1.0), 1.0),
        r_dot_v=min(max(cosine, -1.0), 1.0),
    )
    return LightTest(k, to_light, n_dot_l, True, through, None, terms.diffuse, terms.specular)


def _blocker(record) -> int | None:
    return int(record[1]) if record[0] == 0.0 and record[1] >= 0 else None


def sphere_quadratic(origin: Any, direction: Any, center: Any, radius: float) -> SphereQuadratic:
    """Set up the notes' ray-sphere quadratic for one ray and solve it.

    Examples
    --------
    >>> from pixelpath.raytrace.explain import sphere_quadratic
    >>> q = sphere_quadratic((0, 0, 5), (0, 0, -1), (0, 0, 0), 1.0)
    >>> q.a, q.b, q.c, q.discriminant, q.roots
    (1.0, -10.0, 24.0, 4.0, (4.0, 6.0))
    """
    direction = np.asarray(direction, dtype=np.float64)
    f = np.asarray(origin, dtype=np.float64) - np.asarray(center, dtype=np.float64)
    a = float(direction @ direction)
    b = float(2.0 * direction @ f)
    c = float(f @ f - float(radius) ** 2)
    disc = b * b - 4.0 * a * c
    roots: tuple[float, ...] = ()
    if disc >= 0:
        root = math.sqrt(disc)
        roots = ((-b - root) / (2 * a), (-b + root) / (2 * a))
    return SphereQuadratic(a, b, c, disc, roots)


def _v(values) -> str:
    return "(" + ", ".join(f"{float(x):.4g}" for x in values) + ")"


def _object_name(scene: Scene, index: int) -> str:
    obj = scene.objects[index]
    name = getattr(obj.material, "name", None)
    label = type(obj).__name__.lower()
    return f"object {index} ({label}{', material ' + repr(name) if name else ''})"


def _colouring(obj: Any) -> str:
    """Say what colours ``obj``'s surface beyond its material ("" when nothing does)."""
    uv, colors = getattr(obj, "uv", None), getattr(obj, "colors", None)
    parts = []
    if uv is not None and obj.material.texture is not None:
        parts.append("the texture at the hit's texture coordinates")
    if colors is not None:
        parts.append("the vertex colours there")
    return " × ".join(parts)


def _describe_tree(tree: RayTree) -> list[str]:
    camera = tree.scene.camera
    x, y = tree.pixel
    lines = [f"pixel ({x}, {y}) of {camera.width}×{camera.height}: rgb {_v(tree.rgb)}"]
    count = len(tree.roots)
    sample_note = "" if count == 1 else f", the mean of {count} samples' clamped colours"
    lines.append(f"{tree.rays} rays traced{sample_note}")
    if tree.truncated:
        lines.append(f"(only the first {sum(1 for r in tree.roots for _ in r.walk())} are shown)")
    for root in tree.roots:
        lines.append("")
        if count > 1:
            lines.append(f"sample {root.sample}:")
        lines += _describe_node(tree.scene, root, "")
        lines.append(f"  = {_v(root.color)}, clamped to [0, 1]: {_v(np.clip(root.color, 0, 1))}")
    return lines


def _describe_node(scene: Scene, node: RayNode, indent: str) -> list[str]:
    head = f"{indent}{node.kind} ray (depth {node.depth}, weight {node.weight:.4g})"
    lines = [f"{head}: P0 = {_v(node.origin)}, d = {_v(node.direction)}"]
    pad = indent + "  "
    if not node.hit:
        lines.append(f"{pad}hits nothing: background {_v(node.local)}")
        return lines
    lines.append(f"{pad}hits {_object_name(scene, node.object)} at t = {node.t:.6g}")
    if node.quadratic is not None:
        q = node.quadratic
        roots = ", ".join(f"{r:.6g}" for r in q.roots)
        lines.append(
            f"{pad}  ray-sphere: a = d·d = {q.a:.6g}, b = 2 d·(P0 − C) = {q.b:.6g}, "
            f"c = |P0 − C|² − r² = {q.c:.6g}; b² − 4ac = {q.discriminant:.6g}; "
            f"t = (−b ∓ √(b² − 4ac)) / 2a = {roots}"
        )
    if isinstance(scene.objects[node.object], Plane):
        lines.append(f"{pad}  ray-plane: t = n·(Q − P0) / (n·d) = {node.t:.6g}")
    side = "outside" if node.entering else "inside or back"
    lines.append(f"{pad}P = {_v(node.point)}, N = {_v(node.normal)} (seen from the {side})")
    hit = scene.objects[node.object]
    material = hit.material
    colouring = _colouring(hit)
    if colouring:  # a plain surface's C is its material's colour, which the terms show
        lines.append(f"{pad}surface colour C = {_v(node.surface)}: the material's "
                     f"{_v(material.color)} × {colouring}")
    lines.append(f"{pad}ambient ka·Ia·C = {_v(node.ambient)}")
    for test in node.lights:
        label = f"{pad}light {test.light}: L = {_v(test.to_light)}, N·L = {test.n_dot_l:.4g}"
        if not test.tested:
            lines.append(f"{label} <= 0: behind the surface, no shadow ray")
        elif test.let_through == 0.0:
            blocker = "" if test.blocker is None else f" by {_object_name(scene, test.blocker)}"
            lines.append(f"{label}; shadow ray blocked{blocker}: in shadow")
        else:
            shade = "lit" if test.let_through == 1.0 else f"lets {test.let_through:.4g} through"
            lines.append(
                f"{label}; shadow ray {shade}: diffuse {_v(test.diffuse)}, "
                f"specular {_v(test.specular)}"
            )
    if material.emits:
        scaled = (" × the emission texture there"
                  if material.emission_texture is not None and getattr(hit, "uv", None) is not None
                  else "")
        lines.append(f"{pad}emission E = {_v(material.emission)}{scaled} (added to I_local)")
    lines.append(f"{pad}I_local = {_v(node.local)}")
    if node.total_internal_reflection:
        lines.append(f"{pad}total internal reflection (η = {node.eta:.4g}): kt goes to kr")
    elif node.fresnel > 0.0:
        lines.append(f"{pad}Schlick's Fresnel reflectance F = {node.fresnel:.4g}")
    for child, weight, formula in (
        (node.reflected, node.kr, "R = d − 2(d·N)N"),
        (node.refracted, node.kt, "T = ηd + (η cos θi − cos θt)N, η = " + f"{node.eta:.4g}"),
    ):
        if child is not None:
            lines.append(f"{pad}{child.kind} ray, {formula}, weight k = {weight:.4g}:")
            lines += _describe_node(scene, child, pad + "  ")
    if node.reflected is not None or node.refracted is not None:
        parts = [f"I_local {_v(node.local)}"]
        if node.reflected is not None:
            parts.append(f"kr·I_R {node.kr:.4g} × {_v(node.reflected.color)}")
        if node.refracted is not None:
            parts.append(f"kt·I_T {node.kt:.4g} × {_v(node.refracted.color)}")
        lines.append(f"{pad}I = " + " + ".join(parts) + f" = {_v(node.color)}")
    return lines
