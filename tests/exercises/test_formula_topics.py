"""Answers of the colour, illumination, shading, ray and clipping topics, recomputed here.

Each check is independent of pixelpath's own code: colorsys for colours, the formulas of the
notes written out in NumPy, barycentric interpolation for Gouraud, the quadratic formula for
rays, Snell's law by angles, and shapely for clipped areas.
"""

from __future__ import annotations

import colorsys
import math

import numpy as np
import pytest
import shapely

from pixelpath import exercises

SEEDS = range(40)


def _all(topic: str):
    for difficulty in exercises.DIFFICULTIES:
        for seed in SEEDS:
            yield exercises.make(topic, seed, difficulty)


def test_rgb_hsv_agrees_with_colorsys():
    for ex in _all("rgb-hsv"):
        h, s, v = colorsys.rgb_to_hsv(*ex.params["rgb"])
        assert ex.answer["h"] == pytest.approx(360 * h % 360, abs=1e-9)
        assert (ex.answer["s"], ex.answer["v"]) == pytest.approx((s, v), abs=1e-12)


@pytest.mark.parametrize("topic", ["hsv-rgb", "hsv-cmy"])
def test_hsv_conversions_agree_with_colorsys(topic):
    for ex in _all(topic):
        h, s, v = ex.params["hsv"]
        rgb = np.array(colorsys.hsv_to_rgb(h / 360, s, v))
        got = [ex.answer[k] for k in ("rgb" if topic == "hsv-rgb" else "cmy")]
        expected = rgb if topic == "hsv-rgb" else 1 - rgb
        assert got == pytest.approx(expected.tolist(), abs=1e-12)


def test_rgb_yiq_cmy_and_cmyk_follow_the_notes_formulas():
    yiq = np.array([[0.299, 0.587, 0.114], [0.596, -0.274, -0.322], [0.211, -0.523, 0.312]])
    for ex in _all("rgb-yiq"):
        expected = yiq @ ex.params["rgb"]
        assert [ex.answer[k] for k in "yiq"] == pytest.approx(expected.tolist(), abs=1e-12)
    for ex in _all("rgb-cmy"):
        assert [ex.answer[k] for k in "cmy"] == pytest.approx([1 - x for x in ex.params["rgb"]])
    for ex in _all("rgb-cmyk"):
        c, m, y = (1 - x for x in ex.params["rgb"])
        k = min(c, m, y)
        primes = [0.0] * 3 if k == 1 else [(x - k) / (1 - k) for x in (c, m, y)]
        assert [ex.answer[n] for n in "cmyk"] == pytest.approx([*primes, k], abs=1e-12)


def _phong(p, n_dot_l, r_dot_v):
    specular = p["ks"] * p["IL"] * r_dot_v ** p["n"] if n_dot_l > 0 and r_dot_v > 0 else 0.0
    return p["ka"] * p["Ia"] + p["kd"] * p["IL"] * max(0.0, n_dot_l) + specular


def test_phong_intensity_is_the_illumination_equation():
    for ex in _all("phong-intensity"):
        p = ex.params
        assert ex.answer["I"] == pytest.approx(_phong(p, p["n_dot_l"], p["r_dot_v"]))
        assert ex.answer["I"] <= 1.0


def test_diffuse_and_specular_are_lamberts_and_phongs_laws():
    for ex in _all("diffuse"):
        p = ex.params
        expected = p["kd"] * p["IL"] * max(0.0, math.cos(math.radians(p["theta"])))
        assert ex.answer["Id"] == pytest.approx(expected, abs=1e-12)
    for ex in _all("specular"):
        p = ex.params
        cosine = max(0.0, math.cos(math.radians(p["alpha"])))
        assert ex.answer["Is"] == pytest.approx(p["ks"] * p["IL"] * cosine ** p["n"], abs=1e-12)


def test_phong_shading_interpolates_the_normal_then_lights_the_pixel():
    for ex in _all("phong-shading"):
        p = ex.params
        na, nb = (np.array(p[k], float) / np.linalg.norm(p[k]) for k in ("na", "nb"))
        t = (p["x"] - p["xa"]) / (p["xb"] - p["xa"])
        n = (1 - t) * na + t * nb
        n /= np.linalg.norm(n)
        light, eye = (np.array(p[k], float) / np.linalg.norm(p[k]) for k in ("l", "v"))
        n_dot_l = n @ light
        r_dot_v = (2 * n_dot_l * n - light) @ eye
        assert ex.answer["N"] == pytest.approx(n.tolist())
        assert ex.answer["I"] == pytest.approx(_phong(p, n_dot_l, r_dot_v))


