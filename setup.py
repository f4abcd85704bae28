"""Build hook: compile pixelpath's render kernels into the package it builds.

Everything else about the package is in ``pyproject.toml``. See ``src/pixelpath/_precompiled.py``
for what is compiled, where it goes and how a first run uses it.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
# Kept between builds (beside setuptools' own build/lib), so that installing the same sources
# again, as the README's second command does, copies the kernels instead of compiling them.
KERNEL_CACHE = ROOT / "build" / "kernel-cache"
# Far above the minute or two it takes on two cores; past it the build goes on without them.
TIMEOUT_S = 1800


class BuildWithKernels(build_py):
    """Build the package, then compile its render kernels into it (not for editable installs)."""

    def run(self) -> None:
        """Run setuptools' build_py, then the kernels' compile into the built package."""
        super().run()
        if self.editable_mode:
            return
        build_lib = Path(self.build_lib).resolve()
        destination = build_lib / "pixelpath" / "_precompiled"
        paths = [str(build_lib), *filter(None, [os.environ.get("PYTHONPATH")])]
        env = {**os.environ, "PYTHONPATH": os.pathsep.join(paths),
               "PIXELPATH_CACHE_DIR": str(KERNEL_CACHE)}
        command = [sys.executable, "-m", "pixelpath._precompiled", str(destination)]
        try:
            subprocess.run(command, env=env, check=True, timeout=TIMEOUT_S)
        except (OSError, subprocess.SubprocessError) as exc:
            shutil.rmtree(destination, ignore_errors=True)
            sys.stderr.write(
                f"warning: pixelpath's kernels were not compiled ahead ({exc}); "
                "they will compile on first use\n"
            )

setup(cmdclass={"build_py": BuildWithKernels})
