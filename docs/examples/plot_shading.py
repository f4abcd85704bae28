"""
Illumination and shading
========================

The notes' illumination model term by term (with the corrected worked example), the
highlight for several shininess exponents, and flat, Gouraud and Phong shading of the same
faceted ball.
"""

import dataclasses

import pixelpath as pp
from pixelpath import lighting
from pixelpath.figures.shading import highlight_strip, shading_comparison

# %%
# The notes' worked example: ka = 0.2, kd = 0.6, ks = 0.5, n = 20, Ia = 0.2, IL = 1,
# N·L = 0.707, R·V = 0.866. (0.866)^20 is 0.0563, so I = 0.4923 (the notes print 0.47005).

terms = lighting.phong_terms(ka=0.2, kd=0.6, ks=0.5, shininess=20, ambient=0.2, light=1.0,
                             n_dot_l=0.707, r_dot_v=0.866)
print(terms.ambient, terms.diffuse, terms.specular, terms.total)
print(lighting.reflect([1.0, 1.0, 0.0], [0.0, 1.0, 0.0]))  # R = 2(N·L)N - L

# %%
# Flat shading evaluates the model once per face, Gouraud at the vertices (intensities
# interpolated along edges, then spans), Phong at every pixel (normals interpolated):

shading_comparison().save("shading.png")

# %%
# The highlight narrows as n grows; the numbers are (R·V)^n at 30° and 60° and the
# half-width arccos(0.5^(1/n)), as in the notes' specular table:

highlight_strip(size=120).save("highlight.png")

# %%
# The bundled showcase in the three shadings:

scene = pp.load_scene(pp.scene.bundled_scene("showcase"))
small = dataclasses.replace(scene, camera=scene.camera.with_size(240, 150))
for shading in ("flat", "gouraud", "phong"):
    pp.render(small, shading=shading).save(f"showcase-{shading}.png")

# %%
# Where Gouraud and Phong differ most: highlights that fall between the vertices of large
# faces. The bundled ``facets`` scene (icospheres of 20, 80 and 1280 faces), Gouraud then Phong:

facets = pp.load_scene(pp.scene.bundled_scene("facets"))
facets = dataclasses.replace(facets, camera=facets.camera.with_size(240, 150))
pp.render(facets, shading="gouraud").save("facets-gouraud.png")
pp.render(facets, shading="phong").save("facets-phong.png")
