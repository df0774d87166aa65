"""Serve MathJax from the built book instead of a CDN, so math typesets offline.

MathJax 3 comes from the PyPI wheel ``django-static-mathjax`` (pinned in requirements.txt), whose
package ``mathjax`` holds MathJax's ``es5`` build; only that tree is copied into ``_static``.
"""
from pathlib import Path

import mathjax


def _copy(app, exception):
    if exception is None and app.builder.format == "html":
        from sphinx.util.fileutil import copy_asset

        src = Path(mathjax.__file__).parent / "static" / "mathjax" / "es5"
        copy_asset(str(src), str(Path(app.outdir) / "_static" / "mathjax"))


def setup(app):
    app.config.mathjax_path = "mathjax/tex-mml-chtml.js"
    app.connect("build-finished", _copy)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
