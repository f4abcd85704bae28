"""Compile the kernels a command needs before it runs, on every core at once.

Numba compiles a kernel in the process that first calls it, one kernel at a time (its compiler
holds a global lock), and on a first run that is most of the time a render takes. A kernel
compiled in another process lands in the same disk cache, and a later call here loads it in
milliseconds. So the kernels are split into *groups* that compile independently (each group's
warm-up builds its inputs by hand, without another group's kernels), and on a cold start the
groups a command needs are compiled in parallel worker processes, this one taking a share.

A group is known to be compiled when its marker exists: a file named after the group in a
folder of the cache named after a hash of pixelpath's sources and the Python and Numba
versions, so that any change to the code makes every group cold again (loading unchanged
kernels from the cache is quick). The marker holds the seconds the group took to compile.
The functions here are handed that folder (:func:`pixelpath._precompiled.markers` finds it in
the kernel cache): this module imports neither :mod:`pixelpath._cache` nor
:mod:`pixelpath._precompiled`.

Run as ``python -m pixelpath._warm GROUP...`` a worker compiles the groups named and prints
their seconds as JSON.
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import json
import os
import subprocess
import sys
import time
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "COMPILED_WITH",
    "FEEDS",
    "FOLLOWS",
    "GROUPS",
    "LOOKUPS",
    "METHOD_GROUPS",
    "SHADING_GROUPS",
    "WarmupReport",
    "cold_groups",
    "compile_groups",
    "estimate_seconds",
    "groups_for",
    "kernel_modules",
    "marker_folder",
    "recorded_seconds",
    "run_warmups",
    "sources_digest",
    "write_markers",
]

# Every kernel module's warm-up, the one registry of them. Group name -> (warm-up function as
# "module:function", seconds it took to compile on the 2-core machine pixelpath is developed
# on; only used to share out work and to say how long a first run will take, before anything
# was measured here). Measured 2026-11-27 in the build step (python -m pixelpath._precompiled,
# every group a render calls, in two processes into one empty cache, each group after those
# its process compiled before it); clip and color, which the build leaves out, alone in one
# process on 2026-11-26.
GROUPS: dict[str, tuple[str, float]] = {
    "front": ("pixelpath.raster._kernels:warm_front", 3.0),
    "vertex-shading": ("pixelpath.raster._kernels:warm_vertex_shading", 0.2),
    # The z-buffer's depth test ("depth-test"), its fused pass ("back") and the other methods'
    # shading pass ("shade"), each for plain scenes and, "-lookups", with the alpha test and
    # the colour lookups of textures and vertex colours (LOOKUPS), which "colours" compiles;
    # the passes call the shading of a row, "rows" (FOLLOWS), and load the depth test and the
    # colour lookups from the cache (FEEDS). Until 2026-11-28 "depth-test" (4.2 s), "back"
    # (10.0 s) and "shade" (1.9 s) held them all; the estimates are what the groups took when
    # they split, on a machine that compiled those in 2.9, 7.1 and 1.4 s, scaled by 10 / 7.1
    # (depth-test 1.1 s there, depth-test-lookups 2.6, rows 3.3-4.0, colours 2.1-2.4, back 1.1,
    # back-lookups 1.2-1.6, shade 1.3-1.5, shade-lookups 1.1).
    "depth-test": ("pixelpath.raster._kernels:warm_depth_test", 1.5),
    "depth-test-lookups": ("pixelpath.raster._kernels:warm_depth_test_lookups", 3.7),
    "rows": ("pixelpath.raster._kernels:warm_rows", 5.2),
    "colours": ("pixelpath.raster._kernels:warm_colours", 3.2),
    "back": ("pixelpath.raster._kernels:warm_back", 1.5),
    "back-lookups": ("pixelpath.raster._kernels:warm_back_lookups", 2.0),
    "shade": ("pixelpath.raster._kernels:warm_shade", 2.0),
    "shade-lookups": ("pixelpath.raster._kernels:warm_shade_lookups", 1.5),
    "scan": ("pixelpath.raster._kernels:warm_scan", 2.4),
    "scanline": ("pixelpath.hsr._kernels.scanline:warmup", 6.8),
    "warnock": ("pixelpath.hsr._kernels.warnock:warmup", 3.7),
    "painter": ("pixelpath.hsr._kernels.painter:warmup", 6.4),
    "bsp": ("pixelpath.hsr._kernels.bsp:warmup", 9.7),
    "lighting": ("pixelpath.lighting._kernels:warmup", 0.2),
    "clip": ("pixelpath.clip._kernels:warmup", 13.0),
    "color": ("pixelpath.color._kernels:warmup", 12.0),
    # The BVH build, which the tracer calls, and the searches and ray tests of batches of rays
    # (raytrace.intersect, raytrace.geometry), which it does not: 2.2 and 3.8 s of the 6.0 s
    # the two took as one group on 2026-11-28, which every cold ray-traced render paid. The
    # searches take the eye rays' packet search from "raytrace-eye" (FOLLOWS). The tracer's
    # groups' estimates: what they took in the build step on 2026-11-28 on a 2-core AMD
    # machine, times 1.3, what the other groups took there against their estimates.
    "raytrace-bvh": ("pixelpath.raytrace._bvh_kernels:warmup", 2.1),
    "raytrace-queries": ("pixelpath.raytrace._bvh_kernels:warm_queries", 1.6),
    # The tracer's row kernel ("raytrace") calls the search of its eye rays ("raytrace-eye",
    # which another process compiles, FEEDS) and then their shadow search ("raytrace-shadows",
    # which its own process compiles first, FOLLOWS), and loads both from the cache.
    "raytrace-eye": ("pixelpath.raytrace._whitted_kernels:warm_eye_rays", 6.8),
    "raytrace-shadows": ("pixelpath.raytrace._whitted_kernels:warm_shadow_rays", 6.1),
    "raytrace": ("pixelpath.raytrace._whitted_kernels:warmup", 6.5),
    "octree": ("pixelpath.hsr._kernels.octree:warmup", 6.4),
    "lines": ("pixelpath.raster._line_kernels:warmup", 1.6),
    # 8-bit encoding of float32 pictures (to_uint8); built with the render groups (BUILT_GROUPS).
    "images": ("pixelpath.io._kernels:warmup", 0.2),
}

# The groups a render with each hidden-surface method calls, and those a drawing style adds.
# Those of the shading passes are the passes for plain scenes (groups_for swaps in LOOKUPS).
METHOD_GROUPS: dict[str, tuple[str, ...]] = {
    "zbuffer": ("front", "depth-test", "rows", "back"),
    "scanline": ("front", "rows", "shade", "scanline"),
    "warnock": ("front", "rows", "shade", "warnock"),
    "painter": ("front", "rows", "shade", "scan", "painter"),
    "bsp": ("front", "rows", "shade", "scan", "bsp"),
    "octree": ("front", "rows", "shade", "octree"),
    "raytrace": ("lighting", "raytrace-bvh", "raytrace-eye", "raytrace-shadows", "raytrace"),
    "wireframe": ("lines",),
    "hidden-line": ("lines",),
}

# What the raster methods (those that run the front end) add for a shading mode: flat and
# Gouraud shading light points before rasterizing, Phong shading only per pixel.
SHADING_GROUPS: dict[str, tuple[str, ...]] = {
    "flat": ("vertex-shading",),
    "gouraud": ("vertex-shading",),
    "phong": (),
}

# Groups that call another group's kernels, and are only needed with it: when both are cold
# they compile in one process, the caller after the callee, whose kernels it then reuses
# instead of compiling them again (the shading passes all shade rows of pixels with the same
# kernels; the tracer's row kernel loads its shadow search, compiled before it, and the
# searches of batches of rays the eye rays' packet search).
FOLLOWS: dict[str, str] = {
    "back": "rows",
    "back-lookups": "rows",
    "shade": "rows",
    "shade-lookups": "rows",
    "raytrace": "raytrace-shadows",
    "raytrace-queries": "raytrace-eye",
}

# Each pass's group for plain scenes, and its version with the alpha test and the colour
# lookups, which a render of a scene with textures, vertex colours or alpha-tested materials
# needs instead. A plain scene's render, most of them, compiles none of those lookups
# (pixelpath.raster._kernels.looks_up, pixelpath.scene.texture.needs_lookups).
LOOKUPS: dict[str, str] = {
    "depth-test": "depth-test-lookups",
    "back": "back-lookups",
    "shade": "shade-lookups",
}

# Groups that compile part of another group's kernels, for that one to load from the disk
# cache: each goes first in its process, and the other group compiles the rest of its
# kernels first, so that two processes share the work of one kernel that calls both parts.
# The z-buffer's fused pass ("back", 13 s alone) calls its depth test (4 s) and its row
# shading (7 s); the tracer's row kernel ("raytrace") its eye rays' search (4.3 s), reached
# at once, and then their shadow search (5.7 s), which its process compiles before it
# (FOLLOWS) while the other compiles the eye rays'. Split so, a cold z-buffer render took 12 s
# instead of 15 (docs/performance.md). Should the other process be late, the kernels are
# compiled twice, as they were unsplit. The passes with lookups take them from "colours" and
# "depth-test-lookups" so.
FEEDS: dict[str, tuple[str, ...]] = {
    "depth-test": ("back",),
    "depth-test-lookups": ("back-lookups",),
    "colours": ("back-lookups", "shade-lookups"),
    "raytrace-eye": ("raytrace",),
}

# Kernel modules without a warm-up of their own, after the module whose warm-ups compile their
# kernels: the report of that module counts theirs too (a file split by concern keeps one
# warm-up, and one line in ``pixelpath warmup``, for its parts).
COMPILED_WITH: dict[str, tuple[str, ...]] = {
    # The texture lookups serve the tracer too; the raster's groups come first in GROUPS.
    "pixelpath.raster._kernels": (
        "pixelpath.raster._setup_kernels",
        "pixelpath.raster._scan_kernels",
        "pixelpath.scene._texture_kernels",
    ),
    "pixelpath.raytrace._bvh_kernels": (
        "pixelpath.raytrace._hit_kernels",
        "pixelpath.raytrace._traversal_kernels",
    ),
    "pixelpath.raytrace._whitted_kernels": (
        "pixelpath.raytrace._records",
        "pixelpath.raytrace._primary_kernels",
        "pixelpath.raytrace._surface_kernels",
    ),
}


@dataclass(frozen=True)
class WarmupReport:
    """What one kernel module's warm-up did: its module, seconds taken, specializations.

    ``compiled`` counts the specializations Numba compiled, ``loaded`` those it loaded from the
    disk cache (both 0 with ``NUMBA_DISABLE_JIT=1``, where nothing compiles), of the module's
    kernels and those of the modules :data:`COMPILED_WITH` it.

    Examples
    --------
    >>> from pixelpath._warm import WarmupReport
    >>> WarmupReport("pixelpath.color._kernels", seconds=4.2, compiled=12, loaded=0).compiled
    12
    """

    module: str
    seconds: float
    compiled: int
    loaded: int


def _module_of(group: str) -> str:
    return GROUPS[group][0].split(":")[0]


def kernel_modules() -> tuple[str, ...]:
    """Return every module with a warm-up, each once, in :data:`GROUPS` order.

    Every other module that holds compiled kernels is :data:`COMPILED_WITH` one of these.

    Examples
    --------
    >>> from pixelpath._warm import kernel_modules
    >>> kernel_modules()[:2]
    ('pixelpath.raster._kernels', 'pixelpath.hsr._kernels.scanline')
    """
    return tuple(dict.fromkeys(_module_of(group) for group in GROUPS))


def _specializations(module_name: str) -> tuple[int, int]:
    """Return (compiled, loaded from cache) over the kernels defined in module ``module_name``.

    The kernels of the modules :data:`COMPILED_WITH` it count too.
    """
    from numba.core.dispatcher import Dispatcher

    compiled = loaded = 0
    for name in (module_name, *COMPILED_WITH.get(module_name, ())):
        for value in vars(importlib.import_module(name)).values():
            if isinstance(value, Dispatcher) and value.py_func.__module__ == name:
                compiled += sum(value.stats.cache_misses.values())
                loaded += sum(value.stats.cache_hits.values())
    return compiled, loaded


def run_warmups(markers: Path | None) -> list[WarmupReport]:
    """Run every group's warm-up in this process, module by module; report each module.

    Afterwards every group is in the disk cache, so its marker is written too (in the folder
    ``markers``; None when there is no disk cache): a first render
    then starts no worker processes. ``pixelpath warmup`` prints these reports (its test
    checks that a second run compiles nothing); compiling everything takes minutes, so the
    example of :class:`WarmupReport` only shows their shape.
    """
    reports = []
    seconds: dict[str, float] = {}
    for module in kernel_modules():
        importlib.import_module(module)
        before = _specializations(module)
        start = time.perf_counter()
        seconds.update(_compile_here(g for g in GROUPS if _module_of(g) == module))
        elapsed = time.perf_counter() - start
        compiled, loaded = (now - then for now, then in zip(_specializations(module), before,
                                                            strict=True))
        reports.append(WarmupReport(module, elapsed, compiled, loaded))
    if markers is not None and _jit_enabled():
        write_markers(markers, seconds)
    return reports


def groups_for(
    methods: Iterable[str], shadings: Iterable[str] | None = None, *,
    lookups: bool | None = None,
) -> tuple[str, ...]:
    """Return the groups renders with ``methods`` (or drawing styles) need, each once, in order.

    ``shadings`` are the shading modes the renders use (default: every mode); ``lookups``
    says whether the scenes rendered have surfaces looked up point by point (textures,
    vertex colours or alpha tests, :func:`pixelpath.scene.texture.needs_lookups`): True,
    False, or None when that is not known, for both kinds (:data:`LOOKUPS`).

    Examples
    --------
    >>> from pixelpath._warm import groups_for
    >>> groups_for(["zbuffer", "scanline"], shadings=["phong"], lookups=False)
    ('front', 'depth-test', 'rows', 'back', 'shade', 'scanline')
    >>> groups_for(["zbuffer"], shadings=["gouraud"], lookups=True)
    ('front', 'vertex-shading', 'depth-test-lookups', 'rows', 'colours', 'back-lookups')
    """
    needed = {group for method in methods for group in METHOD_GROUPS.get(method, ())}
    if "front" in needed:
        modes = SHADING_GROUPS if shadings is None else shadings
        needed.update(group for mode in modes for group in SHADING_GROUPS.get(mode, ()))
    passes = {group for group in LOOKUPS if group in needed}
    if passes and lookups is not False:
        needed.update({"colours", *(LOOKUPS[group] for group in passes)})
    if lookups:
        needed -= passes
    return tuple(group for group in GROUPS if group in needed)


@functools.cache
def sources_digest() -> str:
    """Return a hash of pixelpath's source files, their names and contents.

    Examples
    --------
    >>> from pixelpath._warm import sources_digest
    >>> len(sources_digest())
    64
    """
    package = Path(__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        digest.update(path.relative_to(package).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


@functools.cache
def _stamp() -> str:
    """Hash of where pixelpath is installed, its source files and the Python and Numba versions.

    The kernels' cache is kept per source path, so a second installation of the same code
    (another virtual environment, a fresh clone) has its own markers.
    """
    import numba

    package = Path(__file__).resolve().parent
    where = f"{sys.version}|{numba.__version__}|{package}|{sources_digest()}"
    return hashlib.sha256(where.encode()).hexdigest()[:16]


def marker_folder(root: Path) -> Path:
    """Return the folder of the markers of this installation's groups in the kernel cache ``root``.

    Examples
    --------
    >>> from pathlib import Path
    >>> from pixelpath._warm import marker_folder
    >>> marker_folder(Path("/cache")).parent.as_posix()
    '/cache/warm'
    """
    return root / "warm" / _stamp()


def _jit_enabled() -> bool:
    import numba

    return not numba.config.DISABLE_JIT


def cold_groups(groups: Iterable[str], markers: Path | None) -> list[str]:
    """Return those of ``groups`` without a marker in the folder ``markers`` (in their order).

    Empty when Numba's JIT is disabled (nothing to compile) and when no cache folder can be
    written (worker processes could not hand their code over: each kernel compiles on first
    use, as without this module).

    Examples
    --------
    >>> from pixelpath._precompiled import markers
    >>> from pixelpath._warm import cold_groups
    >>> set(cold_groups(["front", "back"], markers())) <= {"front", "back"}
    True
    >>> cold_groups(["front", "back"], None)
    []
    """
    if markers is None or not _jit_enabled():
        return []
    return [group for group in groups if not (markers / group).is_file()]


def recorded_seconds(group: str, folder: Path | None) -> float:
    """Return the seconds ``group`` took to compile here, else its built-in estimate.

    The seconds are read from the group's marker in ``folder``; the estimate is :data:`GROUPS`'.

    Examples
    --------
    >>> from pixelpath._warm import GROUPS, recorded_seconds
    >>> recorded_seconds("front", None) == GROUPS["front"][1]
    True
    """
    if folder is None:
        return GROUPS[group][1]
    try:
        return float((folder / group).read_text())
    except (OSError, ValueError):
        return GROUPS[group][1]


def estimate_seconds(
    groups: Sequence[str], markers: Path | None, processes: int | None = None
) -> float:
    """Return about how long compiling ``groups`` on ``processes`` processes takes.

    From the seconds each group took when last compiled here (its marker in ``markers``), else
    the built-in estimate.

    Examples
    --------
    >>> from pixelpath._warm import estimate_seconds
    >>> estimate_seconds([], None) == 0
    True
    """
    shares = _share_out(groups, processes or _cores(), markers)
    return max((sum(recorded_seconds(g, markers) for g in share) for share in shares), default=0)


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _share_out(groups: Sequence[str], processes: int, folder: Path | None) -> list[list[str]]:
    """Split ``groups`` into at most ``processes`` shares of about equal compile time.

    A group that :data:`FOLLOWS` another one of ``groups`` goes into that one's share, after it;
    a group that :data:`FEEDS` others goes first in its share.
    """
    units: dict[str, list[str]] = {}
    for group in groups:
        leader = FOLLOWS.get(group)
        units.setdefault(leader if leader in groups else group, []).append(group)
    for unit in units.values():
        unit.sort(key=lambda g: g in FOLLOWS)
    cost = {lead: sum(recorded_seconds(g, folder) for g in unit) for lead, unit in units.items()}
    shares: list[list[str]] = [[] for _ in range(max(1, min(processes, len(units))))]
    loads = [0.0] * len(shares)
    for lead in sorted(units, key=lambda g: -cost[g]):
        lightest = loads.index(min(loads))
        shares[lightest].extend(units[lead])
        loads[lightest] += cost[lead]
    for share in shares:
        share.sort(key=lambda g: g not in FEEDS)  # stable: the others keep their order
    return [share for share in shares if share]


def _compile_here(groups: Iterable[str]) -> dict[str, float]:
    """Run the groups' warm-ups in this process; return the seconds each took."""
    seconds = {}
    for group in groups:
        module_name, function_name = GROUPS[group][0].split(":")
        start = time.perf_counter()
        getattr(importlib.import_module(module_name), function_name)()
        seconds[group] = time.perf_counter() - start
    return seconds


