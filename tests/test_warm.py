"""Compiling kernel groups ahead of a first run, in parallel processes."""

from __future__ import annotations

import functools
import importlib
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numba
import pytest

from pixelpath import _precompiled, _warm
from pixelpath.renderer import METHOD_NAMES, STYLES

needs_jit = pytest.mark.skipif(numba.config.DISABLE_JIT, reason="needs Numba's JIT")
DUCK = str(Path(__file__).parent / "data" / "models" / "Duck.glb")  # textured


def test_every_method_groups_name_known_groups():
    for method, groups in _warm.METHOD_GROUPS.items():
        assert method in METHOD_NAMES or method in STYLES
        assert set(groups) <= set(_warm.GROUPS)


def test_a_method_that_needs_a_following_group_needs_its_leader_first():
    for groups in _warm.METHOD_GROUPS.values():
        for follower, leader in _warm.FOLLOWS.items():
            if follower in groups:
                assert groups.index(leader) < groups.index(follower)


@needs_jit
def test_every_module_with_compiled_kernels_is_counted_in_the_warmup_report():
    # A kernel module split by concern keeps its parts on its warm-up module's line; a part
    # missing from COMPILED_WITH would compile uncounted. Inlined kernels compile no code of
    # their own (they are typed into their callers).
    from numba.core.dispatcher import Dispatcher

    from pixelpath._cache import PACKAGE_DIR

    counted = set(_warm.kernel_modules()).union(*_warm.COMPILED_WITH.values())
    holding = set()
    for path in PACKAGE_DIR.rglob("*.py"):
        if "@njit" not in path.read_text():
            continue
        name = ".".join(("pixelpath", *path.relative_to(PACKAGE_DIR).with_suffix("").parts))
        module = importlib.import_module(name)
        if any(isinstance(value, Dispatcher) and value.py_func.__module__ == name
               and value.targetoptions.get("inline") != "always"
               for value in vars(module).values()):
            holding.add(name)
    assert "pixelpath.raytrace._hit_kernels" in holding
    assert holding - counted == set()


def test_groups_for_lists_each_group_once_in_table_order():
    assert _warm.groups_for(["warnock", "zbuffer", "warnock"], ["phong"], lookups=False) == (
        "front", "depth-test", "rows", "back", "shade", "warnock")
    assert _warm.groups_for([]) == ()


def test_groups_for_adds_vertex_shading_to_raster_methods_only():
    plain = functools.partial(_warm.groups_for, lookups=False)
    assert plain(["zbuffer"], ["phong"]) == ("front", "depth-test", "rows", "back")
    assert plain(["zbuffer"], ["flat", "phong"]) == (
        "front", "vertex-shading", "depth-test", "rows", "back")
    assert plain(["zbuffer"]) == (  # every mode
        "front", "vertex-shading", "depth-test", "rows", "back")
    assert "vertex-shading" not in plain(["raytrace", "wireframe"], ["flat"])


def test_groups_for_takes_the_passes_for_the_surfaces_the_scenes_have():
    # plain, looked up point by point (the passes with the lookups instead), or not known
    assert _warm.groups_for(["zbuffer"], ["phong"], lookups=True) == (
        "front", "depth-test-lookups", "rows", "colours", "back-lookups")
    assert _warm.groups_for(["painter"], ["phong"], lookups=True) == (
        "front", "rows", "colours", "shade-lookups", "scan", "painter")
    assert _warm.groups_for(["zbuffer", "octree"], ["phong"]) == (
        "front", "depth-test", "depth-test-lookups", "rows", "colours", "back", "back-lookups",
        "shade", "shade-lookups", "octree")
    for methods in (["raytrace"], ["wireframe"], ["raytrace", "hidden-line"]):
        assert (_warm.groups_for(methods) == _warm.groups_for(methods, lookups=True)
                == _warm.groups_for(methods, lookups=False))
    for groups in _warm.METHOD_GROUPS.values():  # swapped in only
        assert not set(groups) & {"colours", *_warm.LOOKUPS.values()}


