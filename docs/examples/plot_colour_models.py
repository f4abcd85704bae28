"""
Colour models
=============

The notes' colour models over whole arrays: an HSV and an HSL sweep of hues converted to RGB,
and a picture taken apart into its YIQ and CMYK components. Every conversion goes through RGB
and keeps the array's shape; hue is in degrees.
"""

import matplotlib.pyplot as plt
import numpy as np

from pixelpath import color

# %%
# One colour at a time, as in the notes' examples (8-bit input is scaled by 1/255):

print(color.rgb_to_hsv([255, 255, 0]))   # yellow: H = 60°, S = 1, V = 1
print(color.rgb_to_cmyk([0, 0, 0]))      # pure black is (0, 0, 0, 1)
print(color.convert([60, 1, 0.5], "hsl", "yiq"))

# %%
# Whole images: hue across, saturation down. HSV's single hexcone at V = 1 and HSL's double
# hexcone at L = 0.5 give the same pure hues along the top and differ below it.

hue, saturation = np.meshgrid(np.linspace(0, 360, 240, endpoint=False), np.linspace(1, 0, 80))
ones = np.ones_like(hue)
hsv_sweep = color.hsv_to_rgb(np.stack([hue, saturation, ones], axis=-1))
hsl_sweep = color.hsl_to_rgb(np.stack([hue, saturation, 0.5 * ones], axis=-1))

fig, axes = plt.subplots(2, 1, figsize=(6, 4.2))
titles = ("HSV, V = 1", "HSL, L = 0.5")
for ax, picture, title in zip(axes, (hsv_sweep, hsl_sweep), titles, strict=True):
    ax.imshow(picture, interpolation="nearest")
    ax.set_title(title)
    ax.set_axis_off()
fig.tight_layout()

# %%
# The same sweep taken apart: YIQ's luminance Y and chrominance I and Q (the NTSC matrix of
# the notes), and the four inks of CMYK (K = min(C, M, Y)).

yiq = color.rgb_to_yiq(hsv_sweep)
cmyk = color.rgb_to_cmyk(hsv_sweep)
channels = [(yiq[..., 0], "Y"), (yiq[..., 1], "I"), (yiq[..., 2], "Q"),
            (cmyk[..., 0], "C"), (cmyk[..., 1], "M"), (cmyk[..., 2], "Y (ink)"),
            (cmyk[..., 3], "K")]
fig, axes = plt.subplots(len(channels), 1, figsize=(6, 7))
for ax, (values, name) in zip(axes, channels, strict=True):
    ax.imshow(values, cmap="gray", interpolation="nearest")
    ax.set_title(name, fontsize=9)
    ax.set_axis_off()
fig.tight_layout()

# %%
# Round trips are exact to float precision: YIQ back to RGB uses the forward matrix's exact
# inverse (the notes print it rounded to three decimals).

print(np.abs(color.yiq_to_rgb(yiq) - hsv_sweep).max())
