"""Scenes: camera, materials, lights, analytic primitives, polygon meshes and TOML scene files.

Conventions: right-handed world, the camera looks down -Z in camera space, faces are wound
counter-clockwise seen from outside. Vectors are stored as read-only float64 arrays and every
constructor validates its input (``ValueError`` for bad values or shapes, ``TypeError`` for
wrong types), so later stages can trust a scene.

Examples
--------
>>> from pixelpath.scene import Box, Camera, Scene
>>> scene = Scene(Camera(eye=(3, 3, 3), target=(0, 0, 0)), objects=[Box((0, 0, 0), (1, 1, 1))])
>>> len(scene.objects)
1
"""

from pixelpath.scene.animation import Animation, CameraKey, ObjectKey, Turntable
from pixelpath.scene.bundled import bundled_scene, bundled_scenes
from pixelpath.scene.camera import Camera
from pixelpath.scene.lights import DirectionalLight, PointLight
from pixelpath.scene.loader import load_scene, scene_from_dict, scene_to_dict
from pixelpath.scene.material import Material
from pixelpath.scene.mesh import Mesh
from pixelpath.scene.primitives import Box, Plane, Sphere
from pixelpath.scene.procedural import icosphere, torus
from pixelpath.scene.scene import Scene
from pixelpath.scene.texture import Texture
from pixelpath.scene.transform import transform_matrix

# The model (scene.py) knows nothing of its file format; the dict form is attached here, where
# both are known, so that ``Scene.from_dict(data)`` and ``scene.to_dict()`` read naturally.
Scene.to_dict = scene_to_dict
Scene.from_dict = staticmethod(scene_from_dict)

__all__ = [
    "Animation",
    "Box",
    "Camera",
    "CameraKey",
    "DirectionalLight",
    "Material",
    "Mesh",
    "ObjectKey",
    "Plane",
    "PointLight",
    "Scene",
    "Sphere",
    "Texture",
    "Turntable",
    "bundled_scene",
    "bundled_scenes",
    "icosphere",
    "load_scene",
    "scene_from_dict",
    "scene_to_dict",
    "torus",
    "transform_matrix",
]