def test_gouraud_on_a_triangle_is_barycentric_interpolation():
    for ex in _all("gouraud"):
        p = ex.params
        (ax, ay), (bx, by), (cx, cy) = p["vertices"]
        x, y = p["x"], p["scan_line"]
        area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        wb = ((x - ax) * (cy - ay) - (cx - ax) * (y - ay)) / area
        wc = ((bx - ax) * (y - ay) - (x - ax) * (by - ay)) / area
        assert min(1 - wb - wc, wb, wc) >= -1e-12  # the pixel is on the triangle
        expected = np.dot([1 - wb - wc, wb, wc], p["intensities"])
        assert ex.answer["I"] == pytest.approx(expected, abs=1e-12)
        assert ex.answer["x_left"] <= x <= ex.answer["x_right"]


def test_ray_sphere_is_the_smallest_positive_root():
    for ex in _all("ray-sphere"):
        p = ex.params
        o, d, c = (np.array(p[k], float) for k in ("origin", "direction", "center"))
        a, b = d @ d, 2 * d @ (o - c)
        cc = (o - c) @ (o - c) - p["radius"] ** 2
        disc = b * b - 4 * a * cc
        roots = [] if disc < 0 else [(-b - math.sqrt(disc)) / (2 * a),
                                     (-b + math.sqrt(disc)) / (2 * a)]
        ahead = [r for r in roots if r > 1e-9]
        expected = min(ahead) if ahead else None
        if expected is None:
            assert ex.answer["t"] is None
        else:
            assert ex.answer["t"] == pytest.approx(expected)
            assert np.linalg.norm(o + expected * d - c) == pytest.approx(p["radius"])
        assert ex.answer["discriminant"] == pytest.approx(disc)


def test_ray_plane_hits_the_plane():
    for ex in _all("ray-plane"):
        p = ex.params
        o, d, q, n = (np.array(p[k], float) for k in ("origin", "direction", "point", "normal"))
        t = ex.answer["t"]
        if t is None:
            assert n @ d == 0 or (n @ (q - o)) / (n @ d) <= 0
        else:
            assert t > 0 and n @ (o + t * d - q) == pytest.approx(0, abs=1e-9)


def test_refraction_obeys_snells_law():
    for ex in _all("refraction"):
        p = ex.params
        sine = p["n1"] / p["n2"] * math.sin(math.radians(p["theta_i"]))
        if sine > 1:
            assert ex.answer["T"] is None and ex.answer["theta_t"] is None
            continue
        assert ex.answer["theta_t"] == pytest.approx(math.degrees(math.asin(sine)), abs=2e-3)
        t = np.array(ex.answer["T"])
        assert np.linalg.norm(t) == pytest.approx(1)
        assert t[1] < 0 and t[0] == pytest.approx(sine, abs=1e-4)  # sin θt along the surface


def _window(p):
    return shapely.box(*p["window"])


def test_sutherland_hodgman_leaves_the_area_shapely_finds():
    for ex in _all("sutherland-hodgman"):
        subject = shapely.Polygon(ex.params["polygon"])
        expected = subject.intersection(_window(ex.params)).area
        result = ex.answer["polygon"]
        got = shapely.Polygon(result).area if len(result) >= 3 else 0.0
        assert got == pytest.approx(expected, abs=1e-9)
        assert ex.answer["after_top"] == result


def test_weiler_atherton_pieces_are_shapelys_intersection():
    for ex in _all("weiler-atherton"):
        cut = shapely.Polygon(ex.params["polygon"]).intersection(_window(ex.params))
        parts = [g for g in getattr(cut, "geoms", [cut]) if g.area > 0]
        pieces = [shapely.Polygon(piece) for piece in ex.answer["pieces"]]
        assert ex.answer["count"] == len(pieces) == len(parts)
        assert sum(piece.area for piece in pieces) == pytest.approx(cut.area, abs=1e-9)
        assert shapely.union_all(pieces).symmetric_difference(cut).area == pytest.approx(
            0, abs=1e-9)
