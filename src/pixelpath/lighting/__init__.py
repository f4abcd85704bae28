"""Illumination: the Phong model of the notes, Blinn-Phong, and the kernel the renderers call.

* :func:`phong_terms` evaluates ``I = ka Ia + kd IL max(0, N.L) + ks IL max(0, R.V)^n`` term by
  term, the exam form of the notes (with the errata of SPEC section 9 corrected);
* :func:`reflect` gives ``R = 2(N.L)N - L`` and :func:`phong_geometry` derives every vector and
  cosine from N, L, V or from the surface, light and eye points;
* :func:`shade` evaluates the model at many points for several coloured point and directional
  lights, Phong or Blinn-Phong, in a compiled parallel loop;
* :func:`pack_lights`, :func:`pack_material` and :func:`pack_ambient` build the flat arrays the
  scalar kernel ``pixelpath.lighting._kernels.shade_point`` reads (for use inside other kernels).

Examples
--------
>>> from pixelpath import lighting
>>> round(lighting.phong_terms(ka=0.2, kd=0.6, ks=0.5, shininess=20, ambient=0.2, light=1,
...                            n_dot_l=0.707, r_dot_v=0.866).total, 4)
0.4923
"""

from __future__ import annotations

from pixelpath.lighting.packing import pack_ambient, pack_lights, pack_material
from pixelpath.lighting.phong import (
    PhongGeometry,
    PhongTerms,
    phong_geometry,
    phong_terms,
    reflect,
    shade,
)

__all__ = [
    "PhongGeometry",
    "PhongTerms",
    "pack_ambient",
    "pack_lights",
    "pack_material",
    "phong_geometry",
    "phong_terms",
    "reflect",
    "shade",
]
