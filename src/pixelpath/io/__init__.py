"""File input and output: images through Pillow, meshes through trimesh."""

from pixelpath.io.images import read_image, write_image

__all__ = ["read_image", "write_image"]
