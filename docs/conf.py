# conf.py: the pamsim documentation site, built by `make docs` (scripts/docs.sh) with Sphinx
# and MyST (Debian's python3-sphinx and python3-myst-parser), warnings as errors. Sphinx
# because MuJoCo and Drake document with it; MyST so the pages are Markdown. The reference
# pages under _generated/ are written by scripts/docs_generate.py from the program itself
# (`pamsim keys --json`, `pamsim <command> --help`) before each build; the computed numbers
# and figures stand in generated blocks that scripts/docs_blocks.py writes and CI checks.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "_ext"))

project = "pamsim"
author = "the pamsim authors"
# pamsim_docs: the {input} and {paper} roles of numbers in prose (scripts/docs_blocks.py)
extensions = ["myst_parser", "pamsim_docs"]
source_suffix = {".md": "markdown"}
exclude_patterns = ["_build", "_generated", "README.md"]
myst_heading_anchors = 3
myst_enable_extensions = ["deflist"]   # the key references: a key, then what it is
smartquotes = False                    # options are written as typed: --pneumatics
# furo (Debian's furo package): a content column wider than alabaster's, and a sidebar that
# folds into a menu on narrow windows; _static/pamsim.css widens the column further and wraps
# long code lines, so that no command is cut at 1280 px (scripts/docs_screenshot.py checks it)
html_theme = "furo"
html_title = "pamsim"
html_static_path = ["_static"]
html_css_files = ["pamsim.css"]
# Debian's furo.css imports normalize.css from /javascript/normalize.css/, a path that only
# a web server with Debian's javascript-common alias has (not file://, not a plain host):
# the site carries the copy of node-normalize.css (a dependency of furo) instead, ahead of
# furo.css (priority 200), as the import would have put it
_normalize = "/usr/share/javascript/normalize.css/normalize.css"
if os.path.exists(_normalize):
    html_static_path.append(_normalize)
    html_css_files.insert(0, ("normalize.css", {"priority": 100}))
nitpicky = True
