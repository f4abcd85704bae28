"""Helpers of the documentation build: the gallery's image scraper and the module index.

Kept out of ``conf.py`` so that Sphinx can pickle the configuration (it names these by their
qualified names).
"""

from __future__ import annotations

import importlib
import pkgutil
import shutil
from pathlib import Path

PICTURES = (".png", ".gif")


def written_pictures(block, block_vars, gallery_conf):
    """Collect the pictures an example wrote into its own folder, in the order written.

    The gallery runs each example in ``docs/examples``; an example saves its pictures there
    the way a user would (``img.save("ball.png")``, ``report.animate("levels.gif")``). This
    scraper moves each new file to the gallery's image folder, so that the example's page
    shows it and the user guide can point at it.
    """
    from sphinx_gallery.scrapers import figure_rst

    folder = Path(block_vars["src_file"]).parent
    written = sorted((p for p in folder.iterdir() if p.suffix in PICTURES),
                     key=lambda p: p.stat().st_mtime_ns)
    names = []
    for path in written:
        target = Path(next(block_vars["image_path_iterator"])).with_suffix(path.suffix)
        shutil.move(path, target)
        names.append(str(target))
    return figure_rst(names, gallery_conf["src_dir"])


def public_modules(package: str = "pixelpath") -> list[str]:
    """Return every public module of ``package`` (no part of its name starts with ``_``)."""
    root = importlib.import_module(package)
    names = [package]
    for info in pkgutil.walk_packages(root.__path__, prefix=package + "."):
        if not any(part.startswith("_") for part in info.name.split(".")):
            names.append(info.name)
    return sorted(names)


def write_module_index(path: Path) -> None:
    """Write the page of every public module with its docstring (regenerated each build)."""
    modules = public_modules()
    lines = [
        ".. This page is written by docs/_ext/pixelpath_docs.py at every build; do not edit.",
        "",
        "Modules",
        "=======",
        "",
        "Every public module of pixelpath with its own description, grouped by package. The",
        "functions and classes meant for users are documented on the other pages of this",
        "reference, under the names they are imported by.",
        "",
    ]
    for name in modules:
        lines += [name, "-" * len(name), "", f".. automodule:: {name}", "   :no-index:", ""]
    text = "\n".join(lines)
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
