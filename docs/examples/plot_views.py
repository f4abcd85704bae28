"""
A dataset of views
==================

Views of a model round an orbit, each with its camera pose, depth and mask, in the
``transforms.json`` layout that NeRF, nerfstudio and instant-ngp read. Small and few here;
``pixelpath views`` makes hundreds, on Dask.
"""

import json
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

import pixelpath as pp

folder = Path(tempfile.mkdtemp()) / "duck_views"
poses = pp.render_views("../../tests/data/models/Duck.glb", 6, folder,   # run from docs/examples
                        aovs=("depth", "normal", "mask"), size=(96, 96))
print(poses.shape)   # camera-to-world matrices, as in the JSON

# %%
# The folder: pictures, depth as float32 ``.npy``, normals and masks, and the poses.

meta = json.loads((folder / "transforms.json").read_text())
print(sorted(meta)[:8], len(meta["frames"]))
row = [np.asarray(Image.open(folder / frame["file_path"]).convert("RGB"))
       for frame in meta["frames"]]
frame = meta["frames"][3]
normals = np.asarray(Image.open(folder / frame["normal_file_path"]).convert("RGB"))
mask = np.asarray(Image.open(folder / frame["mask_path"]).convert("RGB"))
Image.fromarray(np.hstack([*row, normals, mask])).save("views.png")

# %%
# A pixel's ray, scaled by the depth there, lands on the surface (0 means no surface):

depth = np.load(folder / frame["depth_file_path"])
c2w = np.array(frame["transform_matrix"])
y, x = np.argwhere(depth > 0)[0]
ray = np.array([(x + 0.5 - meta["cx"]) / meta["fl_x"], -(y + 0.5 - meta["cy"]) / meta["fl_y"], -1])
print(c2w[:3, 3] + depth[y, x] * (c2w[:3, :3] @ ray))
