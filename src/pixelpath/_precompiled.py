"""Kernels compiled when pixelpath is built, handed to the kernel cache on first use.

A render's kernels take Numba about 20 s of CPU to compile (its typing in Python, then LLVM),
which a first run would otherwise spend before its first picture. So building pixelpath (the
wheel that ``pip install .`` makes) compiles the groups of :data:`BUILT_GROUPS` and ships the
compiled code in the package's ``_precompiled`` folder, as Numba's own cache files, sorted by the
source folder they belong to, with a manifest saying what they were compiled for (Numba, NumPy and
Python versions, the CPU) and how long each group took.

On first use after installing, :func:`seed` copies those files into the kernel cache (each
source folder's files into the folder :class:`pixelpath._cache.KernelCacheLocator` gives it)
and writes the groups' markers, so that Numba loads the kernels instead of compiling them and
the CLI compiles nothing ahead. The cache's freshness stamp is a hash of the sources, not of
where they are, so files compiled in the build folder are valid where the package is installed.
Nothing is copied when the manifest does not match what is here (sources edited since the
build, another Numba, NumPy, Python or CPU): the kernels then compile on first use as they
would without this module; nor when ``PIXELPATH_PRECOMPILED=0`` (which also skips compiling
them at build time).

Run as ``python -m pixelpath._precompiled FOLDER`` (what ``setup.py`` does while building) it
compiles the groups and writes the files into FOLDER, unless ``PIXELPATH_PRECOMPILED=0``.

Of the kernel cache's three modules this one is on top: it calls :mod:`pixelpath._cache` (the
folder and the stamps) and :mod:`pixelpath._warm` (the groups and their markers), which call
neither each other nor this one. So the folder everything else uses, seeded, is
:func:`cache_root`: the kernels' own caches (:mod:`pixelpath._jit`) and the groups' markers
(:func:`markers`) come through it.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import pickle
import shutil
import sys
import tempfile
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

import numba
import numpy as np
from numba.core.registry import cpu_target

from pixelpath._cache import PACKAGE_DIR, kernel_cache_folder, source_stamp, writable_cache_dir
from pixelpath._warm import (
    METHOD_GROUPS,
    cold_groups,
    compile_groups,
    groups_for,
    marker_folder,
    recorded_seconds,
    sources_digest,
    write_markers,
)

__all__ = ["BUILT_GROUPS", "MANIFEST", "build", "cache_root", "enabled", "markers", "seed"]

# Every group a render calls, whatever its method, shading or drawing style, the searches of
# batches of rays (raytrace.intersect) and the 8-bit encoding of the saved picture (1.4 s to
# compile); the clipping and colour kernels (about a minute of compiling between them, over
# every dtype they accept) compile on first use.
BUILT_GROUPS = (*groups_for(METHOD_GROUPS), "raytrace-queries", "images")
MANIFEST = "manifest.json"
SHIPPED = Path(__file__).resolve().parent / "_precompiled"


def enabled(environ: Mapping[str, str] | None = None) -> bool:
    """Return whether precompiled kernels are built and used (``PIXELPATH_PRECOMPILED`` not 0).

    Examples
    --------
    >>> from pixelpath._precompiled import enabled
    >>> enabled({"PIXELPATH_PRECOMPILED": "0"}), enabled({})
    (False, True)
    """
    env = os.environ if environ is None else environ
    return env.get("PIXELPATH_PRECOMPILED", "1").strip() != "0"


def _compiled_for() -> dict[str, object]:
    """Return what compiled code depends on: the sources, Numba, NumPy, Python and the CPU.

    NumPy's version is there because Numba types some arithmetic after NumPy's promotion
    rules, which changed between NumPy 1 and 2, and its cache does not check it.
    """
    return {
        "sources": sources_digest(),
        "numba": numba.__version__,
        "numpy": np.__version__,
        "python": sys.version,
        "target": list(cpu_target.target_context.codegen().magic_tuple()),
    }


def _source_folders() -> list[Path]:
    return [PACKAGE_DIR, *(p for p in sorted(PACKAGE_DIR.rglob("*")) if p.is_dir())]


class _Opaque:
    """Any object an index pickles besides strings (Numba types, signatures), left unbuilt."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        pass

    def __setstate__(self, state: object) -> None:
        pass


