"""pixelpath in the environments users run it in: cache settings, one thread, no JIT, a read-only
home. Each variation runs in a fresh interpreter, since Numba reads its environment variables
when it is first imported; nothing pixelpath does may leak into the user's own Numba code."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

CACHE_VARIABLES = {"PIXELPATH_CACHE_DIR": None, "NUMBA_CACHE_DIR": None}
JIT_ON = {"NUMBA_DISABLE_JIT": None}  # the disk cache only exists for compiled kernels


def run_python(code: str, cwd: Path | None = None, **changes: str | None) -> dict:
    """Run ``code`` in a fresh interpreter with this environment changed (None unsets).

    ``code`` prints one JSON object as its last line, which is returned with the child's stderr
    under ``"stderr"``. A crash fails the test with the child's traceback.
    """
    env = dict(os.environ)
    for name, value in changes.items():
        if value is None:
            env.pop(name, None)
        else:
            env[name] = value
    result = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        timeout=300,
    )
    assert result.returncode == 0, result.stderr
    return {**json.loads(result.stdout.splitlines()[-1]), "stderr": result.stderr}


def one_kernel(before: str = "") -> str:
    """A script that runs ``before``, then the smallest kernel, and reports on its disk cache.

    The kernel compiles in about half a second when its cache is cold.
    """
    return f"""
import json
from pathlib import Path
import numpy as np
import platformdirs
{before}
from pixelpath.clip import _kernels
status = _kernels.check_subject(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]))
stats = _kernels.check_subject.stats
folder = Path(stats.cache_path or "")  # None when there is no disk cache
print(json.dumps({{
    "status": int(status),
    "cache_path": stats.cache_path,
    "hits": sum(stats.cache_hits.values()),
    "index_files": sorted(p.name for p in folder.glob("*.nbi")) if stats.cache_path else [],
    "platform_cache": platformdirs.user_cache_dir("pixelpath"),
}}))
"""


@pytest.mark.parametrize(
    ("settings", "expected"),
    [
        ({"PIXELPATH_CACHE_DIR": "pp"}, "pp/numba"),
        ({"NUMBA_CACHE_DIR": "nb"}, "nb/pixelpath"),
        ({"PIXELPATH_CACHE_DIR": "pp", "NUMBA_CACHE_DIR": "nb"}, "pp/numba"),
    ],
)
def test_kernels_cache_in_the_folder_the_variables_choose(tmp_path, settings, expected):
    env = CACHE_VARIABLES | JIT_ON | {name: str(tmp_path / f) for name, f in settings.items()}
    result = run_python(one_kernel(), **env)
    assert result["status"] == 0
    assert Path(result["cache_path"]).parent == tmp_path / expected
    assert any(name.startswith("_kernels.check_subject-") for name in result["index_files"])
    assert "Warning" not in result["stderr"]


def test_a_second_process_loads_the_kernels_from_the_cache(tmp_path):
    env = CACHE_VARIABLES | JIT_ON | {"PIXELPATH_CACHE_DIR": str(tmp_path)}
    first = run_python(one_kernel(), **env)
    again = run_python(one_kernel(), **env)
    assert (first["hits"], again["hits"]) == (0, 1)
    assert first["cache_path"] == again["cache_path"]


def test_by_default_kernels_cache_in_the_platforms_user_cache_folder(tmp_path):
    env = CACHE_VARIABLES | JIT_ON | {"HOME": str(tmp_path), "XDG_CACHE_HOME": None}
    result = run_python(one_kernel(), **env)
    assert Path(result["cache_path"]).parent == Path(result["platform_cache"]) / "numba"
    assert Path(result["platform_cache"]).is_relative_to(tmp_path)
    assert result["index_files"] and "Warning" not in result["stderr"]


def unwritable_home(tmp_path: Path, how: str) -> Path:
    """Return a home directory in which nothing can be created, made one of two ways."""
    if how == "read-only":
        home = tmp_path / "home"
        home.mkdir()
        home.chmod(stat.S_IRUSR | stat.S_IXUSR)
        try:
            (home / "probe").mkdir()
        except OSError:
            return home
        pytest.skip("this user (root?) writes through read-only permissions")
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("a file where the home directory's parent should be")
    return blocker / "home"


@pytest.mark.parametrize("how", ["read-only", "under a file"])
def test_unwritable_home_falls_back_to_a_private_temporary_folder_with_one_warning(tmp_path, how):
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    home = unwritable_home(tmp_path, how)
    env = CACHE_VARIABLES | JIT_ON
    env |= {"HOME": str(home), "XDG_CACHE_HOME": None, "TMPDIR": str(temporary)}
    # Kernels of two modules load: the folder is chosen, and the warning given, once.
    result = run_python(one_kernel(before="import pixelpath.color._kernels"), **env)
    folder = Path(result["cache_path"]).parent
    assert folder.name == "numba" and folder.parent.parent == temporary
    if hasattr(os, "getuid"):
        assert folder.parent.name == f"pixelpath-{os.getuid()}"
        assert stat.S_IMODE(folder.parent.stat().st_mode) == 0o700
    assert result["index_files"], "the fallback folder holds the compiled kernel"
    assert result["stderr"].count("CacheWarning") == 1, result["stderr"]
    assert str(folder) in result["stderr"] and "Traceback" not in result["stderr"]


def test_without_any_writable_folder_kernels_compile_without_a_disk_cache(tmp_path):
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("nothing can be created under a file")
    env = CACHE_VARIABLES | JIT_ON | {"PIXELPATH_CACHE_DIR": str(blocker / "cache")}
    # tempfile.tempdir is how a program picks its temporary folder; this one cannot be made.
    no_temporary = f"import tempfile; tempfile.tempdir = {str(blocker / 'tmp')!r}"
    result = run_python(one_kernel(before=no_temporary), **env)
    assert result["status"] == 0
    assert result["cache_path"] is None and result["hits"] == 0
    assert result["stderr"].count("CacheWarning") == 1, result["stderr"]
    assert "compile again in every new process" in result["stderr"]
    assert "Traceback" not in result["stderr"]


USER_MODULE = """
import numba


