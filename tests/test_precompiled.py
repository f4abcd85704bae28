"""Kernels compiled at build time: shipped as Numba cache files, copied into a fresh cache on
first use, and loaded there instead of compiled. The round trip runs in fresh interpreters
(a process's kernels are located once), with the small ``lighting`` group."""

from __future__ import annotations

import itertools
import json
import os
import pickle
import subprocess
import sys
import textwrap
from pathlib import Path

import numba
import pytest
from numba.core import types

from pixelpath import _precompiled, _warm

needs_jit = pytest.mark.skipif(
    numba.config.DISABLE_JIT, reason="NUMBA_DISABLE_JIT=1: nothing is compiled or cached"
)


def run_python(code: str, *args: str, **changes: str) -> dict:
    """Run ``code`` with ``args`` in a fresh interpreter, the environment changed; parse its JSON.

    ``NUMBA_CACHE_DIR`` is dropped, so that ``PIXELPATH_CACHE_DIR`` alone says where the
    kernels go, and so is a ``PIXELPATH_PRECOMPILED`` of the user's.
    """
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CACHE_DIR", "PIXELPATH_PRECOMPILED")}
    result = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code), *args],
        capture_output=True,
        text=True,
        env={**env, **changes},
        timeout=300,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.splitlines()[-1])


# As setup.py runs it: the package's own shipped kernels (if any) are not copied into the cache
# the build compiles in (PIXELPATH_PRECOMPILED=0), so the group really compiles.
BUILD = """
import json, sys
from pathlib import Path
from pixelpath import _precompiled
print(json.dumps(_precompiled.build(Path(sys.argv[1]), ["lighting"])))
"""

# Points the package at the files built above instead of its own, then runs the lighting
# group's warm-up and reports what Numba compiled and what it loaded from the disk cache.
USE = """
import json, sys
from pathlib import Path
from pixelpath import _precompiled
_precompiled.SHIPPED = Path(sys.argv[1])
from pixelpath import _warm
cold = _warm.cold_groups(["lighting"], _precompiled.markers())
_warm.compile_groups(["lighting"], _precompiled.markers(), processes=1)
compiled, loaded = _warm._specializations("pixelpath.lighting._kernels")
print(json.dumps({"cold": cold, "compiled": compiled, "loaded": loaded}))
"""