def test_shares_balance_the_estimated_seconds(tmp_path, monkeypatch):
    estimates = {"front": 4.5, "back": 6.0, "scan": 1.5, "clip": 4.0, "color": 4.0}
    for group, seconds in estimates.items():
        monkeypatch.setitem(_warm.GROUPS, group, (_warm.GROUPS[group][0], seconds))
    groups = list(estimates)
    shares = _warm._share_out(groups, 2, tmp_path)
    assert sorted(g for share in shares for g in share) == sorted(groups)
    loads = [sum(_warm.GROUPS[g][1] for g in share) for share in shares]
    assert loads == [10.0, 10.0]  # back+color, front+clip+scan: the greedy split is even here
    assert _warm._share_out(groups, 8, tmp_path) == [[g] for g in sorted(
        groups, key=lambda g: -_warm.GROUPS[g][1])]
    assert _warm._share_out([], 4, tmp_path) == []


def test_a_group_that_follows_another_shares_its_process_after_it(tmp_path):
    for follower, leader in _warm.FOLLOWS.items():
        shares = _warm._share_out([follower, "front", leader, "scan"], 8, tmp_path)
        with_leader = [share for share in shares if leader in share]
        assert with_leader == [[leader, follower]]
        assert len(shares) == 3
        alone = _warm._share_out([follower, "scan"], 8, tmp_path)
        assert sorted(alone) == sorted([[follower], ["scan"]])


def test_a_group_that_feeds_another_goes_first_in_its_process(tmp_path):
    for feeder, feds in _warm.FEEDS.items():
        for fed in feds:
            groups = [fed, "front", "scan", feeder]
            for processes in (1, 2, 8):
                shares = _warm._share_out(groups, processes, tmp_path)
                assert sorted(g for share in shares for g in share) == sorted(groups)
                assert [share.index(feeder) for share in shares if feeder in share] == [0]


def test_every_render_that_runs_a_fed_group_runs_its_feeder():
    for method in _warm.METHOD_GROUPS:
        for lookups in (False, True, None):
            groups = _warm.groups_for([method], lookups=lookups)
            for feeder, feds in _warm.FEEDS.items():
                assert (feeder in groups) == any(fed in groups for fed in feds)


def test_recorded_seconds_replace_the_estimate(tmp_path):
    (tmp_path / "front").write_text("0.250\n")
    (tmp_path / "back").write_text("not a number\n")
    assert _warm.recorded_seconds("front", tmp_path) == 0.25
    assert _warm.recorded_seconds("back", tmp_path) == _warm.GROUPS["back"][1]


def test_unknown_groups_are_refused():
    with pytest.raises(ValueError, match="unknown kernel groups"):
        _warm.compile_groups(["front", "nonsense"], None)


def test_this_process_compiles_the_share_estimated_longest(tmp_path, monkeypatch):
    # workers start a Python and import Numba first: they take the shorter shares
    for group, seconds in {"front": 2.5, "scan": 4.0, "lighting": 2.0}.items():
        monkeypatch.setitem(_warm.GROUPS, group, (_warm.GROUPS[group][0], seconds))
    here, started = [], []
    monkeypatch.setattr(_warm, "_compile_here", lambda share: here.append(list(share)) or {
        g: 0.0 for g in share})
    monkeypatch.setattr(_warm, "_start_worker", lambda share: started.append(list(share)))
    monkeypatch.setattr(_warm, "_finish_worker", lambda share, worker: dict.fromkeys(share, 0.0))
    _warm.compile_groups(["front", "scan", "lighting"], tmp_path, processes=2)
    assert here == [["front", "lighting"]] and started == [["scan"]]  # 4.5 s, 4 s


def test_a_failed_worker_leaves_its_share_to_this_process(monkeypatch):
    ran = []
    monkeypatch.setattr(_warm, "_compile_here", lambda share: ran.extend(share) or {
        g: 0.0 for g in share})
    failing = subprocess.Popen([sys.executable, "-c", "import sys; sys.exit(3)"],
                               stdout=subprocess.PIPE, text=True)
    assert _warm._finish_worker(["scan"], failing) == {"scan": 0.0}
    garbled = subprocess.Popen([sys.executable, "-c", "print('[1, 2]')"],
                               stdout=subprocess.PIPE, text=True)
    assert _warm._finish_worker(["clip"], garbled) == {"clip": 0.0}
    assert ran == ["scan", "clip"]


def _stamp_of_copy(root) -> str:
    """The stamp seen by a pixelpath imported from the copy of the package under ``root``."""
    code = "from pixelpath import _warm; print(_warm._stamp())"
    env = {**os.environ, "PYTHONPATH": str(root)}
    return subprocess.run([sys.executable, "-c", code], env=env, check=True,
                          capture_output=True, text=True).stdout.strip()


