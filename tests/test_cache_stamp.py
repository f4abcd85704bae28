"""The kernel cache's stamp covers every pixelpath module a kernel file imports."""

from __future__ import annotations

import ast

import pytest

from pixelpath._cache import PACKAGE_DIR, _imported_files, _module_file, source_stamp

SOURCES = sorted(PACKAGE_DIR.rglob("*.py"))


def imported_by_parsing(path):
    """The reference: the same question answered from the module's syntax tree."""
    package = ("pixelpath", *path.relative_to(PACKAGE_DIR).parent.parts)
    found = set()
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.Import):
            found.update(_module_file(alias.name) for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            anchor = package[: len(package) - node.level + 1] if node.level else ()
            base = ".".join((*anchor, node.module) if node.module else anchor)
            found.update(
                _module_file(f"{base}.{alias.name}") or _module_file(base) for alias in node.names
            )
    return found - {None}


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.relative_to(PACKAGE_DIR).as_posix())
def test_the_import_scan_finds_every_import_the_syntax_tree_has(path):
    assert imported_by_parsing(path) <= _imported_files(path)


def test_a_kernel_that_inlines_another_files_kernels_is_stamped_with_it():
    raster = PACKAGE_DIR / "raster" / "_kernels.py"
    lighting = PACKAGE_DIR / "lighting" / "_kernels.py"
    assert lighting in _imported_files(raster)
    colour = PACKAGE_DIR / "color" / "_kernels.py"
    assert lighting not in _imported_files(colour)
    assert source_stamp(raster) != source_stamp(colour)