def compile_groups(
    groups: Sequence[str], markers: Path | None, processes: int | None = None
) -> dict[str, float]:
    """Compile ``groups`` into the disk cache, on up to ``processes`` processes at once.

    This process compiles one share itself, the one estimated longest: the others go to
    worker processes started with the same Python, which import pixelpath and Numba before
    they compile (most of a second). A worker that fails leaves its groups to this process.
    Each compiled group's marker is written afterwards.

    Parameters
    ----------
    groups : sequence of str
        Names from :data:`GROUPS`.
    markers : Path or None
        The markers' folder in the kernel cache (:func:`pixelpath._precompiled.markers`); None
        when there is no disk cache, and everything compiles in this process.
    processes : int, optional
        How many processes compile at once (default: the cores this process may use).

    Returns
    -------
    dict of str to float
        Seconds each group took to compile (or load from the cache).

    Examples
    --------
    >>> from pixelpath._precompiled import markers
    >>> from pixelpath._warm import compile_groups
    >>> sorted(compile_groups(["lighting"], markers(), processes=1))
    ['lighting']
    """
    unknown = sorted(set(groups) - set(GROUPS))
    if unknown:
        raise ValueError(f"unknown kernel groups {unknown}; known: {sorted(GROUPS)}")
    if markers is None:  # no disk cache: what workers compiled would not reach this process
        return _compile_here(groups)
    shares = _share_out(list(groups), processes or _cores(), markers)
    if not shares:
        return {}
    shares.sort(key=lambda share: -sum(recorded_seconds(g, markers) for g in share))
    workers = [_start_worker(share) for share in shares[1:]]
    seconds = _compile_here(shares[0])
    for share, worker in zip(shares[1:], workers, strict=True):
        seconds.update(_finish_worker(share, worker))
    write_markers(markers, seconds)
    return seconds


def _start_worker(share: list[str]) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "pixelpath._warm", *share],
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )


def _finish_worker(share: list[str], worker: subprocess.Popen) -> dict[str, float]:
    """Wait for a worker; compile its share here instead if it failed."""
    output, _ = worker.communicate()
    try:
        seconds = json.loads(output) if worker.returncode == 0 else None
    except json.JSONDecodeError:
        seconds = None
    if not isinstance(seconds, dict) or set(seconds) != set(share):
        return _compile_here(share)
    return {group: float(value) for group, value in seconds.items()}


def write_markers(folder: Path, seconds: Mapping[str, float]) -> None:
    """Record each compiled group and its seconds in the markers' ``folder``.

    An unwritable cache only means that the next run checks again.
    """
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for group, value in seconds.items():
            (folder / group).write_text(f"{value:.3f}\n")
    except OSError:
        pass


if __name__ == "__main__":
    sys.stdout.write(json.dumps(_compile_here(sys.argv[1:])) + "\n")
