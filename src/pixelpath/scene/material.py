"""Surface materials for the Phong illumination model of the notes (section 5 of the spec).

``I = ka·Ia·C + Σ_lights [kd·IL·C·max(0, N·L) + ks·IL·max(0, R·V)^n]`` per colour channel, where C
is the material's ``color``: the object colour tints ambient and diffuse light, while highlights
take the light's colour. ``reflectivity``, ``transparency`` and ``ior`` are used by the ray tracer.

``emission`` (not in the notes' model; glTF's ``emissiveFactor``, an MTL file's ``Ke``) is light
the surface gives off itself: ``I + E``, the same from every side, in every method and in the
ray tracer (where reflections and refractions show it too), and the same at every point unless
an ``emission_texture`` (glTF's ``emissiveTexture``, MTL's ``map_Ke``) scales it point by point.
It lights no other surface: an emissive material is not a light source.

``alpha_cutoff`` makes a material *alpha-tested* (glTF's ``alphaMode`` MASK): the surface's
alpha, ``alpha`` × the vertex colours' alpha × the texture's alpha, is compared with the cutoff
at every point drawn, and where it is below the surface is cut away, as if it were not there:
every raster method shows what lies behind, and the ray tracer's eye, shadow, reflected and
refracted rays pass through. There is no partial coverage (no blending): a point is kept
whole or cut.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from pixelpath import _validate as v
from pixelpath.scene._record import Record
from pixelpath.scene.texture import FILTERS, WRAPS, Texture


@dataclasses.dataclass(frozen=True, eq=False)
class Material(Record):
    """Phong material: colour, ambient/diffuse/specular coefficients, shininess, optics.

    Parameters
    ----------
    color : (3,) array_like
        Object colour (r, g, b), non-negative; stored as a read-only float64 array.
    ka, kd, ks : float
        Ambient, diffuse and specular reflection coefficients, each >= 0.
    shininess : float
        Phong exponent n, >= 0.
    reflectivity, transparency : float
        Fractions in [0, 1] of mirror reflection and transmission (ray tracer only).
    ior : float
        Index of refraction, > 0 (ray tracer only).
    name : str, optional
        The name the material has in a scene file; not part of equality.
    texture : Texture, path or (H, W, 3|4) array_like, optional
        A picture that modulates ``color`` (and the vertex colours) at each point of the
        surface through its texture coordinates; anything but a :class:`Texture` is made
        into one (see :mod:`pixelpath.scene.texture` for how colours are decoded).
    texture_filter : {"trilinear", "bilinear", "nearest"}
        How the picture is sampled: the nearest texel, a bilinear blend of the four nearest,
        or a blend of two mip-map levels chosen by the pixel's footprint (no shimmer when a
        textured surface recedes).
    texture_wrap : {"repeat", "clamp", "mirror"}
        What lies outside [0, 1] in texture space.
    double_sided : bool
        Draw the faces seen from behind too (lit with the normal turned to the viewer), even
        when back faces are culled (glTF's ``doubleSided``).
    alpha : float
        Alpha of the material colour in [0, 1] (glTF's ``baseColorFactor[3]``): multiplies
        the texture's and the vertex colours' alpha. Only the alpha test reads it.
    alpha_cutoff : float, optional
        None (the default): the surface is opaque and every alpha is ignored (glTF's OPAQUE).
        A number >= 0: points whose alpha is below it are cut away (glTF's MASK with its
        ``alphaCutoff``, 0.5 by default there); 0 cuts nothing, above 1 everything. The
        test reads the texture's base level with the material's filter (trilinear filtering
        reads it bilinearly), so a cut-out's outline does not move with distance, and it is
        the same in every method and in the ray tracer.
    emission : (3,) array_like
        Light the surface emits (r, g, b), non-negative, added to the shaded intensity; the
        default (0, 0, 0) emits none.
    emission_texture : Texture, path or (H, W, 3|4) array_like, optional
        A picture that scales ``emission`` at each point, channel by channel (its alpha is
        ignored), read through the mesh's texture coordinates with the material's
        ``texture_filter`` and ``texture_wrap``, like ``texture``; on an object without
        texture coordinates it is left out. Nothing is emitted where ``emission`` is zero.

    Examples
    --------
    >>> from pixelpath.scene import Material
    >>> Material(color=(1, 0, 0), kd=0.5).packed().tolist()
    [1.0, 0.0, 0.0, 0.1, 0.5, 0.3, 32.0, 0.0]

    A leaf cut out of a square by its texture's alpha (transparent texels drawn as holes):

    >>> import numpy as np
    >>> leaf = np.zeros((2, 2, 4))
    >>> leaf[0, 0] = (0.2, 0.6, 0.1, 1.0)  # one opaque green texel, three transparent ones
    >>> Material(texture=leaf, alpha_cutoff=0.5).alpha_cutoff
    0.5
    """

    color: Any = (1.0, 1.0, 1.0)
    ka: float = 0.1
    kd: float = 0.7
    ks: float = 0.3
    shininess: float = 32.0
    reflectivity: float = 0.0
    transparency: float = 0.0
    ior: float = 1.0
    name: str | None = dataclasses.field(default=None, compare=False)
    texture: Any = None
    texture_filter: str = "trilinear"
    texture_wrap: str = "repeat"
    double_sided: bool = False
    alpha: float = 1.0
    alpha_cutoff: float | None = None
    emission: Any = (0.0, 0.0, 0.0)
    emission_texture: Any = None

    def __post_init__(self) -> None:
        self._set(
            color=v.colour(self.color, "color"),
            ka=v.real(self.ka, "ka", minimum=0.0),
            kd=v.real(self.kd, "kd", minimum=0.0),
            ks=v.real(self.ks, "ks", minimum=0.0),
            shininess=v.real(self.shininess, "shininess", minimum=0.0),
            reflectivity=_fraction(self.reflectivity, "reflectivity"),
            transparency=_fraction(self.transparency, "transparency"),
            ior=v.real(self.ior, "ior", positive=True),
            name=_name(self.name),
            texture=_texture(self.texture),
            texture_filter=_choice(self.texture_filter, "texture_filter", FILTERS),
            texture_wrap=_choice(self.texture_wrap, "texture_wrap", WRAPS),
            double_sided=_flag(self.double_sided, "double_sided"),
            alpha=_fraction(self.alpha, "alpha"),
            alpha_cutoff=_cutoff(self.alpha_cutoff),
            emission=v.colour(self.emission, "emission"),
            emission_texture=_texture(self.emission_texture),
        )

    @property
    def emits(self) -> bool:
        """Whether the material emits light (an ``emission`` above zero).

        Examples
        --------
        >>> from pixelpath.scene import Material
        >>> Material().emits, Material(emission=(0.5, 0.0, 0.0)).emits
        (False, True)
        """
        return bool(self.emission.any())

    def packed(self) -> np.ndarray:
        """Return the (8,) float64 row ``[r, g, b, ka, kd, ks, shininess, 0.0]`` kernels read.

        Examples
        --------
        >>> from pixelpath.scene import Material
        >>> Material().packed().shape
        (8,)
        """
        r, g, b = self.color
        return np.array([r, g, b, self.ka, self.kd, self.ks, self.shininess, 0.0])


def _name(value: Any) -> str | None:
    if value is not None and not isinstance(value, str):
        raise TypeError(f"name must be a str, got {type(value).__name__}")
    return value


def _fraction(value: Any, name: str) -> float:
    result = v.real(value, name, minimum=0.0)
    if result > 1.0:
        raise ValueError(f"{name} must lie in [0, 1], got {result}")
    return result


def _cutoff(value: Any) -> float | None:
    if value is None:
        return None
    return v.real(value, "alpha_cutoff", minimum=0.0)


def _texture(value: Any) -> Texture | None:
    if value is None or isinstance(value, Texture):
        return value
    return Texture(value)


def _choice(value: Any, name: str, choices: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(choices)}; got {value!r}")
    return value


def _flag(value: Any, name: str) -> bool:
    if not isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be a bool, got {type(value).__name__}")
    return bool(value)
