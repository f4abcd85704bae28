"""Drawing helpers for the teaching figures: a world-to-pixel view, colours, text, files.

:class:`Board` lays out the frames of the hidden-surface and ray figures: a title, panels of a
rendered image's size (scaled up by whole factors) and a column of numbers.

Everything is drawn with Pillow in a small fixed palette, so that a figure's pixels can be
checked by colour (a test finds the emitted points by their highlight colour) and a GIF's
frames quantize to exactly the colours that were drawn.
"""

from __future__ import annotations

import io
import itertools
import os
from collections.abc import Sequence
from functools import cache
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from pixelpath.io.images import write_bytes

# The palette of every figure (RGB). Tests look pixels up by these names.
COLOURS = {
    "background": (255, 255, 255),
    "text": (25, 25, 30),
    "muted": (130, 130, 140),
    "faint": (228, 228, 232),
    "subject": (40, 100, 200),
    "subject fill": (208, 222, 245),
    "window": (30, 30, 30),
    "boundary": (235, 140, 0),
    "inside": (255, 243, 214),
    "output": (0, 140, 80),
    "output fill": (196, 234, 208),
    "edge": (130, 60, 190),
    "emitted": (225, 25, 35),
    "row": (255, 233, 170),
    "contact": (200, 0, 160),
    # How Warnock decided an area (pixelpath.hsr.warnock.DECISIONS).
    "empty area": (232, 236, 244),
    "single area": (150, 210, 160),
    "in front area": (140, 175, 235),
    "pixel area": (235, 110, 110),
    "area edge": (70, 70, 80),
    # Objects of the hidden-surface figures, in turn.
    "object 1": (95, 140, 215),
    "object 2": (230, 160, 60),
    "object 3": (110, 185, 120),
    "object 4": (200, 100, 160),
    "object 5": (150, 120, 210),
    "object 6": (90, 180, 190),
    # The rays of a ray tree (pixelpath.figures.ray_tree).
    "primary ray": (20, 90, 230),
    "shadow ray": (240, 170, 0),
    "reflected ray": (0, 170, 90),
    "refracted ray": (170, 40, 200),
    "blocked ray": (120, 120, 120),
}

TEXT_SIZE = 13
LINE_HEIGHT = 17
# The layout of a Board: margins, the gap between panels, the height of the title and captions
# above them, the width of the column of numbers right of them, and the size pictures are
# scaled up towards.
MARGIN, GAP, HEADER = 10, 16, 64
COLUMN = 250
PANEL = 320


@cache
def font(size: int = TEXT_SIZE) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    """Pillow's bundled font at ``size`` pixels."""
    return ImageFont.load_default(size=size)


class View:
    """Maps world coordinates (y up) into a pixel rectangle, keeping the aspect ratio.

    Parameters
    ----------
    points : (N, 2) array_like
        Everything the view must show; padded by ``pad`` of its extent on each side.
    box : (left, top, width, height)
        The pixel rectangle to draw in.
    """

    def __init__(self, points: np.ndarray, box: tuple[int, int, int, int], pad: float = 0.08):
        points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        lo, hi = points.min(axis=0), points.max(axis=0)
        span = np.maximum(hi - lo, 1e-9)
        lo, hi = lo - pad * span.max(), hi + pad * span.max()
        left, top, width, height = box
        self.scale = min(width / (hi[0] - lo[0]), height / (hi[1] - lo[1]))
        # Centre the world box in the pixel box.
        self.origin = np.array(
            [
                left + (width - self.scale * (hi[0] - lo[0])) / 2 - self.scale * lo[0],
                top + (height + self.scale * (hi[1] - lo[1])) / 2 + self.scale * lo[1],
            ]
        )
        self.box = box
        self.world_corners = np.array([lo, (hi[0], lo[1]), hi, (lo[0], hi[1])])

    def pixel(self, points: np.ndarray) -> np.ndarray:
        """Pixel coordinates (x right, y down) of world points ``(..., 2)``."""
        points = np.asarray(points, dtype=np.float64)
        return np.stack(
            [
                self.origin[0] + self.scale * points[..., 0],
                self.origin[1] - self.scale * points[..., 1],
            ],
            axis=-1,
        )

    def xy(self, points: np.ndarray) -> list[tuple[float, float]]:
        """Pixel coordinates as a list of tuples, as ImageDraw takes them."""
        return [tuple(p) for p in self.pixel(np.asarray(points).reshape(-1, 2)).tolist()]


