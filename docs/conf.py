"""Sphinx configuration of pixelpath's documentation (``make -C docs html``)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

from pixelpath_docs import write_module_index

import pixelpath

project = "pixelpath"
author = "the pixelpath developers"
copyright = "the pixelpath developers"
version = release = pixelpath.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_templates", "_ext", "Thumbs.db", ".DS_Store", "scenes",
                    "examples/README.rst", "auto_examples/*.ipynb",
                    "auto_examples/*.py", "auto_examples/*.zip"]
templates_path = ["_templates"]
suppress_warnings = ["myst.header"]  # the scene format page's own heading levels

# Markdown pages (MyST): anchors for the headings, so that pages link to sections.
myst_heading_anchors = 3
myst_enable_extensions = ["colon_fence", "deflist"]

# API reference: one page per public name, from its NumPy-style docstring.
autosummary_generate = True
autosummary_ignore_module_all = False
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"  # the docstrings' Parameters sections say the types
numpydoc_show_class_members = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()

# The gallery: every example is run at each build (a failing example fails the build), the
# pictures it writes are collected for its page and the user guide.
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "ignore_pattern": r"__init__\.py",
    "within_subsection_order": "FileNameSortKey",
    "image_scrapers": ("pixelpath_docs.written_pictures", "matplotlib"),
    "doc_module": ("pixelpath",),
    "backreferences_dir": "api/generated/backreferences",
    "reference_url": {"pixelpath": None},
    "remove_config_comments": True,
    "show_memory": False,
    "download_all_examples": False,
    "plot_gallery": os.environ.get("PIXELPATH_DOCS_GALLERY", "True"),
}

# Offline: no intersphinx, nothing fetched; the theme's links stay inside the site.
html_theme = "pydata_sphinx_theme"
html_title = "pixelpath"
html_static_path: list[str] = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 6,
    "secondary_sidebar_items": ["page-toc"],
}
html_sidebars = {"index": []}

write_module_index(HERE / "api" / "modules.rst")
