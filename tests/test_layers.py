"""The package's import structure: one-way layers, no module-level cycle.

The imports are read from the sources (``ast``), so that the structure is checked without
importing anything. Module-level imports (those that run when a module is imported) and imports
inside functions (run at first call) are collected apart: a module-level import may only go
down :data:`LAYERS` or sideways, and the only imports allowed to go up, inside functions, are
the drawing conveniences (``.figure()``, ``_repr_png_``, ``save_animation``) that import
:mod:`pixelpath.figures`, which draws the traces and reports the lower layers return as data.
Imports under ``if TYPE_CHECKING:`` are annotations only and are left out; so are modules
imported by name at run time (the renderer's method registry, the warm-up groups).
"""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path

import pytest

import pixelpath

PACKAGE = Path(pixelpath.__file__).resolve().parent

# Bottom to top. A module belongs to the layer of the longest prefix naming it.
LAYERS: tuple[tuple[str, ...], ...] = (
    # Checks, threads, memory, and the kernel cache: _precompiled calls _cache and _warm, and
    # _jit (which every kernel imports) calls _precompiled.
    ("pixelpath._validate", "pixelpath._threads", "pixelpath._memory", "pixelpath._cache",
     "pixelpath._warm"),
    ("pixelpath._precompiled",),
    ("pixelpath._jit",),
    # Data and the algorithms on it: scenes, images, reports, the render contract, colour,
    # clipping and lighting (each with its kernels).
    (
        "pixelpath.scene",
        "pixelpath.io",
        "pixelpath.image",
        "pixelpath.report",
        "pixelpath.contract",
        "pixelpath.color",
        "pixelpath.clip",
        "pixelpath.lighting",
    ),
    # The rasterizer's stages, shared by the hidden-surface methods.
    ("pixelpath.raster",),
    # The rendering methods.
    ("pixelpath.hsr", "pixelpath.raytrace"),
    # render(): validates a call and runs a method.
    ("pixelpath.renderer",),
    # Pictures of traces, reports and renders.
    ("pixelpath.figures",),
    # What users run: many frames, exercises, the playground, the command line.
    (
        "pixelpath.frames",
        "pixelpath.exercises",
        "pixelpath.web",
        "pixelpath.cli",
        "pixelpath.__main__",
        "pixelpath",
    ),
)

# The one layer that lower modules may import upwards, inside the functions that draw.
DRAWING = "pixelpath.figures"
METHODS = ("pixelpath.hsr", "pixelpath.raytrace")
CACHE = ("pixelpath._cache", "pixelpath._precompiled", "pixelpath._warm")


def _name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def _module(name: str) -> str:
    """The package module that importing ``name`` (a module, or a name in one) loads."""
    while name not in MODULES:
        name = name.rpartition(".")[0]
    return name


def _is_type_checking(node: ast.AST) -> bool:
    return isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)


@cache
def imports(module: str) -> tuple[frozenset[str], frozenset[str]]:
    """Return the package modules ``module`` imports (module level, inside functions)."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    top: set[str] = set()
    inner: set[str] = set()

    def visit(node: ast.AST, in_function: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if _is_type_checking(child):
                continue
            found = inner if in_function else top
            if isinstance(child, ast.Import):
                found.update(_module(a.name) for a in child.names if a.name.startswith("pixelpath"))
            elif isinstance(child, ast.ImportFrom):
                base = child.module or ""
                if child.level:
                    parts = package.split(".")[: len(package.split(".")) - child.level + 1]
                    base = ".".join([*parts, base] if base else parts)
                if base == "pixelpath" or base.startswith("pixelpath."):
                    for alias in child.names:  # ``from pixelpath.hsr import pipeline``: a module
                        found.add(_module(f"{base}.{alias.name}"))
            function = isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda)
            visit(child, in_function or function)

    visit(ast.parse(path.read_text(encoding="utf-8")), False)
    return frozenset(top - {module}), frozenset(inner - top - {module})


def layer(module: str) -> int:
    """Index in :data:`LAYERS` of the longest prefix naming ``module``."""
    best, level = "", None
    for index, prefixes in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and len(prefix) > len(best):
                best, level = prefix, index
    assert level is not None, f"{module} is in no layer; add it to LAYERS"
    return level


def _under(module: str, prefixes: tuple[str, ...] | str) -> bool:
    prefixes = (prefixes,) if isinstance(prefixes, str) else prefixes
    return any(module == p or module.startswith(p + ".") for p in prefixes)


def test_the_parser_sees_imports_at_both_levels():
    # Guards the tests below against passing because nothing was found.
    top, inner = imports("pixelpath.hsr.zbuffer")
    assert {"pixelpath.contract", "pixelpath.hsr.pipeline", "pixelpath.scene"} <= top
    assert "pixelpath.raster._kernels" in inner
    assert "pixelpath.hsr.hidden_line" in imports("pixelpath.renderer")[1]
    assert "pixelpath.contract" not in imports("pixelpath.raster.lines")[0]  # TYPE_CHECKING
    assert len(MODULES) > 100


@pytest.mark.parametrize("module", sorted(MODULES))
def test_every_module_has_a_layer(module):
    layer(module)


def test_module_level_imports_never_go_up():
    upward = [
        f"{module} -> {target}"
        for module in MODULES
        for target in imports(module)[0]
        if layer(target) > layer(module)
    ]
    assert upward == []


def test_only_drawing_is_imported_upwards_and_only_inside_functions():
    upward = [
        f"{module} -> {target}"
        for module in MODULES
        for target in imports(module)[1]
        if layer(target) > layer(module) and not _under(target, DRAWING)
    ]
    assert upward == []


def test_no_method_imports_the_renderer():
    offenders = [
        module
        for module in MODULES
        if _under(module, METHODS) and "pixelpath.renderer" in set().union(*imports(module))
    ]
    assert offenders == []


def _cycles(edges: dict[str, frozenset[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def strong(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for target in edges[node]:
            if target not in index:
                strong(target)
                low[node] = min(low[node], low[target])
            elif target in stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while not component or component[-1] != node:
                component.append(stack.pop())
            if len(component) > 1:
                found.append(sorted(component))

    for node in edges:
        if node not in index:
            strong(node)
    return found


def test_the_cycle_finder_finds_a_cycle():
    edges = {"a": frozenset({"b"}), "b": frozenset({"c"}), "c": frozenset({"a"}),
             "d": frozenset({"a"})}
    assert _cycles(edges) == [["a", "b", "c"]]


def test_no_module_level_cycle():
    assert _cycles({module: imports(module)[0] for module in MODULES}) == []


def test_the_kernel_cache_modules_form_no_circle():
    # _precompiled (build and seed) calls the folder and stamps of _cache and the groups and
    # markers of _warm; neither calls back, at any level.
    edges = {
        (module, target)
        for module in CACHE
        for target in set().union(*imports(module))
        if target in CACHE
    }
    assert edges == {
        ("pixelpath._precompiled", "pixelpath._cache"),
        ("pixelpath._precompiled", "pixelpath._warm"),
    }