def write_index(path: Path, version: object, stamp: object, data: dict[str, bytes]) -> None:
    """Write a cache index as Numba does (its version, then (stamp, overloads)) and its data."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("wb") as index:
        pickle.dump(version, index)
        pickle.dump((stamp, {f"key{i}": name for i, name in enumerate(data)}), index)
    for name, content in data.items():
        (path.parent / name).write_bytes(content)


STALE_INDEX = "_kernels.removed-1.py311.nbi"


@pytest.fixture(scope="module")
def shipped(tmp_path_factory) -> Path:
    """The lighting group's kernels built as setup.py builds them, from a scratch cache.

    The cache also holds the index of a kernel compiled from older sources, as a build folder
    reused across edits does.
    """
    if numba.config.DISABLE_JIT:
        pytest.skip("NUMBA_DISABLE_JIT=1: nothing is compiled or cached")
    from pixelpath._cache import PACKAGE_DIR, kernel_cache_folder

    build_cache = tmp_path_factory.mktemp("build-cache")
    old = kernel_cache_folder(build_cache / "numba", PACKAGE_DIR / "lighting")
    write_index(old / STALE_INDEX, numba.__version__, "older sources",
                {STALE_INDEX.replace(".nbi", ".1.nbc"): b"old code"})
    destination = tmp_path_factory.mktemp("shipped") / "_precompiled"
    run_python(BUILD, str(destination), PIXELPATH_CACHE_DIR=str(build_cache),
               PIXELPATH_PRECOMPILED="0")
    return destination


def test_the_build_ships_fresh_indexes_with_the_data_they_name(shipped, tmp_path_factory):
    manifest = json.loads((shipped / "manifest.json").read_text())
    # the seconds the group took to compile, as its marker in the build's cache records them
    # (not the built-in estimate): a first run's notice says how long compiling takes from them
    (marker,) = tmp_path_factory.getbasetemp().glob("build-cache[0-9]*/**/warm/*/lighting")
    assert manifest["groups"] == {"lighting": round(float(marker.read_text()), 3)}
    assert manifest["sources"] == _warm.sources_digest()
    assert manifest["numba"] == numba.__version__
    indexes = sorted((shipped / "lighting").glob("*.nbi"))
    assert indexes and STALE_INDEX not in {index.name for index in indexes}
    named = set()
    for path in indexes:
        index = _precompiled._Index.read(path)
        assert index is not None and index.version == numba.__version__
        named |= index.data_files
    assert named == {p.name for p in (shipped / "lighting").glob("*.nbc")}


@needs_jit
def test_a_fresh_cache_loads_the_shipped_kernels_instead_of_compiling_them(shipped, tmp_path):
    used = run_python(USE, str(shipped), PIXELPATH_CACHE_DIR=str(tmp_path))
    assert used["cold"] == []  # the group's marker came with the kernels
    assert used["compiled"] == 0 and used["loaded"] > 0
    again = run_python(USE, str(shipped), PIXELPATH_CACHE_DIR=str(tmp_path))
    assert again == used


@needs_jit
@pytest.mark.parametrize(
    ("change", "environment"),
    [
        ({"numba": "0.0.0"}, {}),
        ({"numpy": "1.0.0"}, {}),
        ({"target": ["another", "cpu", ""]}, {}),
        ({"sources": "edited since the build"}, {}),
        ({}, {"PIXELPATH_PRECOMPILED": "0"}),
    ],
    ids=["other-numba", "other-numpy", "other-cpu", "other-sources", "turned-off"],
)
def test_kernels_that_do_not_fit_are_compiled_instead(shipped, tmp_path, change, environment):
    elsewhere = tmp_path / "shipped"
    elsewhere.mkdir()
    for path in shipped.rglob("*"):
        if path.is_file():
            target = elsewhere / path.relative_to(shipped)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(path.read_bytes())
    manifest = json.loads((shipped / "manifest.json").read_text())
    (elsewhere / "manifest.json").write_text(json.dumps(manifest | change))
    used = run_python(USE, str(elsewhere), PIXELPATH_CACHE_DIR=str(tmp_path / "cache"),
                      **environment)
    assert used["cold"] == ["lighting"]
    assert used["compiled"] > 0 and used["loaded"] == 0


def test_seeding_keeps_a_current_index_and_replaces_a_stale_one(tmp_path):
    shipped, cache = tmp_path / "shipped", tmp_path / "cache"

    def index(kernel: int) -> str:
        return f"_kernels.kernel-{kernel}.py311.nbi"

    def data(kernel: int, entry: int = 1) -> str:
        return f"_kernels.kernel-{kernel}.py311.{entry}.nbc"

    for kernel in (1, 2, 3):
        write_index(shipped / index(kernel), "1.0", "now", {data(kernel): b"shipped"})
    # Kernel 2: the user's own current index, with one more entry; kernel 3: a stale one.
    write_index(cache / index(2), "1.0", "now", {data(2, 1): b"mine", data(2, 2): b"mine"})
    write_index(cache / index(3), "1.0", "before", {data(3): b"old"})
    _precompiled._seed_folder(shipped, cache)
    assert (cache / data(1)).read_bytes() == b"shipped"
    assert _precompiled._Index.read(cache / index(2)).data_files == {data(2, 1), data(2, 2)}
    assert (cache / data(2)).read_bytes() == b"mine"
    assert _precompiled._Index.read(cache / index(3)).stamp == "now"
    assert (cache / data(3)).read_bytes() == b"shipped"
    assert not list(cache.glob(".*"))  # no temporary file left behind


def test_an_index_is_read_without_importing_the_classes_its_signatures_name(tmp_path, monkeypatch):
    # Seeding runs while the first kernel module is being imported, before the classes its
    # kernels take (named tuples) exist: an index naming one must still be read.
    (tmp_path / "vanishing_module.py").write_text("class Scene:\n    pass\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import vanishing_module

    path = tmp_path / "_kernels.kernel-1.py311.nbi"
    with path.open("wb") as index:
        pickle.dump("1.0", index)
        pickle.dump(("now", {(vanishing_module.Scene(), "int64"): "_kernels.kernel-1.py311.1.nbc"}),
                    index)
    monkeypatch.delitem(sys.modules, "vanishing_module")
    (tmp_path / "vanishing_module.py").unlink()
    with path.open("rb") as index, pytest.raises(ModuleNotFoundError):
        pickle.load(index), pickle.load(index)
    read = _precompiled._Index.read(path)
    assert read == _precompiled._Index("1.0", "now", frozenset({"_kernels.kernel-1.py311.1.nbc"}))


def test_an_installed_package_ships_kernels_for_its_own_sources():
    manifest_path = _precompiled.SHIPPED / _precompiled.MANIFEST
    if not manifest_path.is_file():
        pytest.skip("no kernels compiled at build time here (an editable install, or "
                    "PIXELPATH_PRECOMPILED=0 when it was built)")
    manifest = json.loads(manifest_path.read_text())
    assert set(manifest["groups"]) == set(_precompiled.BUILT_GROUPS)
    assert manifest["sources"] == _warm.sources_digest()


def literal_twins(folder: Path) -> list[str]:
    """Kernels in the Numba cache under ``folder`` compiled twice for want of a typed argument.

    Numba types a literal argument (``0``, ``-1``, ``True`` or a global constant written at
    the call) as a type of its own, so a helper called with a literal at one place and a
    variable (or another literal) at another is compiled once per call: a kernel is listed
    when two of its signatures differ in an argument that one of them takes as a literal.
    """
    twins = []
    for path in sorted(folder.rglob("*.nbi")):
        with path.open("rb") as index:
            pickle.load(index)  # Numba's version
            _, overloads = pickle.load(index)
        signatures = [key[0] for key in overloads]
        for first, other in itertools.combinations(signatures, 2):
            if any(isinstance(a, types.Literal) or isinstance(b, types.Literal)
                   for a, b in zip(first, other, strict=True) if a != b):
                twins.append(f"{path.name}: {first} and {other}")
    return twins


def test_a_kernel_compiled_once_for_a_literal_and_once_for_a_variable_is_found(tmp_path):
    path = tmp_path / "raster" / "_kernels.helper-1.py311.nbi"
    path.parent.mkdir()
    for second, found in ((types.int64, False), (types.literal(-1), True)):
        with path.open("wb") as index:
            pickle.dump(numba.__version__, index)
            pickle.dump(("now", {((types.float64, types.int64), "cpu"): "a.nbc",
                                 ((types.float64, second), "cpu"): "b.nbc"}), index)
        assert bool(literal_twins(tmp_path)) == found


def test_no_shipped_kernel_is_compiled_twice_for_a_literal_argument():
    # Such a twin cost the z-buffer's pass 1.2 s of its compile, and each build and cold
    # first use: a kernel is typed for its callers' argument types (pixelpath._jit.Kernel).
    if not (_precompiled.SHIPPED / _precompiled.MANIFEST).is_file():
        pytest.skip("no kernels compiled at build time here (an editable install, or "
                    "PIXELPATH_PRECOMPILED=0 when it was built)")
    assert literal_twins(_precompiled.SHIPPED) == []


def test_a_build_with_precompiling_off_ships_nothing_not_even_an_earlier_builds(
    tmp_path, monkeypatch
):
    earlier = tmp_path / "_precompiled"  # as setuptools' build folder keeps it between builds
    (earlier / "raster").mkdir(parents=True)
    (earlier / _precompiled.MANIFEST).write_text("{}")
    monkeypatch.setenv("PIXELPATH_PRECOMPILED", "0")
    _precompiled._build_for_setup(earlier)
    assert not earlier.exists()