class Sketch:
    """An RGB picture with drawing shortcuts in world coordinates through a :class:`View`."""

    def __init__(self, width: int, height: int):
        self.image = Image.new("RGB", (width, height), COLOURS["background"])
        self.draw = ImageDraw.Draw(self.image)
        # Text without antialiasing: its pixels keep the palette's exact colours, so GIF
        # frames stay exact and compress to a fraction of the size of shaded text.
        self.draw.fontmode = "1"

    def fill(self, view: View, points: np.ndarray, colour: str) -> None:
        """Fill a polygon (nothing for fewer than 3 vertices)."""
        if len(points) >= 3:
            self.draw.polygon(view.xy(points), fill=COLOURS[colour])

    def outline(self, view: View, points: np.ndarray, colour: str, width: int = 2,
                dashed: bool = False) -> None:
        """Draw a closed polygon's edges."""
        if len(points) == 0:
            return
        closed = np.vstack([points, points[:1]])
        for a, b in itertools.pairwise(closed):
            self.segment(view, a, b, colour, width, dashed)

    def segment(self, view: View, a: np.ndarray, b: np.ndarray, colour: str, width: int = 2,
                dashed: bool = False) -> None:
        """Draw a segment, solid or dashed (8-pixel dashes)."""
        (x0, y0), (x1, y1) = view.xy(np.array([a, b]))
        if not dashed:
            self.draw.line([(x0, y0), (x1, y1)], fill=COLOURS[colour], width=width)
            return
        length = max(np.hypot(x1 - x0, y1 - y0), 1e-9)
        for start in np.arange(0.0, length, 12.0):
            ends = [start / length, min(start + 7.0, length) / length]
            dash = [(x0 + t * (x1 - x0), y0 + t * (y1 - y0)) for t in ends]
            self.draw.line(dash, fill=COLOURS[colour], width=width)

    def dots(self, view: View, points: np.ndarray, colour: str, radius: float = 4) -> None:
        """Draw filled discs at points."""
        for x, y in view.xy(points):
            box = [x - radius, y - radius, x + radius, y + radius]
            self.draw.ellipse(box, fill=COLOURS[colour])

    def rings(self, view: View, points: np.ndarray, colour: str, radius: float = 7) -> None:
        """Draw circles around points."""
        for x, y in view.xy(points):
            self.draw.ellipse(
                [x - radius, y - radius, x + radius, y + radius], outline=COLOURS[colour], width=2
            )

    def label(self, view: View, point: np.ndarray, text: str, colour: str = "text") -> None:
        """Write ``text`` just above and right of a world point."""
        ((x, y),) = view.xy(point)
        self.draw.text((x + 6, y - LINE_HEIGHT), text, fill=COLOURS[colour], font=font())

    def text(self, x: float, y: float, text: str, colour: str = "text", size: int = TEXT_SIZE,
             background: str | None = None) -> None:
        """Write a line of text with its top-left corner at (x, y)."""
        if background is not None:
            width = self.draw.textlength(text, font=font(size))
            self.draw.rectangle([x - 3, y - 1, x + width + 3, y + size + 3],
                                fill=COLOURS[background])
        self.draw.text((x, y), text, fill=COLOURS[colour], font=font(size))

    def columns(self, x: float, y: float, rows: Sequence[Sequence[str]], gap: int = 14,
                highlight: int | None = None, colour: str = "text") -> float:
        """Write rows of cells in aligned columns; return the y below the last row."""
        widths = [0.0] * max((len(row) for row in rows), default=0)
        for row in rows:
            for k, cell in enumerate(row):
                widths[k] = max(widths[k], self.draw.textlength(cell, font=font()))
        for index, row in enumerate(rows):
            if index == highlight:
                right = x + sum(widths) + gap * (len(widths) - 1)
                self.draw.rectangle([x - 3, y - 1, right + 3, y + LINE_HEIGHT - 1],
                                    fill=COLOURS["row"])
            left = x
            for k, cell in enumerate(row):
                self.draw.text((left, y), cell, fill=COLOURS[colour], font=font())
                left += widths[k] + gap
            y += LINE_HEIGHT
        return y