@numba.njit(cache=True)
def add(a, b):
    return a + b
"""


def user_script(with_pixelpath: bool) -> str:
    """A user's script: maybe pixelpath runs a kernel, then the user's cached function runs."""
    pixelpath_part = "import pixelpath\n" + one_kernel() if with_pixelpath else ""
    return f"""
import json, os
before = dict(os.environ)
{pixelpath_part}
import numba
import user_kernels
user_kernels.add(1, 2)
print(json.dumps({{
    "environ_unchanged": dict(os.environ) == before,
    "numba_cache_dir": numba.config.CACHE_DIR,
    "user_cache": user_kernels.add.stats.cache_path,
    "kernel_cache": stats.cache_path if {with_pixelpath} else None,
}}))
"""


@pytest.mark.parametrize("numba_cache_dir", [None, "numba-cache"])
def test_pixelpath_changes_nothing_for_the_users_own_numba_code(tmp_path, numba_cache_dir):
    (tmp_path / "user_kernels.py").write_text(USER_MODULE)
    env = CACHE_VARIABLES | JIT_ON
    if numba_cache_dir:
        env["NUMBA_CACHE_DIR"] = str(tmp_path / numba_cache_dir)
    alone = run_python(user_script(with_pixelpath=False), cwd=tmp_path, **env)
    together = run_python(user_script(with_pixelpath=True), cwd=tmp_path, **env)
    assert together["environ_unchanged"]
    assert together["numba_cache_dir"] == alone["numba_cache_dir"]
    assert together["user_cache"] == alone["user_cache"] != together["kernel_cache"]
    assert list(Path(together["user_cache"]).glob("user_kernels.add-*.nbi"))
    if numba_cache_dir:
        assert Path(together["kernel_cache"]).parent == tmp_path / numba_cache_dir / "pixelpath"


def test_cache_doctests_pass_whatever_cache_variables_are_set(tmp_path):
    code = """
        import doctest, json
        import pixelpath._cache, pixelpath._jit
        results = [doctest.testmod(m) for m in (pixelpath._cache, pixelpath._jit)]
        print(json.dumps({"failed": sum(r.failed for r in results),
                          "attempted": sum(r.attempted for r in results)}))
    """
    for variable in ("NUMBA_CACHE_DIR", "PIXELPATH_CACHE_DIR"):
        result = run_python(code, **{variable: str(tmp_path / variable)})
        assert result["failed"] == 0 and result["attempted"] > 0, result["stderr"]


# The parallel kernels (more than one chunk of work each) write their results to OUT.
KERNEL_RESULTS = """
    import json
    import numpy as np
    import numba
    from pixelpath import clip, color
    image = np.random.default_rng(7).random((100, 120, 3))
    hsv = color.rgb_to_hsv(image)
    back = color.hsl_to_rgb(color.rgb_to_hsl(image.astype(np.float32)))
    rings = [np.array([[0.0, 0.0], [9.0, 1.0], [4.0, 8.0]]) + k for k in range(200)]
    clipped = clip.clip_polygons(rings, clip.Rect(2, 2, 60, 60))
    np.savez(OUT, hsv=hsv, back=back, clipped=np.concatenate(clipped))
    print(json.dumps({"threads": numba.config.NUMBA_NUM_THREADS,
                      "jit": not numba.config.DISABLE_JIT}))