def test_the_stamp_follows_the_install_location_and_the_sources(tmp_path):
    import shutil

    import pixelpath

    here = _warm._stamp()
    assert here == _warm._stamp() and len(here) == 16
    assert here in str(_precompiled.markers())
    copy = tmp_path / "pixelpath"
    shutil.copytree(os.path.dirname(pixelpath.__file__), copy,
                    ignore=shutil.ignore_patterns("__pycache__"))
    elsewhere = _stamp_of_copy(tmp_path)
    assert elsewhere != here  # same code, another place: its kernels are cached apart
    (copy / "_threads.py").write_text((copy / "_threads.py").read_text() + "\n# edited\n")
    assert _stamp_of_copy(tmp_path) not in (here, elsewhere)


# The start of the scripts below: lists every function Numba starts to compile afterwards.
_COUNT_COMPILES = textwrap.dedent(
    """
    import json, sys
    from numba.core import event
    compiled = []

    class Count(event.Listener):
        def on_start(self, e):
            compiled.append(e.data["dispatcher"].py_func.__qualname__)

        def on_end(self, e):
            pass

    event.register("numba:compile", Count())
    """
)

# Compile every method's groups into an empty cache in worker processes, then render each
# method and shading in a fresh process, a plain scene and a textured model (the passes with
# colour lookups): nothing may compile there. This proves that the groups' hand-made warm-up
# inputs have the very types the render path passes. Methods come after the model's path.
_RENDER_EVERY_METHOD = _COUNT_COMPILES + textwrap.dedent(
    """
    import dataclasses
    import pixelpath as pp
    from pixelpath.scene import bundled_scenes, load_scene
    for scene in (load_scene(bundled_scenes()["showcase"]), load_scene(sys.argv[1])):
        scene = dataclasses.replace(scene, camera=scene.camera.with_size(64, 40))
        for method in sys.argv[2:]:
            if method in ("wireframe", "hidden-line"):
                pp.render(scene, style=method)
                continue
            for shading in ("flat", "gouraud", "phong"):
                if (method, shading) != ("raytrace", "gouraud"):  # a ray tracer has no Gouraud
                    pp.render(scene, method=method, shading=shading)
    print(json.dumps(compiled))
    """
)


@needs_jit
@pytest.mark.slow
def test_after_compiling_the_groups_a_render_compiles_nothing(tmp_path):
    from pixelpath._precompiled import MANIFEST, SHIPPED

    if (SHIPPED / MANIFEST).is_file():
        # The package's build compiled these very groups, through these functions, into an
        # empty cache: the next test renders every method with them and counts what compiles.
        # Compiling them again here would check nothing more, for a minute of two cores.
        pytest.skip("the build compiled the groups: the build-time kernels test renders with "
                    "them")
    # PIXELPATH_PRECOMPILED=0: an installed package's own kernels stay out of this empty cache,
    # so that the groups really compile here.
    env = {**os.environ, "PIXELPATH_CACHE_DIR": str(tmp_path), "PIXELPATH_PRECOMPILED": "0"}
    env.pop("NUMBA_CACHE_DIR", None)
    methods = sorted(_warm.METHOD_GROUPS)
    warm = (
        "from pixelpath import _precompiled, _warm; import json, sys; "
        "groups = _warm.groups_for(sys.argv[1:]); folder = _precompiled.markers(); "
        "print(json.dumps([_warm.cold_groups(groups, folder), "
        "sorted(_warm.compile_groups(groups, folder, 2)), _warm.cold_groups(groups, folder)]))"
    )
    result = subprocess.run([sys.executable, "-c", warm, *methods], env=env, check=True,
                            capture_output=True, text=True)
    cold_before, compiled, cold_after = json.loads(result.stdout)
    groups = list(_warm.groups_for(methods))
    assert cold_before == groups and compiled == sorted(groups) and cold_after == []
    result = subprocess.run([sys.executable, "-c", _RENDER_EVERY_METHOD, DUCK, *methods],
                            env=env,
                            check=True, capture_output=True, text=True)
    assert json.loads(result.stdout) == []


