"""pamsim_docs: the site's two roles for numbers in prose that pamsim does not compute, so that
scripts/docs_blocks.py's lint can tell them from computed ones: {input}`0.2 kg` (a value the
user or a file sets) and {paper}`5.24 %` (a value a paper reports). Both show as plain text.
"""
from docutils import nodes


def _as_text(name, rawtext, text, lineno, inliner, options=None, content=None):
    return [nodes.inline(rawtext, text, classes=[name])], []


def setup(app):
    app.add_role("input", _as_text)
    app.add_role("paper", _as_text)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
