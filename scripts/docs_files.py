"""docs_files.py: what the docs scripts (docs_blocks.py, docs_lint.py, docs_generate.py) share:
a generated block's syntax in a page, and writing a file whole or not at all."""

import os
import re

OPEN = "<!-- pamsim-block"
CLOSE = "<!-- /pamsim-block"
# a block: its spec (YAML inside the opening comment), its body, and the closing stamp
BLOCK = re.compile(
    re.escape(OPEN)
    + r"\n(?P<spec>.*?)-->\n(?P<body>.*?)"
    + re.escape(CLOSE)
    + r"(?P<stamp>[^\n]*?)-->",
    re.S,
)


def atomic_write(path, text):
    """`text` into `path` through a temporary file beside it: a reader sees the old file or
    the new one, never a part."""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)