def picture_scale(width: int, height: int) -> int:
    """Return the whole factor a ``width`` × ``height`` image is scaled up by in the figures.

    Examples
    --------
    >>> from pixelpath.figures._canvas import picture_scale
    >>> picture_scale(160, 120), picture_scale(16, 16), picture_scale(640, 480)
    (2, 20, 1)
    """
    return max(1, PANEL // max(width, height))


class PixelPanel:
    """Maps pixel coordinates of the rendered image (x right, y down) into one panel."""

    def __init__(self, left: int, top: int, scale: int, width: int, height: int):
        self.left, self.top, self.scale = left, top, scale
        self.width, self.height = width, height

    def xy(self, points: np.ndarray) -> list[tuple[float, float]]:
        """Board coordinates of image points, as ImageDraw takes them."""
        points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        return [(self.left + self.scale * x, self.top + self.scale * y) for x, y in points]

    def box(self, first_row: int, stop_row: int, first_col: int, stop_col: int) -> list[int]:
        """Return the board rectangle [x0, y0, x1, y1] (inclusive) of a block of pixels."""
        s = self.scale
        return [self.left + s * first_col, self.top + s * first_row,
                self.left + s * stop_col - 1, self.top + s * stop_row - 1]


class Board:
    """A frame: a title and a line under it, captioned panels, a column of numbers.

    Panel ``k`` starts at ``(MARGIN + k * (width * scale + GAP), HEADER)`` for an image of
    ``width`` pixels scaled by ``scale = picture_scale(width, height)``.
    """

    def __init__(self, shape: tuple[int, int], captions: Sequence[str], title: str,
                 detail: str = ""):
        height, width = shape
        self.scale = picture_scale(width, height)
        pw, ph = width * self.scale, height * self.scale
        panels = len(captions)
        self.column_x = MARGIN + panels * (pw + GAP)
        self.sketch = Sketch(self.column_x + COLUMN, max(HEADER + ph, HEADER + 14 * LINE_HEIGHT)
                             + MARGIN)
        self.panels = [
            PixelPanel(MARGIN + k * (pw + GAP), HEADER, self.scale, width, height)
            for k in range(panels)
        ]
        self.sketch.text(MARGIN, 6, title)
        self.sketch.text(MARGIN, 6 + LINE_HEIGHT, detail, colour="muted")
        for panel, caption in zip(self.panels, captions, strict=True):
            self.sketch.text(panel.left, HEADER - LINE_HEIGHT - 2, caption)
        self.y = HEADER

    def paste(self, panel: int, rgb: np.ndarray) -> None:
        """Place an (H, W, 3) uint8 picture in a panel, each pixel a square block."""
        self.place(panel, scaled(rgb, self.scale))

    def place(self, panel: int, picture: Image.Image) -> None:
        """Place a picture of the panel's size (from :meth:`canvas`) in a panel."""
        target = self.panels[panel]
        self.sketch.image.paste(picture, (target.left, target.top))

    def canvas(self, rgb: np.ndarray | None = None) -> tuple[Sketch, PixelPanel]:
        """Return a sketch of one panel's size (white, or ``rgb`` scaled up) and its mapping.

        Drawing there and placing it keeps what reaches past the panel out of the others.
        """
        height, width = self.panels[0].height, self.panels[0].width
        sketch = Sketch(width * self.scale, height * self.scale)
        if rgb is not None:
            sketch.image.paste(scaled(rgb, self.scale), (0, 0))
        return sketch, PixelPanel(0, 0, self.scale, width, height)

    def line(self, text: str, colour: str = "text", swatch: str | None = None) -> None:
        """Write a line in the column of numbers, with a colour swatch before it if asked."""
        x = self.column_x
        if swatch is not None:
            self.sketch.draw.rectangle([x, self.y + 2, x + 11, self.y + 13],
                                       fill=COLOURS[swatch], outline=COLOURS["area edge"])
            x += 18
        self.sketch.text(x, self.y, text, colour=colour)
        self.y += LINE_HEIGHT

    def skip(self) -> None:
        """Leave half a line of space in the column of numbers."""
        self.y += LINE_HEIGHT // 2

    @property
    def image(self) -> Image.Image:
        """The frame drawn so far."""
        return self.sketch.image


def scaled(rgb: np.ndarray, scale: int) -> Image.Image:
    """Return an (H, W, 3) uint8 picture scaled up by a whole factor, nearest neighbour."""
    picture = Image.fromarray(np.ascontiguousarray(rgb, dtype=np.uint8), "RGB")
    if scale > 1:
        picture = picture.resize((picture.width * scale, picture.height * scale),
                                 Image.Resampling.NEAREST)
    return picture


def paste_row(images: Sequence[Image.Image], captions: Sequence[str], gap: int = 8,
              caption_height: int = 22) -> Image.Image:
    """Place pictures side by side on white, each with a caption above it."""
    measure = ImageDraw.Draw(Image.new("RGB", (1, 1)))
    widths = [
        max(image.width, int(np.ceil(measure.textlength(caption, font=font()))))
        for image, caption in zip(images, captions, strict=True)
    ]
    width = sum(widths) + gap * (len(images) + 1)
    height = max(image.height for image in images) + caption_height + 2 * gap
    sketch = Sketch(width, height)
    left = gap
    for image, caption, column in zip(images, captions, widths, strict=True):
        sketch.text(left, gap, caption)
        sketch.image.paste(image, (left, gap + caption_height))
        left += column + gap
    return sketch.image


def paste_grid(images: Sequence[Image.Image], captions: Sequence[str],
               columns: int) -> Image.Image:
    """Place captioned pictures in rows of ``columns`` (:func:`paste_row`), row under row."""
    rows = [
        paste_row(images[start : start + columns], captions[start : start + columns])
        for start in range(0, len(images), columns)
    ]
    grid = Image.new("RGB", (max(row.width for row in rows), sum(row.height for row in rows)),
                     "white")
    top = 0
    for row in rows:
        grid.paste(row, (0, top))
        top += row.height
    return grid


def _palette_image(picture: Image.Image | None = None) -> Image.Image:
    """Return a 'P' image whose palette is the figure colours, their half-tones and greys.

    With a ``picture``, the free entries are filled with its own colours (median cut).
    """
    entries = list(COLOURS.values())
    entries += [(v, v, v) for v in range(0, 256, 5)]
    # Half-tones of each colour on white: antialiased text and thin lines land near them.
    entries += [tuple((c + 255) // 2 for c in colour) for colour in COLOURS.values()]
    if picture is not None:
        adaptive = picture.convert("RGB").quantize(256 - len(entries), dither=Image.Dither.NONE)
        colours = adaptive.getpalette()[: 3 * len(adaptive.getcolors())]
        entries += [tuple(colours[k : k + 3]) for k in range(0, len(colours), 3)]
    flat = [c for entry in entries for c in entry]
    palette = Image.new("P", (1, 1))
    palette.putpalette(flat + [0] * (768 - len(flat)))
    return palette


def gif_bytes(frames: Sequence[Image.Image], durations: Sequence[int],
              pictures: bool = False) -> bytes:
    """Encode RGB frames as a looping GIF in the figure palette (no dithering).

    With ``pictures`` (frames that hold rendered images), the palette's free entries take the
    last frame's most representative other colours; the figure colours stay exact.
    """
    palette = _palette_image(frames[-1] if pictures else None)
    quantized = [frame.quantize(palette=palette, dither=Image.Dither.NONE) for frame in frames]
    buffer = io.BytesIO()
    quantized[0].save(
        buffer,
        format="GIF",
        save_all=True,
        append_images=quantized[1:],
        duration=list(durations),
        loop=0,
        disposal=1,
        optimize=True,
    )
    return buffer.getvalue()


def png_bytes(image: Image.Image) -> bytes:
    """Encode a picture as PNG."""
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", optimize=True)
    return buffer.getvalue()


def save(image: Image.Image, path: str | os.PathLike) -> Path:
    """Write a picture atomically; the format follows the extension (.png, .gif, ...)."""
    path = Path(path)
    fmt = Image.registered_extensions().get(path.suffix.lower())
    if fmt is None:
        raise ValueError(f"unknown image extension {path.suffix!r} for {path}; use .png or .gif")
    if fmt == "GIF":
        return _write(path, gif_bytes([image], [1000]))
    buffer = io.BytesIO()
    image.save(buffer, format=fmt)
    return _write(path, buffer.getvalue())


def save_animation(frames: Sequence[Image.Image], durations: Sequence[int],
                   path: str | os.PathLike, pictures: bool = False) -> Path:
    """Write frames as an animated GIF, atomically (``pictures``: see :func:`gif_bytes`)."""
    path = Path(path)
    if path.suffix.lower() != ".gif":
        raise ValueError(f"animations are written as GIF; give a .gif path, got {str(path)!r}")
    return _write(path, gif_bytes(frames, durations, pictures))


def _write(path: Path, data: bytes) -> Path:
    """Write a figure's bytes atomically, saying plainly when the folder is missing."""
    if not path.parent.is_dir():
        raise FileNotFoundError(f"output directory does not exist: {path.parent}")
    write_bytes(path, data)
    return path
