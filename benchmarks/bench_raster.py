"""Raster speed: pixelpath's z-buffer with per-pixel Phong shading beside Mesa's llvmpipe.

Renders the Stanford bunny (69,451 triangles, from ../shared/data/meshes; an icosphere of
81,920 triangles when the file is absent) at 1024×1024 and the Utah teapot (6,320 triangles;
a torus when absent), each lit by one point light with per-pixel Phong shading, and prints
milliseconds per frame after warm-up (median and best of several frames).

The anchor is OpenGL on the CPU: moderngl with a headless EGL context on Mesa's llvmpipe,
drawing the same triangles with the same camera matrices and the same Phong formula in a
fragment shader, in the same run. It is optional: without moderngl or an EGL driver the
script says so and prints pixelpath's figures alone. llvmpipe's thread count follows
``LP_NUM_THREADS`` (default: one per core); pixelpath's follows ``NUMBA_NUM_THREADS``.

Usage::

    python benchmarks/bench_raster.py [--frames 15] [--size 1024]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path

import numpy as np

import pixelpath as pp

MESHES = Path(__file__).resolve().parents[2] / "shared" / "data" / "meshes"

# With TEXTURED defined, the shaders also carry texture coordinates and multiply the colour
# by the (sRGB-decoded, trilinearly filtered) texture, as pixelpath's textured Phong does.
VERTEX_SHADER = """
#version 330
uniform mat4 mvp;
in vec3 in_position;
in vec3 in_normal;
out vec3 position;
out vec3 normal;
#ifdef TEXTURED
in vec2 in_uv;
out vec2 uv;
#endif
void main() {
    position = in_position;
    normal = in_normal;
#ifdef TEXTURED
    uv = in_uv;
#endif
    gl_Position = mvp * vec4(in_position, 1.0);
}
"""

FRAGMENT_SHADER = """
#version 330
uniform vec3 eye;
uniform vec3 light;
uniform vec3 color;
uniform vec4 coefficients;  // ka, kd, ks, shininess
uniform float ambient;
in vec3 position;
in vec3 normal;
out vec4 frag;
#ifdef TEXTURED
uniform sampler2D picture;
in vec2 uv;
#endif
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(light - position);
    vec3 v = normalize(eye - position);
    float n_dot_l = dot(n, l);
    vec3 albedo = color;
#ifdef TEXTURED
    albedo *= texture(picture, uv).rgb;
