"""Where pixelpath's compiled kernels are cached, and against which sources.

Numba caches a ``cache=True`` function through a list of *locators*: the first that claims
the function's source file says where its cache lives and which stamp keeps it fresh. Setting
``NUMBA_CACHE_DIR`` (or ``numba.config.CACHE_DIR``) would move the cache of every Numba library
in the process and in every child process; instead each pixelpath kernel gets a cache of its own
(:class:`KernelCache`) whose only locator is :class:`KernelCacheLocator`, and nothing global
changes:

* **Folder.** :func:`cache_dir` — ``$PIXELPATH_CACHE_DIR/numba``, else
  ``$NUMBA_CACHE_DIR/pixelpath``, else the platform's per-user cache folder. When it cannot be
  written (a read-only home directory), a private folder in the temporary directory is used, and
  when that fails too the kernels compile without a disk cache; either way one
  :class:`CacheWarning` says so (:func:`writable_cache_dir`). The kernels compiled when
  pixelpath was built are copied into that folder by :mod:`pixelpath._precompiled`, which
  calls this module (and :mod:`pixelpath._warm`), never the other way round.
* **Freshness.** Numba stamps a cache with its own source file only, so a kernel that inlines a
  function from another file would keep stale code when that file changes. The stamp here
  (:func:`source_stamp`) hashes the kernel's file together with every pixelpath module it
  imports, transitively: editing ``lighting/_kernels.py`` recompiles the raster kernels that
  inline it, while the colour and clipping kernels, which do not import it, stay cached.
"""

from __future__ import annotations

import functools
import getpass
import hashlib
import inspect
import os
import pickle
import re
import stat
import tempfile
import warnings
from collections.abc import Mapping
from pathlib import Path

import platformdirs
from numba.core.caching import (
    CompileResultCacheImpl,
    FunctionCache,
    IndexDataCacheFile,
    _CacheLocator,
)

PACKAGE_DIR = Path(__file__).resolve().parent


class CacheWarning(UserWarning):
    """pixelpath's compile cache could not go where it was asked to."""


def cache_dir(environ: Mapping[str, str] | None = None) -> Path:
    """Return the folder where pixelpath asks for its compiled kernels to be cached.

    Parameters
    ----------
    environ : mapping, optional
        The environment variables to read (default ``os.environ``).

    Returns
    -------
    pathlib.Path
        ``$PIXELPATH_CACHE_DIR/numba`` when set, else ``$NUMBA_CACHE_DIR/pixelpath`` (beside the
        other Numba caches the user gathered there), else the per-user cache folder of the
        platform (``~/.cache/pixelpath/numba`` on Linux). If it cannot be written, the kernels
        go elsewhere: see :func:`writable_cache_dir`.

    Examples
    --------
    >>> from pixelpath._cache import cache_dir
    >>> cache_dir({"PIXELPATH_CACHE_DIR": "/data/pp"}).as_posix()
    '/data/pp/numba'
    >>> cache_dir({"NUMBA_CACHE_DIR": "/scratch/numba"}).as_posix()
    '/scratch/numba/pixelpath'
    >>> cache_dir({}).is_absolute()
    True
    """
    env = os.environ if environ is None else environ
    if env.get("PIXELPATH_CACHE_DIR"):
        folder = Path(env["PIXELPATH_CACHE_DIR"]) / "numba"
    elif env.get("NUMBA_CACHE_DIR"):
        folder = Path(env["NUMBA_CACHE_DIR"]) / "pixelpath"
    else:
        folder = Path(platformdirs.user_cache_dir("pixelpath")) / "numba"
    return folder.expanduser().absolute()


def _fallback_dir() -> Path:
    """Return a per-user folder in the temporary directory (``/tmp/pixelpath-<uid>/numba``)."""
    owner = os.getuid() if hasattr(os, "getuid") else getpass.getuser()
    return Path(tempfile.gettempdir()) / f"pixelpath-{owner}" / "numba"


