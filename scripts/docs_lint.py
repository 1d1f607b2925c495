#!/usr/bin/env python3
"""docs_lint.py: the lint of scripts/docs_blocks.py (`docs_blocks.py lint`): a computed number
in a page's prose, outside a generated block, is a number that can go stale. A number counts
when it has a decimal point, or a unit after it; prose may still give, as they are, equation,
table, figure and section numbers, list numbers, years, software versions, DOIs and
addresses, code, and a paper's or an input's values marked {paper}`5.24 %` or {input}`0.2 kg`
(roles the site shows as plain text, docs/_ext/pamsim_docs.py).
"""

import os
import re
import sys

from docs_files import BLOCK

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

UNIT = (
    r"(?:%|deg|mm|cm|m|s|ms|us|ns|N|MPa|kPa|Pa|Hz|kHz|kg|g|V|mV|GPa|Ohm|J|W|x|"
    r"frames/s|fps|steps/s|trials/s|points|trials|rigs|arms|standard errors|se)(?![\w/])"
)
COMPUTED = re.compile(r"(?<![\w.\-/])(?:\d+\.\d+(?:[eE][-+]?\d+)?|\d+(?=\s?" + UNIT + r"))")
SOFTWARE = re.compile(
    r"\b(?:pamsim|MuJoCo|SUNDIALS|Python|Debian|Sphinx|CMake|NumPy|numpy|"
    r"gymnasium|Gymnasium|pybind11|Eigen|Ceres|PyTorch|C\+\+|bookworm|"
    r"toml\+\+|version|v)\s?\d+(?:\.\d+)+\b"
)
HIDDEN = [
    re.compile(p, re.S | re.M)
    for p in (
        BLOCK.pattern,  # generated blocks
        r"<!--.*?-->",  # comments
        r"^(```|~~~).*?^\1",  # fenced code
        r"\{(?:input|paper)\}`[^`]*`",  # marked inputs and paper values
        r"`[^`\n]*`",  # inline code
        r"\]\([^)]*\)",  # link targets
        r"\b(?:doi:|https?://)\S+",  # DOIs and addresses
        r"\b(?:Eq|Eqs|Table|Tables|Fig|Figs|Sec|Section|Ch)\.?\s?\(?[\dIVX][\w.\-,()]*",
    )
]
LINT_SKIP = ("docs/references.md",)


def lint_text(text):
    """Each computed number in prose: (line number, the numbers)."""

    def blank(m):
        return re.sub(r"[^\n]", " ", m.group(0))  # keeps the lines where they were

    for pattern in HIDDEN:
        text = pattern.sub(blank, text)
    text = SOFTWARE.sub(blank, text)
    for i, line in enumerate(text.splitlines(), 1):
        found = COMPUTED.findall(line)
        if found:
            yield i, found


def lint(paths):
    problems = 0
    for path in paths:
        where = os.path.relpath(path, ROOT)
        if where in LINT_SKIP:
            continue
        with open(path) as f:
            text = f.read()
        for line, numbers in lint_text(text):
            problems += 1
            print(
                f"{where}:{line}: {', '.join(numbers)} in prose: a computed number belongs in "
                f"a generated block; an input or a paper's value is marked {{input}}`...` or "
                f"{{paper}}`...`",
                file=sys.stderr,
            )
    print(f"docs_blocks lint: {len(paths)} pages, {problems} lines with computed numbers")
    return 1 if problems else 0