class _StringsOnly(pickle.Unpickler):
    """Unpickle an index without importing anything it names.

    The keys of an index are signatures whose types name pixelpath's classes; seeding runs
    while the first kernel module is still being imported, before those classes exist. The
    version, the stamp and the data files' names are plain strings, and only they are read.
    """

    def find_class(self, module: str, name: str) -> type:
        return _Opaque


@dataclass(frozen=True)
class _Index:
    """What a Numba cache index (``.nbi``) says: Numba's version, the stamp, the data files."""

    version: object
    stamp: object
    data_files: frozenset[str]

    @property
    def freshness(self) -> tuple[object, object]:
        """(Numba version, source stamp): the index is current when both match."""
        return self.version, self.stamp

    @classmethod
    def read(cls, path: Path) -> _Index | None:
        """Read the index at ``path`` (two pickles, as Numba writes it); None if unreadable."""
        try:
            with path.open("rb") as index:
                version = _StringsOnly(index).load()
                stamp, overloads = _StringsOnly(index).load()
            return cls(version, stamp, frozenset(overloads.values()))
        except Exception:  # a damaged or foreign index is replaced like a stale one
            return None


def _current_indexes(folder: Path, sources: Path) -> dict[Path, _Index]:
    """Return the indexes in cache folder ``folder`` that are fresh for the files in ``sources``.

    An index is named after its kernel's file (``_kernels.shade_row-120.py311.nbi`` for a
    kernel of ``_kernels.py``); a kernel renamed or changed since it was cached leaves an index
    of older sources behind, which is not shipped.
    """
    fresh = {}
    for path in sorted(folder.glob("*.nbi")):
        source = sources / f"{path.name.split('.')[0]}.py"
        index = _Index.read(path)
        if (
            index is not None
            and source.is_file()
            and index.freshness == (numba.__version__, source_stamp(source))
        ):
            fresh[path] = index
    return fresh


