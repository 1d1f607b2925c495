#!/usr/bin/env bash
# Holds src/ to the size rule ("rooms of human size"): no file (*.cc, *.c, *.h, *.py)
# over 400 lines, no function over 60 lines. Prints every file and function over its limit and
# exits 1; else prints one summary line and exits 0. File lengths by wc -l, function lengths
# by pmccabe (Debian package pmccabe; its 5th column is a function's lines, its last
# "file(line): name"), a Python function's by Python's ast. Run from anywhere; the optional
# argument is the folder to check, and `--except FOLDER` leaves out a folder inside it (the
# check's own too-long fixture in tests/).
# A CTest test (SizesTest) runs it, so `make test` and CI hold every change to it.
set -euo pipefail

readonly MAX_FILE_LINES=400
readonly MAX_FUNCTION_LINES=60

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
src="$(cd "${1:-$root/src}" && pwd)"
except=""
if [ "${2:-}" = "--except" ]; then except="$(cd "$3" && pwd)"; fi
cd "$root"

if ! command -v pmccabe >/dev/null; then
  echo "check-sizes: pmccabe not found (scripts/install-deps.sh installs it)" >&2
  exit 2
fi

# paths relative to the repository root, as the messages name them
mapfile -t files < <(find "$src" -type f \( -name '*.cc' -o -name '*.c' -o -name '*.h' \) |
  { if [ -n "$except" ]; then grep -v "^$except/"; else cat; fi; } | sort)
files=("${files[@]#"$root"/}")
if [ ${#files[@]} -eq 0 ]; then
  echo "check-sizes: no *.cc or *.h under $src" >&2
  exit 2
fi

# Python files are measured too: their functions by Python's own parser (ast)
mapfile -t py_files < <(find "$src" -type f -name '*.py' -not -path '*/__pycache__/*' |
  { if [ -n "$except" ]; then grep -v "^$except/"; else cat; fi; } | sort)
py_files=("${py_files[@]#"$root"/}")

# files: "lines<TAB>path", longest first
file_lines="$(for f in "${files[@]}" "${py_files[@]}"; do
  printf '%s\t%s\n' "$(awk 'END { print NR }' "$f")" "$f"; done | sort -t$'\t' -k1,1nr)"

# functions: "lines<TAB>file(line): name", longest first. pmccabe parses C, not C++17: it
# loses its way at `noexcept` and `override`, so it reads copies without those words (the
# lines stay where they are) under the same relative paths. Anything it still cannot parse
# fails the check, since the functions after it would go unmeasured.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for f in "${files[@]}"; do
  mkdir -p "$work/$(dirname "$f")"
  sed -E 's/\b(noexcept|override|final)\b//g' "$f" >"$work/$f"
done
function_lines="$(cd "$work" && pmccabe -v "${files[@]}" 2>"$work/.errors" |
  awk -F'\t' 'NF >= 6 && $5 ~ /^[0-9]+$/ { print $5 "\t" $6 }' | sort -t$'\t' -k1,1nr)"
if [ -s "$work/.errors" ]; then
  sed 's/^/check-sizes: pmccabe cannot parse: /' "$work/.errors" >&2
  exit 1
fi

if [ ${#py_files[@]} -gt 0 ]; then
  function_lines="$(printf '%s\n' "$function_lines" "$(python3 - "${py_files[@]}" <<'PY'
import ast, sys
for path in sys.argv[1:]:
    for node in ast.walk(ast.parse(open(path).read(), path)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            print(f"{node.end_lineno - node.lineno + 1}\t{path}({node.lineno}): {node.name}")
PY
)" | grep . | sort -t$'\t' -k1,1nr)"
fi

over_files="$(awk -F'\t' -v max="$MAX_FILE_LINES" '$1 > max' <<<"$file_lines")"
over_functions="$(awk -F'\t' -v max="$MAX_FUNCTION_LINES" '$1 > max' <<<"$function_lines")"

if [ -n "$over_files" ] || [ -n "$over_functions" ]; then
  [ -n "$over_files" ] && awk -F'\t' -v max="$MAX_FILE_LINES" \
    '{ print "file over " max " lines: " $2 " (" $1 " lines)" }' <<<"$over_files"
  [ -n "$over_functions" ] && awk -F'\t' -v max="$MAX_FUNCTION_LINES" \
    '{ print "function over " max " lines: " $2 " (" $1 " lines)" }' <<<"$over_functions"
  exit 1
fi

n_files=$((${#files[@]} + ${#py_files[@]}))
n_functions="$(grep -c . <<<"$function_lines" || true)"
IFS=$'\t' read -r largest_lines largest_file <<<"$(head -n 1 <<<"$file_lines")"
IFS=$'\t' read -r longest_lines longest_function <<<"$(head -n 1 <<<"$function_lines")"
echo "sizes: $n_files files, $n_functions functions, largest file $largest_file" \
  "($largest_lines lines), longest function $longest_function ($longest_lines lines)"
