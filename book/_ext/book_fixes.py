"""Two fixes to the HTML build, found by the browser check (tests/test_browser.py).

1. Serve MathJax from the built book instead of a CDN, so math typesets offline. MathJax 3 comes
   from the PyPI wheel ``django-static-mathjax`` (pinned in requirements.txt), whose package
   ``mathjax`` holds MathJax's ``es5`` build; only that tree is copied into ``_static``.
2. Drop repeated script entries: under Jupyter Book 1.0 sphinx-thebe registers its inline config
   (``const THEBE_JS_URL = ...``) twice, and the second copy throws "Identifier 'THEBE_JS_URL' has
   already been declared" in the browser console on every page.
"""
from pathlib import Path

import mathjax


def _copy_mathjax(app, exception):
    if exception is None and app.builder.format == "html":
        from sphinx.util.fileutil import copy_asset

        src = Path(mathjax.__file__).parent / "static" / "mathjax" / "es5"
        copy_asset(str(src), str(Path(app.outdir) / "_static" / "mathjax"))


def _dedupe_scripts(app, pagename, templatename, context, doctree):
    seen, kept = set(), []
    for js in context.get("script_files", []):
        # the repeated inline scripts differ only in filename None against "" (sphinx-thebe, togglebutton)
        key = (getattr(js, "filename", None) or "", tuple(sorted(getattr(js, "attributes", {}).items())))
        if key not in seen:
            seen.add(key)
            kept.append(js)
    # in place: it is the builder's own list, to which the math extension appends MathJax afterwards
    context["script_files"][:] = kept


def setup(app):
    app.config.mathjax_path = "mathjax/tex-mml-chtml.js"
    app.connect("build-finished", _copy_mathjax)
    # last: other handlers (thebe, togglebutton, the math extension) add scripts during this event
    app.connect("html-page-context", _dedupe_scripts, priority=999)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
