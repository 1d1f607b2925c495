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
html_theme = "alabaster"
html_theme_options = {"description": "simulating PAM-driven arms and legs with a stretch reflex"}
nitpicky = True