"""


@pytest.fixture(scope="module")
def baseline_results(tmp_path_factory) -> Path:
    """The kernels' results computed in this test run's own environment."""
    out = tmp_path_factory.mktemp("baseline") / "results.npz"
    run_python(KERNEL_RESULTS.replace("OUT", repr(str(out))))
    return out


@pytest.mark.parametrize("variable", ["NUMBA_NUM_THREADS", "NUMBA_DISABLE_JIT"])
def test_kernels_give_identical_results_with_one_thread_or_without_jit(
    tmp_path, variable, baseline_results
):
    out = tmp_path / "results.npz"
    varied = run_python(KERNEL_RESULTS.replace("OUT", repr(str(out))), **{variable: "1"})
    if variable == "NUMBA_NUM_THREADS":
        assert varied["threads"] == 1
    else:
        assert not varied["jit"]
    with np.load(baseline_results) as expected, np.load(out) as got:
        for name in expected.files:
            np.testing.assert_array_equal(got[name], expected[name], err_msg=name)


VECTORIZED = """
import json, platform
from numba.core import config
from pixelpath._jit import njit

def scale(a, out):
    out[0], out[1], out[2], out[3] = a[0] * 3.0, a[1] * 3.0, a[2] * 3.0, a[3] * 3.0

before = config.SLP_VECTORIZE
lanes = njit(simd=True, cache=False)(scale)
plain = njit(cache=False)(scale)
import numpy as np
out = np.empty(4)
lanes(np.arange(4.0), out)
plain(np.arange(4.0), out)
packed = [f.inspect_asm(f.signatures[0]).count("mulpd") > 0 for f in (lanes, plain)]
print(json.dumps({"before": before, "after": config.SLP_VECTORIZE, "out": out.tolist(),
                  "packed": packed, "x86": platform.machine().lower() in ("x86_64", "amd64")}))
"""


def test_vectorized_kernels_use_packed_arithmetic_and_leave_numbas_setting_alone():
    result = run_python(VECTORIZED, **CACHE_VARIABLES, **JIT_ON)
    assert result["before"] == result["after"]  # on only while that kernel compiled
    assert result["out"] == [0.0, 3.0, 6.0, 9.0]
    if result["x86"]:  # the instruction names are x86's
        assert result["packed"] == [True, False]


UNCOUNTED = """
import json
import numpy as np
from numba.core.errors import TypingError
from pixelpath._jit import njit

@njit(cache=False)
def checked(values, k):
    if values[k] < 0.0:
        raise ValueError("negative")
    return values[k]

@njit(inline="always", cache=False)
def pick(values, k):
    return checked(values, k) if values.shape[0] > 0 else 0.0

def total(values):
    s = 0.0
    for k in range(values.shape[0]):
        s += pick(values, k)  # counted: the inlined helper's array is a new reference, per k
    return s

def allocates(n):
    return np.zeros(n)[0]

counted = njit(cache=False)(total)
uncounted = njit(refcount=False, cache=False)(total)
values = np.arange(5.0)
sums = [counted(values), uncounted(values)]
updates = [f.inspect_asm(f.signatures[0]).count("NRT_incref") for f in (counted, uncounted)]
try:
    njit(refcount=False, cache=False)(allocates)(3)
    refused = False
except TypingError:
    refused = True
print(json.dumps({"sums": sums, "updates": updates, "refused": refused}))
"""


def test_uncounted_kernels_update_no_reference_counts_and_may_not_allocate():
    result = run_python(UNCOUNTED, **CACHE_VARIABLES, **JIT_ON)
    assert result["sums"] == [10.0, 10.0]
    counted, uncounted = result["updates"]
    assert counted > 0 and uncounted == 0
    assert result["refused"]


INLINED = """
import json, re
import numpy as np
from pixelpath._jit import njit
from pixelpath.raytrace._hit_kernels import reflect_direction, triangle_t

def mirrored(directions, out):
    for k in range(directions.shape[0]):
        out[k] = reflect_direction(directions[k, 0], directions[k, 1], directions[k, 2],
                                   0.0, 0.0, 1.0)

