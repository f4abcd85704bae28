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


class Vanished:
    """A record type pickled into an index, then renamed (moved) before the index is read."""


def test_an_index_naming_a_type_no_longer_there_is_stale_not_an_error(tmp_path):
    import pickle

    from pixelpath._cache import _KernelIndexFile

    cache = _KernelIndexFile(str(tmp_path), "_kernels.kernel-1.py311", "now")
    cache.save((Vanished(), "int64"), "old code")
    index = tmp_path / "_kernels.kernel-1.py311.nbi"
    index.write_bytes(index.read_bytes().replace(b"Vanished", b"Vanishes"))
    with pytest.raises(AttributeError):
        with index.open("rb") as f:
            pickle.load(f)
            pickle.loads(f.read())
    assert cache.load(("anything", "int64")) is None
    cache.save(("anything", "int64"), "new code")  # replaces the index
    assert cache.load(("anything", "int64")) == "new code"
