"""Whether a command's kernels are compiled yet, and the notice a cold first run prints.

Numba compiles a kernel the first time a process needs it and later processes load it from the
disk cache (:mod:`pixelpath._cache`), so the first run of a command can take many seconds of
silence. To say so beforehand without compiling or inspecting Numba's cache files, the cache
folder holds two small JSON files:

* ``warm-<stamp>.json`` lists the *needs* (a command and the options that choose its kernels,
  e.g. ``render:zbuffer:phong``) that finished since the kernel sources last changed. The stamp
  hashes every kernel module with the pixelpath modules it imports (the stamps the cache itself
  uses), so editing or upgrading the kernels makes every command cold again. A need listed
  there is warm; ``warmup`` compiles every kernel, so after it every need is warm.
* ``first-runs.json`` keeps the last measured duration of each command's cold run, so the
  notice can say how long the next one will take. Before any was measured, the estimates in
  :data:`ESTIMATED_SECONDS` stand.

The answer is a guess on the safe side: it can call a run cold when only some kernels compile
(after editing one kernel file), and warm when a render needs a kernel variant the last runs
did not use; it never delays a command.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import TextIO

from pixelpath import _KERNEL_MODULES

#: Cold-run seconds assumed before one was measured on this machine. demo and render: medians of
#: ``benchmarks/bench_coldstart.py`` on the shared 2-core development machine (28 and 26 s),
#: rounded up; phong, color and clip compile less and were not measured: rough guesses. The
#: first cold run measured on a machine replaces them there.
ESTIMATED_SECONDS = {"demo": 30.0, "render": 30.0, "phong": 5.0, "color": 10.0, "clip": 10.0}
#: The estimate for ``warmup``, which compiles every kernel: 55 s measured at rest (README).
WARMUP_ESTIMATE = 60.0
#: The options of a command that decide which kernels it compiles.
KERNEL_OPTIONS = ("method", "shading")

NOTICE = "compiling kernels for the first run, about {seconds:.0f} s; later runs are instant"


def kernels_stamp() -> str:
    """Return a hash of every kernel module's source stamp (the cache's own freshness key).

    Examples
    --------
    >>> from pixelpath._firstrun import kernels_stamp
    >>> len(kernels_stamp())
    64
    """
    from pixelpath._cache import _module_file, source_stamp

    digest = hashlib.sha256()
    for module in _KERNEL_MODULES:
        digest.update(source_stamp(_module_file(module)).encode())
    return digest.hexdigest()


def _read_json(path: Path) -> dict:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):  # missing, unreadable or half-written by another process
        return {}
    return data if isinstance(data, dict) else {}


def _write_json(path: Path, data: dict) -> None:
    """Write ``data`` atomically; a cache folder that refuses it only costs a later notice."""
    try:
        with tempfile.NamedTemporaryFile(
            "w", dir=path.parent, prefix=path.name, suffix=".tmp", delete=False, encoding="utf-8"
        ) as handle:
            json.dump(data, handle, indent=1, sort_keys=True)
        os.replace(handle.name, path)
    except OSError:
        return


@dataclass(frozen=True)
class FirstRun:
    """What one command needs compiled, checked against the markers in the cache ``folder``.

    ``folder`` None means there is no disk cache (every process compiles: always cold).

    Examples
    --------
    >>> from pixelpath._firstrun import FirstRun
    >>> run = FirstRun("demo", None, stamp="0" * 64)  # no disk cache: every run compiles
    >>> run.cold, run.command
    (True, 'demo')
    """

    need: str
    folder: Path | None
    stamp: str

    @property
    def command(self) -> str:
        """The command name: the need up to its first colon."""
        return self.need.split(":")[0]

    def _marker(self) -> Path | None:
        return None if self.folder is None else self.folder / f"warm-{self.stamp[:20]}.json"

    @property
    def cold(self) -> bool:
        """True unless this need (or ``warmup``) finished since the kernel sources changed."""
        marker = self._marker()
        if marker is None:
            return True
        needs = _read_json(marker).get("needs", [])
        return self.need not in needs and "warmup" not in needs

    def expected_seconds(self) -> float:
        """Return the last measured cold-run time of this command, else the estimate."""
        measured = {} if self.folder is None else _read_json(self.folder / "first-runs.json")
        seconds = measured.get(self.command)
        if isinstance(seconds, (int, float)) and seconds > 0:
            return float(seconds)
        return ESTIMATED_SECONDS.get(self.command, WARMUP_ESTIMATE)

    def notice(self) -> str:
        """Return the line printed before a cold run."""
        return NOTICE.format(seconds=max(1.0, self.expected_seconds()))

    def record(self, seconds: float) -> None:
        """Mark this need warm; if it was cold, keep ``seconds`` as the command's cold time."""
        marker = self._marker()
        if marker is None or not self.cold:
            return
        runs_file = marker.parent / "first-runs.json"
        _write_json(runs_file, {**_read_json(runs_file), self.command: round(seconds, 1)})
        needs = _read_json(marker).get("needs", [])
        _write_json(marker, {"needs": sorted({*needs, self.need})})


def for_command(command: str, options: dict) -> FirstRun | None:
    """Return the :class:`FirstRun` of a CLI command, or None when it compiles no kernels.

    Parameters
    ----------
    command : str
        The subcommand's name.
    options : dict
        Its parsed options; :data:`KERNEL_OPTIONS` among them refine the need.
    """
    if command not in (*ESTIMATED_SECONDS, "warmup"):
        return None
    from pixelpath._cache import writable_cache_dir

    need = ":".join([command, *(str(options[key]) for key in KERNEL_OPTIONS if key in options)])
    return FirstRun(need, writable_cache_dir(), kernels_stamp())


def announce(first_run: FirstRun | None, stream: TextIO | None = None) -> bool:
    """Print the first-run notice on ``stream`` (standard error) if it is a terminal and cold.

    Returns whether it printed: never when piped or redirected, so logs and CI stay clean.

    Examples
    --------
    >>> import io
    >>> from pixelpath._firstrun import FirstRun, announce
    >>> cold = FirstRun("render:zbuffer:phong", None, stamp="0" * 64)
    >>> announce(cold, io.StringIO())  # not a terminal
    False
    """
    stream = sys.stderr if stream is None else stream
    isatty = getattr(stream, "isatty", None)
    if first_run is None or not (isatty is not None and isatty()) or not first_run.cold:
        return False
    print(first_run.notice(), file=stream, flush=True)
    return True