def _unwritable_reason(folder: Path, private_parent: bool = False) -> str | None:
    """Create ``folder`` and write a file in it; return why that failed, or None.

    With ``private_parent``, the parent is created for this user alone (mode 0700) and refused
    if it is a link, belongs to someone else or is open to others: the cache holds pickled
    code, which nobody else may plant in a shared temporary directory.
    """
    try:
        if private_parent:
            folder.parent.mkdir(mode=0o700, exist_ok=True)
            info = folder.parent.lstat()
            foreign = hasattr(os, "getuid") and info.st_uid != os.getuid()
            if stat.S_ISLNK(info.st_mode) or foreign or info.st_mode & 0o077:
                return f"{folder.parent} is a link, another user's, or open to others"
        folder.mkdir(parents=True, exist_ok=True)
        tempfile.TemporaryFile(dir=folder).close()
    except OSError as exc:
        return exc.strerror or str(exc)
    return None


@functools.cache
def writable_cache_dir() -> Path | None:
    """Return the folder the kernels are cached in, or None when no folder can be written.

    :func:`cache_dir` when it can be written; else the private temporary folder
    ``pixelpath-<uid>/numba`` with one :class:`CacheWarning`; else None (the kernels compile
    in every new process) with one :class:`CacheWarning`. Decided once per process;
    :func:`pixelpath._precompiled.cache_root` copies the kernels compiled at build time into it.
    """
    preferred = cache_dir()
    reason = _unwritable_reason(preferred)
    if reason is None:
        return preferred
    advice = "set PIXELPATH_CACHE_DIR to a writable folder to choose where"
    try:
        fallback = _fallback_dir()
        fallback_reason = _unwritable_reason(fallback, private_parent=True)
    except OSError as exc:  # no usable temporary directory at all
        fallback, fallback_reason = None, exc.strerror or str(exc)
    if fallback_reason is None:
        message = f"caching them in {fallback} instead; {advice}"
    else:
        fallback = None
        message = (
            f"nor in a temporary folder ({fallback_reason}); kernels compile again in every "
            f"new process; {advice}"
        )
    warnings.warn(
        f"pixelpath cannot write compiled kernels to {preferred} ({reason}); {message}",
        CacheWarning,
        stacklevel=2,
    )
    return fallback


