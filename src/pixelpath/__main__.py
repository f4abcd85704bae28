"""``python -m pixelpath``: the same command line as ``pixelpath``."""

from pixelpath.cli import run

run()
