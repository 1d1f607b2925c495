#!/usr/bin/env bash
# docs.sh [PAMSIM] [OUT]: the documentation site. Writes the reference pages from the program
# (scripts/docs_generate.py into docs/_generated/), then builds docs/ with Sphinx and MyST
# into OUT (default build/docs), warnings as errors, cross-references checked (-n).
set -euo pipefail
cd "$(dirname "$0")/.."
pamsim="${1:-build/src/sim/pamsim}"
out="${2:-build/docs}"
/usr/bin/python3 scripts/docs_generate.py "$pamsim" docs/_generated
/usr/bin/python3 -m sphinx -W --keep-going -n -q -b html docs "$out"
echo "docs: $out/index.html"