def twice(x):
    return 2.0 * x

kernel = njit(refcount=False, cache=False)(mirrored)
directions = np.array([[1.0, 0.0, -1.0], [0.0, 2.0, -3.0]])
out = np.empty((2, 3))
kernel(directions, out)
ir = kernel.inspect_llvm(kernel.signatures[0])
forced = njit(refcount=False, forceinline=True, cache=False)(twice)
forced(1.0)
forced_ir = forced.inspect_llvm(forced.signatures[0])
attributes = re.findall(r"attributes #\\d+ = [{]([^}]*)[}]", forced_ir)
print(json.dumps({
    "out": out.tolist(),
    "calls": len(re.findall(r"call [^\\n]*reflect_direction", ir)),
    "plain": reflect_direction.targetoptions.get("inline", "never"),
    "forced": triangle_t.targetoptions.get("forceinline", False),
    "always_inline": any("alwaysinline" in group for group in attributes),
}))
"""


def test_plain_helpers_are_inlined_by_llvm_into_their_callers():
    # pixelpath._jit's rule: a small helper compiled as a function of its own costs no call in
    # the kernels that use it, as LLVM inlines it; were that to stop (another Numba or LLVM),
    # the ray tracer's plain helpers would become calls per ray. The helpers that LLVM would
    # leave calls in the traversal loops (the triangle test) are marked for LLVM to inline
    # wherever they are called: Numba's forceinline must reach LLVM as alwaysinline.
    result = run_python(INLINED, **JIT_ON)
    assert result["out"] == [[1.0, 0.0, 1.0], [0.0, 2.0, 3.0]]
    assert result["plain"] == "never"  # compiled on its own, not inlined by Numba
    assert result["forced"] is True
    assert result["always_inline"] is True
    assert result["calls"] == 0


KERNEL_ONLY = """
import json
import numpy as np
from pixelpath._jit import njit
from pixelpath.scene._texture_kernels import wrapped

def add_one(x):
    return x + 1.0

helper = njit(from_python=False, cache=False)(add_one)

def through_helper(values):
    return helper(values[0])

kernel = njit(cache=False)(through_helper)
result = kernel(np.array([2.0]))
messages = []
for function, arguments in ((helper, (2.0,)), (wrapped, (5, 4, 0))):
    try:
        function(*arguments)
    except TypeError as error:
        messages.append(str(error))

def wrappers(dispatcher):
    compiled = dispatcher.overloads[dispatcher.signatures[0]]
    library, names = compiled.library, compiled.fndesc
    return [library.get_pointer_to_function(name) != 0
            for name in (names.llvm_cpython_wrapper_name, names.llvm_cfunc_wrapper_name)]

print(json.dumps({"result": result, "messages": messages, "kernel": wrappers(kernel),
                  "helper": wrappers(helper)}))
"""


def test_helpers_for_kernels_only_have_no_python_wrapper_and_refuse_python_calls():
    # A helper compiled without the CPython wrapper (njit(from_python=False)) would crash the
    # interpreter if Python called it (a jump to address 0): it raises a TypeError instead.
    # No kernel gets Numba's C-callable wrapper, and only Python's entry points the CPython one.
    result = run_python(KERNEL_ONLY, **JIT_ON)
    assert result["result"] == 3.0
    assert len(result["messages"]) == 2
    assert "add_one is compiled for other kernels to call" in result["messages"][0]
    assert "_texture_kernels.wrapped is compiled for other kernels" in result["messages"][1]
    assert result["kernel"] == [True, False]
    assert result["helper"] == [False, False]


LITERALS = """
import json
from pixelpath._jit import njit

def step(x, k, up):
    return x + k if up else x - k

helper = njit(from_python=False, cache=False)(step)

def three_calls(x, k):
    return helper(x, 0, True) + helper(x, k, x > 0.0) + helper(x, -1, False)

kernel = njit(cache=False)(three_calls)
print(json.dumps({"result": kernel(2.0, 3), "signatures": [str(s) for s in helper.signatures]}))
"""


def test_a_helper_called_with_literals_and_variables_is_compiled_once():
    # Numba types a constant written at a call as a literal, a type of its own: the helper
    # would be compiled three times here; pixelpath's kernels are typed for the base types.
    result = run_python(LITERALS, **JIT_ON)
    assert result["result"] == 2.0 + 5.0 + 3.0
    assert result["signatures"] == ["(float64, int64, bool)"]