def _module_file(name: str) -> Path | None:
    """Return the source file of pixelpath module ``name``, or None for other modules."""
    package, *parts = name.split(".")
    if package != "pixelpath" or not parts:
        # The package's own __init__ (version, lazy names) holds nothing a kernel compiles.
        return None
    base = PACKAGE_DIR.joinpath(*parts)
    for candidate in (base.parent / f"{base.name}.py", base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


# ``import a.b, c`` and ``from .a import (b, c)`` at the start of a line, anywhere in a file
# (imports inside functions count). Parsing the files would be exact but costs about 10 ms a
# file, paid at every start-up; a line that only looks like an import (in a docstring) can only
# add a file to the stamp, never hide one.
_IMPORT_LINE = re.compile(
    r"^[ \t]*(?:from[ \t]+(?P<base>\.*[\w.]*)[ \t]+import[ \t]+(?P<names>\([^)]*\)|[^\n#;]*)"
    r"|import[ \t]+(?P<modules>[^\n#;]*))",
    re.MULTILINE,
)


def _names(text: str) -> list[str]:
    """Split ``a as b, c`` (or ``(a, c)`` over several lines) into ``["a", "c"]``."""
    parts = text.strip("()").replace("\n", " ").split(",")
    return [part.split()[0] for part in parts if part.split()]


@functools.cache
def _imported_files(path: Path) -> frozenset[Path]:
    """Return the pixelpath source files that the module at ``path`` imports, anywhere in it."""
    package = ("pixelpath", *path.relative_to(PACKAGE_DIR).parent.parts)
    found = set()
    for match in _IMPORT_LINE.finditer(path.read_text(encoding="utf-8")):
        if match["modules"] is not None:
            candidates = [_module_file(name) for name in _names(match["modules"])]
        else:
            dots = len(match["base"]) - len(match["base"].lstrip("."))
            module = match["base"][dots:]
            anchor = package[: len(package) - dots + 1] if dots else ()
            base = ".".join((*anchor, module) if module else anchor)
            # ``from pixelpath.color import _kernels`` names a module; ``from x import f``, x's.
            candidates = [
                _module_file(f"{base}.{name}") or _module_file(base)
                for name in _names(match["names"])
            ]
        found.update(candidate for candidate in candidates if candidate is not None)
    return frozenset(found)


@functools.cache
def source_stamp(path: Path) -> str:
    """Hash the kernel file ``path`` with every pixelpath module it imports, transitively.

    Examples
    --------
    >>> from pixelpath._cache import PACKAGE_DIR, source_stamp
    >>> len(source_stamp(PACKAGE_DIR / "color" / "_kernels.py"))
    64
    """
    seen = {path}
    pending = [path]
    while pending:
        for dependency in _imported_files(pending.pop()) - seen:
            seen.add(dependency)
            pending.append(dependency)
    digest = hashlib.sha256()
    for source in sorted(seen):
        digest.update(source.relative_to(PACKAGE_DIR).as_posix().encode() + b"\0")
        digest.update(hashlib.sha256(source.read_bytes()).digest())
    return digest.hexdigest()


def kernel_cache_folder(root: Path, source_folder: Path) -> Path:
    """Return the folder of ``root`` that caches the kernels of the files in ``source_folder``.

    Named as Numba names its own: the folder's name and a hash of its resolved path.

    Examples
    --------
    >>> from pathlib import Path
    >>> from pixelpath._cache import PACKAGE_DIR, kernel_cache_folder
    >>> kernel_cache_folder(Path("/cache"), PACKAGE_DIR / "raster").name.startswith("raster_")
    True
    """
    resolved = source_folder.resolve()
    return root / _CacheLocator.get_suitable_cache_subpath(str(resolved / "kernels.py"))


class KernelCacheLocator(_CacheLocator):
    """Numba cache locator for pixelpath's kernels: the folder and the stamp described above.

    Cache files go to a subfolder per source folder (named as Numba names its own, with a hash
    of the folder's path, so two installations never share files) of
    :func:`writable_cache_dir`; each kernel file keeps its own index, so one kernel's edit
    leaves the files that do not import it cached.
    """

    def __init__(self, py_func, py_file: str, root: Path) -> None:
        self._py_file = Path(py_file).resolve()
        self._lineno = py_func.__code__.co_firstlineno
        self._cache_path = str(kernel_cache_folder(root, self._py_file.parent))

    def get_cache_path(self) -> str:
        """Return the folder of this kernel's cache files."""
        return self._cache_path

    def get_source_stamp(self) -> str:
        """Return the hash of the kernel's file and of the pixelpath modules it imports."""
        return source_stamp(self._py_file)

    def get_disambiguator(self) -> str:
        """Tell apart functions of one file with the same name (as Numba does: the line)."""
        return str(self._lineno)

    @classmethod
    def from_function(cls, py_func, py_file: str) -> KernelCacheLocator:
        """Locate the cache of a kernel (:func:`enable_cache` passes pixelpath's files only)."""
        return cls(py_func, py_file, writable_cache_dir())


class _KernelCacheImpl(CompileResultCacheImpl):
    _locator_classes = [KernelCacheLocator]  # noqa: RUF012 (Numba's own name and type)


class _KernelIndexFile(IndexDataCacheFile):
    """Numba's index and data files, where an index that cannot be unpickled is only stale.

    An index's keys are signatures that name pixelpath's record types (``Cutouts``,
    ``TraceScene``, ...) by module. One written before such a type moved to another module
    names a class that is no longer there, and Numba unpickles the index before it compares
    the source stamp: the kernel would fail instead of compiling again and replacing it.
    """

    def _load_index(self) -> dict:
        try:
            return super()._load_index()
        except (AttributeError, ImportError, EOFError, pickle.UnpicklingError):
            return {}


class KernelCache(FunctionCache):
    """Numba's function cache, located by :class:`KernelCacheLocator` alone."""

    _impl_class = _KernelCacheImpl

    def __init__(self, py_func) -> None:
        super().__init__(py_func)
        self._cache_file = _KernelIndexFile(
            self._cache_path, self._impl.filename_base, self._impl.locator.get_source_stamp()
        )


def enable_cache(dispatcher) -> None:
    """Give the Numba dispatcher of a pixelpath kernel its disk cache, if a folder can be written.

    This is what ``numba.njit(cache=True)`` does (``Dispatcher.enable_caching``) with Numba's
    default locators; no setting of Numba's or of the environment changes. Functions defined
    outside pixelpath's files (in a doctest, at the prompt) stay uncached.
    """
    source = Path(inspect.getfile(dispatcher.py_func)).resolve()
    if source.is_relative_to(PACKAGE_DIR) and writable_cache_dir() is not None:
        dispatcher._cache = KernelCache(dispatcher.py_func)
