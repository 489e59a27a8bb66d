"""Sphinx configuration of the rollingdisk documentation.

Build (offline, warnings as errors)::

    python -m sphinx -W --keep-going -b html docs docs/_build/html
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
# Document the source tree next to this file, not whatever copy happens to be installed.
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(HERE))
os.environ.setdefault("MPLBACKEND", "Agg")

from _apigen import filename_map, write_api_index  # noqa: E402

import rollingdisk  # noqa: E402

write_api_index(HERE / "api" / "index.rst")

# -- project ---------------------------------------------------------------------------
project = "rollingdisk"
author = "the rollingdisk authors"
copyright = "the rollingdisk authors, MIT licence"
release = version = rollingdisk.__version__

# -- general ---------------------------------------------------------------------------
extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "sphinx.ext.mathjax",
    # MathJax shipped with the site (no request to a CDN): the pages render math offline
    "sphinx-mathjax-offline",
    "_rdext",  # the CLI reference and the derived equations, made from the library
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "gallery", "**.ipynb_checkpoints", "auto_examples/*.ipynb",
                    "auto_examples/*.py", "auto_examples/*.zip"]
templates_path = ["_templates"]
suppress_warnings: list[str] = []

# -- MyST: the Markdown pages (docs/*.md) -------------------------------------------------
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath", "amsmath"]

# -- autodoc / autosummary / numpydoc ------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = False
autosummary_filename_map = filename_map()  # Thresholds vs thresholds: one file on macOS
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types
autodoc_member_order = "bysource"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
numpydoc_xref_param_type = False

# -- sphinx-gallery: examples/plot_*.py, run at build time ----------------------------------
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": str(HERE / "auto_examples"),
    "filename_pattern": r"/plot_",
    "within_subsection_order": "_gallery.example_order",
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "remove_config_comments": True,
    "backreferences_dir": None,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "show_signature": False,
    "capture_repr": (),
}

# -- HTML ------------------------------------------------------------------------------
html_theme = "alabaster"
html_title = f"rollingdisk {release}"
html_static_path = ["_static"]
html_css_files = ["custom.css"]
html_theme_options = {
    "description": "A rigid disk of finite thickness on a horizontal plane",
    "fixed_sidebar": True,
    "page_width": "1240px",
    "sidebar_width": "220px",
}


def _constant_docstring(app, what, name, obj, options, lines):
    """A constant's documentation is the ``#:`` comment above it in its module.

    The reference lists constants under their public path (``rollingdisk.DEFAULT_H``), where
    autodoc finds no comment and would show the docstring of ``float`` or ``tuple``; this
    looks the comment up in the module that defines the name instead.
    """
    if what != "data":
        return
    from _apigen import _defining_module
    from sphinx.pycode import ModuleAnalyzer

    modname, _, attr = name.rpartition(".")
    package = sys.modules.get(modname)
    if package is None:
        return
    source = _defining_module(package, attr, getattr(package, attr, None)) or modname
    try:
        docs = ModuleAnalyzer.for_module(source).find_attr_docs()
    except Exception:  # no source to read: keep what autodoc found
        return
    comment = docs.get(("", attr))
    lines[:] = list(comment) if comment else [f"The constant ``{attr}`` (value below)."]


def setup(app):
    app.connect("autodoc-process-docstring", _constant_docstring)