#endif
    vec3 intensity = coefficients.x * ambient * albedo;
    if (n_dot_l > 0.0) {
        intensity += coefficients.y * albedo * n_dot_l;
        float r_dot_v = dot(2.0 * n_dot_l * n - l, v);
        if (r_dot_v > 0.0) intensity += vec3(coefficients.z * pow(r_dot_v, coefficients.w));
    }
    frag = vec4(clamp(intensity, 0.0, 1.0), 1.0);
}
"""


def _shader(source: str, textured: bool) -> str:
    """The shader source, with TEXTURED defined after its version line when asked."""
    if not textured:
        return source
    version, rest = source.strip().split("\n", 1)
    return f"{version}\n#define TEXTURED\n{rest}"


def load_model(name: str) -> tuple[str, pp.Mesh]:
    """A label and the shared mesh ``name``, or a procedural stand-in of similar size."""
    from pixelpath.scene import icosphere, torus

    path = MESHES / name
    if path.is_file():
        return name, pp.Mesh.load(path)
    print(f"\n({path} not found: using a procedural stand-in)")
    if name.startswith("stanford-bunny"):
        return "icosphere (bunny stand-in)", icosphere(subdivisions=6)
    return "torus (teapot stand-in)", torus(major_segments=80, minor_segments=40)


def framed_scene(mesh: pp.Mesh, size: int) -> pp.Scene:
    """The mesh seen from the front and a little above, filling most of the frame."""
    low, high = mesh.bounds()
    center = (low + high) / 2
    radius = float(np.linalg.norm(high - low)) / 2
    camera = pp.Camera(
        eye=center + radius * np.array([0.0, 0.3, 2.6]),
        target=center,
        fov=45.0,
        width=size,
        height=size,
        near=0.05 * radius,
        far=10.0 * radius,
    )
    light = pp.PointLight(center + radius * np.array([2.0, 2.0, 2.0]))
    return pp.Scene(camera, objects=[mesh], lights=[light], ambient=0.1)


def time_frames(draw, frames: int) -> tuple[float, float]:
    """Median and best milliseconds per call of ``draw`` (after one warm-up call)."""
    draw()
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        draw()
        times.append(1000.0 * (time.perf_counter() - start))
    return statistics.median(times), min(times)


class Llvmpipe:
    """The same scene drawn by OpenGL on Mesa's llvmpipe through moderngl (EGL, no display).

    A mesh with texture coordinates and a textured material is drawn textured: an sRGB
    texture with mip maps, sampled trilinearly, its repeat wrap, multiplying the colour.
    """

    def __init__(self, scene: pp.Scene) -> None:
        import moderngl

        self.ctx = moderngl.create_standalone_context(backend="egl")
        self.renderer = self.ctx.info["GL_RENDERER"]
        camera = scene.camera
        mesh = scene.objects[0]
        material = mesh.material
        textured = mesh.uv is not None and material.texture is not None
        program = self.ctx.program(vertex_shader=_shader(VERTEX_SHADER, textured),
                                   fragment_shader=_shader(FRAGMENT_SHADER, textured))
        mvp = camera.projection_matrix() @ camera.view_matrix()
        program["mvp"].write(mvp.T.astype("f4").tobytes())  # GLSL matrices are column-major
        program["eye"].value = tuple(camera.eye)
        program["light"].value = tuple(scene.lights[0].position)
        program["color"].value = tuple(material.color)
        program["coefficients"].value = (material.ka, material.kd, material.ks, material.shininess)
        program["ambient"].value = float(scene.ambient[0])
        corners = mesh.triangles.reshape(-1)
        columns = [mesh.vertices[corners], mesh.vertex_normals[corners]]
        layout, names = "3f 3f", ["in_position", "in_normal"]
        if textured:
            columns.append(mesh.uv[corners])
            layout, names = "3f 3f 2f", [*names, "in_uv"]
            base = material.texture.levels[0]  # RGBA, sRGB colour, row 0 at the top
            self.texture = self.ctx.texture(
                (base.shape[1], base.shape[0]), 4, np.ascontiguousarray(base[::-1]).tobytes(),
                internal_format=0x8C43,  # GL_SRGB8_ALPHA8: decoded to linear when sampled
            )
            self.texture.build_mipmaps()
            self.texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
            self.texture.use(0)
            program["picture"].value = 0
        data = np.hstack(columns).astype("f4")
        self.vao = self.ctx.vertex_array(
            program, [(self.ctx.buffer(data.tobytes()), layout, *names)]
        )
        size = (camera.width, camera.height)
        self.fbo = self.ctx.framebuffer(
            color_attachments=[self.ctx.renderbuffer(size)],
            depth_attachment=self.ctx.depth_renderbuffer(size),
        )
        self.ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)

    def draw(self) -> None:
        """Draw one frame and wait for it."""
        self.fbo.use()
        self.fbo.clear(0.0, 0.0, 0.0, 1.0)
        self.vao.render()
        self.ctx.finish()

    def draw_and_read(self) -> np.ndarray:
        """Draw one frame and read it back as an (H, W, 3) float image, row 0 at the top."""
        self.draw()
        width, height = self.fbo.size
        pixels = np.frombuffer(self.fbo.read(components=3), dtype=np.uint8)
        return pixels.reshape(height, width, 3)[::-1] / 255.0


def open_llvmpipe(scene: pp.Scene) -> Llvmpipe | None:
    """The anchor, or None (with the reason printed) when it cannot run here."""
    try:
        return Llvmpipe(scene)
    except ImportError:
        print("  llvmpipe anchor skipped: moderngl is not installed (pip install moderngl)")
    except Exception as exc:  # no EGL driver, no llvmpipe: report and go on without the anchor
        print(f"  llvmpipe anchor skipped: no headless OpenGL context ({exc})")
    return None


def bench(name: str, size: int, frames: int) -> None:
    label, mesh = load_model(name)
    scene = framed_scene(mesh, size)
    print(f"\n{label}: {len(mesh.triangles):,} triangles at {size}x{size}, Phong per pixel")
    image = pp.render(scene, shading="phong")
    median, best = time_frames(lambda: pp.render(scene, shading="phong"), frames)
    print(f"  pixelpath zbuffer  {median:7.1f} ms/frame (best {best:.1f})")
    compare_with_llvmpipe(scene, np.asarray(image), median, frames)


def compare_with_llvmpipe(scene: pp.Scene, image: np.ndarray, median: float, frames: int,
                          encode=lambda rgb: rgb) -> None:
    """Time llvmpipe on ``scene`` and print its figures beside pixelpath's ``median`` ms.

    ``image`` is pixelpath's picture of the scene; both pictures pass through ``encode``
    (for example the sRGB curve) before they are compared.
    """
    anchor = open_llvmpipe(scene)
    if anchor is None:
        return
    gl_median, gl_best = time_frames(anchor.draw, frames)
    read_median, _ = time_frames(anchor.draw_and_read, frames)
    print(f"  llvmpipe (OpenGL)  {gl_median:7.1f} ms/frame (best {gl_best:.1f}); "
          f"{read_median:.1f} ms with read-back  [{anchor.renderer}]")
    print(f"  ratio pixelpath / llvmpipe: {median / gl_median:.2f} "
          f"({median / read_median:.2f} against draw + read-back)")
    difference = np.abs(encode(image) - encode(anchor.draw_and_read()))
    print(f"  images agree: mean |difference| {difference.mean():.4f}, "
          f"{(difference.max(axis=2) > 8 / 255).mean():.2%} of pixels differ by more than 8/255")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=15, help="timed frames per renderer")
    parser.add_argument("--size", type=int, default=1024, help="image side in pixels")
    args = parser.parse_args()

    import numba

    print(f"pixelpath {pp.__version__}: numba {numba.__version__}, "
          f"{numba.get_num_threads()} threads; {os.cpu_count()} CPUs; "
          f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'default')}")
    start = time.perf_counter()
    pp.warmup()
    print(f"warm-up (compile or load cached kernels): {time.perf_counter() - start:.1f} s")
    for name in ("stanford-bunny.obj", "teapot.obj"):
        bench(name, args.size, args.frames)


if __name__ == "__main__":
    main()