@needs_jit
@pytest.mark.slow
def test_with_the_kernels_compiled_at_build_time_a_first_render_compiles_nothing(tmp_path):
    from pixelpath._precompiled import MANIFEST, SHIPPED

    if not (SHIPPED / MANIFEST).is_file():
        pytest.skip("no kernels compiled at build time here (an editable install, or "
                    "PIXELPATH_PRECOMPILED=0 when it was built)")
    env = {**os.environ, "PIXELPATH_CACHE_DIR": str(tmp_path)}
    env.pop("NUMBA_CACHE_DIR", None)
    env.pop("PIXELPATH_PRECOMPILED", None)
    methods = sorted(_warm.METHOD_GROUPS)
    result = subprocess.run([sys.executable, "-c", _RENDER_EVERY_METHOD, DUCK, *methods],
                            env=env,
                            check=True, capture_output=True, text=True)
    assert json.loads(result.stdout) == []
    assert (tmp_path / "numba" / "precompiled").is_dir()  # copied from the package, not compiled


@needs_jit
@pytest.mark.slow
def test_a_plain_scene_is_rendered_without_compiling_the_lookups(tmp_path):
    # A cold z-buffer render of a scene without textures, vertex colours or alpha tests: its
    # groups compiled into an empty cache (in two processes), the render compiles nothing
    # more, and no process compiled the colour lookups, the alpha test or the texture
    # sampling, which the passes given no cutouts or colour tables prune.
    env = {**os.environ, "PIXELPATH_CACHE_DIR": str(tmp_path), "PIXELPATH_PRECOMPILED": "0"}
    env.pop("NUMBA_CACHE_DIR", None)
    groups = _warm.groups_for(["zbuffer"], ["phong"], lookups=False)
    assert groups == ("front", "depth-test", "rows", "back")
    warm = ("from pixelpath import _precompiled, _warm; import sys; "
            "_warm.compile_groups(sys.argv[1:], _precompiled.markers(), 2)")
    subprocess.run([sys.executable, "-c", warm, *groups], env=env, check=True)
    render = _COUNT_COMPILES + textwrap.dedent(
        """
        import pixelpath as pp
        from pixelpath.scene import bundled_scenes, load_scene
        pp.render(load_scene(bundled_scenes()["showcase"]), "zbuffer", "phong")
        print(json.dumps(compiled))
        """
    )
    result = subprocess.run([sys.executable, "-c", render], env=env, check=True,
                            capture_output=True, text=True)
    assert json.loads(result.stdout) == []
    cached = [path.name for path in tmp_path.rglob("*.nbi")]
    assert any("_shade_row" in name for name in cached)  # where Numba keeps its index files
    for kernel in ("_row_surface_colors", "_draw_masked", "_texture_kernels.sample-"):
        assert not [name for name in cached if kernel in name]


_COMPILE_GROUPS = textwrap.dedent(
    """
    import json, sys
    from numba.core import event
    from pixelpath import _warm
    compiled = []

    class Count(event.Listener):  # pixelpath's kernels, each when its compile ends
        def on_start(self, e):
            pass

        def on_end(self, e):
            function = e.data["dispatcher"].py_func
            if function.__module__.startswith("pixelpath."):
                compiled.append([f"{function.__module__}.{function.__qualname__}",
                                 str(e.data["args"])])

    event.register("numba:compile", Count())
    _warm._compile_here(sys.argv[1:])
    print(json.dumps(compiled))
    """
)


@needs_jit
@pytest.mark.slow
def test_a_fed_group_loads_what_its_feeder_compiled_and_compiles_the_rest_once(tmp_path):
    # Each in a process of its own into an empty cache (one per feeder), the feeder first (each
    # group it feeds after the group that one follows, as a cold start runs it): a fed group
    # must not compile the feeder's kernel again, which it would if either warm-up passed
    # other types, nor any kernel twice for the same types. (Small helpers both call, compiled
    # by each before the other is done, may compile in both.)
    for feeder, feds in _warm.FEEDS.items():
        cache = tmp_path / feeder
        env = {**os.environ, "PIXELPATH_CACHE_DIR": str(cache), "PIXELPATH_PRECOMPILED": "0"}
        env.pop("NUMBA_CACHE_DIR", None)
        by_group = {}
        for group, groups in ((feeder, [feeder]),
                              *((fed, [_warm.FOLLOWS.get(fed, fed), fed]) for fed in feds)):
            result = subprocess.run([sys.executable, "-c", _COMPILE_GROUPS, *dict.fromkeys(groups)],
                                    env=env, check=True, capture_output=True, text=True)
            by_group[group] = json.loads(result.stdout)
        feeders_kernel, _ = by_group[feeder][-1]  # the warm-up's own call: the last to end
        for fed in feds:
            assert feeders_kernel not in [name for name, _ in by_group[fed]]
            assert len(by_group[fed]) == len({tuple(kernel) for kernel in by_group[fed]})