def build(destination: Path, groups: Iterable[str] = BUILT_GROUPS) -> dict:
    """Compile ``groups`` into this process's kernel cache and copy the files to ``destination``.

    Groups already compiled there (their markers present) are not compiled again, so a second
    build with the same cache folder only copies. Only indexes fresh for the sources are copied,
    each with the data files it names. Returns the manifest written beside the files.
    """
    groups = tuple(groups)
    root = cache_root()
    if root is None or numba.config.DISABLE_JIT:
        raise RuntimeError("kernels cannot be compiled into a cache (JIT disabled or no folder)")
    markers = marker_folder(root)
    compile_groups(cold_groups(groups, markers), markers)
    shutil.rmtree(destination, ignore_errors=True)
    digest = hashlib.sha256()
    for sources in _source_folders():
        compiled = kernel_cache_folder(root, sources)
        if not compiled.is_dir():
            continue
        target = destination / sources.relative_to(PACKAGE_DIR)
        for path, index in _current_indexes(compiled, sources).items():
            target.mkdir(parents=True, exist_ok=True)
            for name in sorted(index.data_files | {path.name}):
                shutil.copyfile(compiled / name, target / name)
                digest.update(name.encode() + (target / name).read_bytes())
    manifest = {
        **_compiled_for(),
        "groups": {group: round(recorded_seconds(group, markers), 3) for group in groups},
        "id": digest.hexdigest()[:16],
    }
    (destination / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n")
    return manifest


def _copy_atomically(source: Path, target: Path) -> None:
    """Copy ``source`` to ``target`` so that no process ever reads a half-written file."""
    handle, temporary = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.")
    os.close(handle)
    try:
        shutil.copyfile(source, temporary)
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _seed_folder(shipped: Path, cache: Path) -> None:
    """Copy one source folder's shipped cache files into its cache folder.

    An index already there with the same Numba version and source stamp is the user's own
    current cache (possibly holding more specializations) and is kept with its data files;
    any other (stale, from an earlier version of the sources) is replaced. Data files go
    before their index, so that an index never names a file not yet there.
    """
    cache.mkdir(parents=True, exist_ok=True)
    for path in sorted(shipped.glob("*.nbi")):
        index = _Index.read(path)
        existing = _Index.read(cache / path.name)
        if index is None or (existing is not None and existing.freshness == index.freshness):
            continue
        for name in sorted(index.data_files):
            _copy_atomically(shipped / name, cache / name)
        _copy_atomically(path, cache / path.name)


def seed(root: Path, shipped: Path | None = None) -> bool:
    """Copy the kernels compiled at build time (in ``shipped``) into the kernel cache ``root``.

    Returns True when the kernels are (now or already) in ``root``; False when there are none
    to copy, they do not match the sources or this machine, ``PIXELPATH_PRECOMPILED=0`` is set,
    or the cache cannot be written (the kernels then compile on first use). A small file under
    ``root/precompiled`` records that this installation's files were copied, so later processes
    only look for it. ``shipped`` defaults to the package's ``_precompiled`` folder.
    """
    shipped = SHIPPED if shipped is None else shipped
    manifest_path = shipped / MANIFEST
    if not enabled() or not manifest_path.is_file():
        return False
    try:
        manifest = json.loads(manifest_path.read_text())
        done = root / "precompiled" / hashlib.sha256(
            f"{manifest['id']}|{PACKAGE_DIR}".encode()
        ).hexdigest()[:16]
        if done.is_file():
            return True
        expected = _compiled_for()
        if {key: manifest.get(key) for key in expected} != expected:
            return False
        for folder in sorted({index.parent for index in shipped.rglob("*.nbi")}):
            relative = folder.relative_to(shipped)
            _seed_folder(folder, kernel_cache_folder(root, PACKAGE_DIR / relative))
        write_markers(marker_folder(root), manifest["groups"])
        done.parent.mkdir(parents=True, exist_ok=True)
        done.write_text(json.dumps(manifest["groups"]) + "\n")
    except (OSError, KeyError, TypeError, ValueError):
        return False
    return True


@functools.cache
def cache_root() -> Path | None:
    """Return the kernel cache's folder, the kernels compiled at build time in it; None if none.

    The folder is :func:`pixelpath._cache.writable_cache_dir`'s. The shipped kernels are copied
    in (:func:`seed`) the first time a process asks, which is before Numba looks for a kernel
    there (:func:`pixelpath._jit.njit` asks first) or a command for a group's marker.
    """
    root = writable_cache_dir()
    if root is not None:
        seed(root)
    return root


def markers() -> Path | None:
    """Return the folder of the groups' markers (:mod:`pixelpath._warm`); None without a cache.

    Examples
    --------
    >>> from pixelpath._precompiled import markers
    >>> folder = markers()
    >>> folder is None or folder.parent.name == "warm"
    True
    """
    root = cache_root()
    return None if root is None else marker_folder(root)


def _build_for_setup(destination: Path) -> None:
    """Compile into ``destination`` for ``setup.py``, unless ``PIXELPATH_PRECOMPILED=0``.

    Either way no files of an earlier build (still in setuptools' build folder) are left there.
    """
    shutil.rmtree(destination, ignore_errors=True)
    if not enabled():
        return
    sys.stderr.write("compiling pixelpath's render kernels (PIXELPATH_PRECOMPILED=0 skips)\n")
    # What is shipped is what these sources compile to: neither this process nor the worker
    # processes it starts copy shipped kernels into the cache they compile in.
    os.environ["PIXELPATH_PRECOMPILED"] = "0"
    written = build(destination)
    sys.stdout.write(json.dumps(written["groups"]) + "\n")


if __name__ == "__main__":
    _build_for_setup(Path(sys.argv[1]))
