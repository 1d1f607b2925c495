#!/usr/bin/env bash
# check.sh BUILD_DIR WORK_DIR: installs the pamsim built in BUILD_DIR into WORK_DIR/prefix
# (cmake --install), builds tests/package (an outside project using find_package(pamsim))
# against it in WORK_DIR/build, and runs its two programs, the installed `pamsim` and (when
# built) an import of the installed Python package.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
work=$2
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" > /dev/null
# nothing internal is installed: the public headers include only public ones (else the
# outside build below fails), and an internal header is absent
test ! -e "$work/prefix/include/pamsim/sim/core/trial_run.h"
# every installed header, included by one source file the outside project compiles
mkdir -p "$work"
(cd "$work/prefix/include/pamsim" && find . -name "*.h" | sort | sed 's|^\./|#include "|; s|$|"|') \
  > "$work/all_headers.cc"
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DALL_HEADERS_SOURCE="$work/all_headers.cc" > "$work/configure.log"
cmake --build "$work/build" -j 2 > "$work/build.log"
"$work/build/law_only"
# the muscle alone: no simulation dependency looked for
cmake -S "$here/muscle_only" -B "$work/muscle_only" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/muscle_only.log"
cmake --build "$work/muscle_only" -j 2 >> "$work/muscle_only.log"
"$work/muscle_only/law_only"
"$work/build/drop_trial"
"$work/prefix/bin/pamsim" --version
# the Python package installed beside it (when built), importable from there
python_dir=$(find "$work/prefix" -type d -name pamsim -path "*-packages/pamsim" | head -1)
if [ -n "$python_dir" ]; then
  PYTHONPATH=$(dirname "$python_dir") python3 -c \
    "import pamsim; print('python pamsim', pamsim.__version__, pamsim.SpringModel.__name__)"
fi
