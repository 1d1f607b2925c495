#!/usr/bin/env bash
# format.sh [--check]: the tree's C and C++ (src, tests, python, bench) through clang-format-14
# (.clang-format: Google's style at 100 columns), and its Python (python, scripts, bench,
# tests, examples) through ruff's formatter and linter (pyproject.toml's [tool.ruff]; ruff
# from the Python registry, pinned, in .tools/ by scripts/install-deps.sh). Without --check
# it rewrites the files (and applies ruff's safe fixes); with --check it changes nothing and
# exits 1 naming each file that is not formatted or a lint finding (.ci/run).
# tests/sizes/too_long.cc is a fixture of a given length, left as it is.
set -euo pipefail
cd "$(dirname "$0")/.."
check="${1:-}"
ruff="${RUFF:-.tools/bin/ruff}"
if ! command -v clang-format-14 >/dev/null || [ ! -x "$ruff" ]; then
  echo "format: clang-format-14 or $ruff missing (scripts/install-deps.sh installs them)" >&2
  exit 2
fi

mapfile -t cpp < <(git ls-files 'src/*.cc' 'src/*.h' 'src/*.c' 'tests/*.cc' 'tests/*.h' \
  'python/*.cc' 'python/*.h' 'bench/*.cc' | grep -v '^tests/sizes/')
mapfile -t py < <(git ls-files 'python/*.py' 'python/*.pyi' 'scripts/*.py' 'bench/*.py' \
  'tests/*.py' 'examples/*.py')

if [ "$check" = "--check" ]; then
  status=0
  if ! clang-format-14 --dry-run -Werror "${cpp[@]}" >/dev/null 2>&1; then
    for f in "${cpp[@]}"; do
      clang-format-14 --dry-run -Werror "$f" >/dev/null 2>&1 ||
        echo "format: $f: not as clang-format-14 writes it (scripts/format.sh)"
    done
    status=1
  fi
  "$ruff" format --quiet --check "${py[@]}" || status=1
  "$ruff" check --quiet --output-format concise "${py[@]}" || status=1
  [ "$status" -eq 0 ] && echo "format: ${#cpp[@]} C/C++ and ${#py[@]} Python files as formatted, no lint"
  exit "$status"
fi
clang-format-14 -i "${cpp[@]}"
"$ruff" format --quiet "${py[@]}"
"$ruff" check --quiet --fix "${py[@]}"
