#!/usr/bin/env bash
# fuzz.sh BUILD_DIR [SECONDS]: runs each libFuzzer harness of tests/fuzz (built in BUILD_DIR by
# `make fuzz`) for SECONDS (default 60) from its seed corpus tests/fuzz/corpus/<name>. The
# corpus it grows is kept in BUILD_DIR/corpus/<name> and used again by the next run; an input
# that crashes, trips a sanitizer, hangs (20 s) or throws anything but InputError is saved as
# BUILD_DIR/findings/<name>-* and fails the run. The mutations follow FUZZ_SEED (default 1),
# so a run from the same corpus explores the same inputs.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: fuzz.sh BUILD_DIR [SECONDS]}
seconds=${2:-60}
mkdir -p "$build/findings"
status=0
for name in scenario override sweep tensile_csv identify recording_csv readings_csv; do
  work="$build/corpus/$name"
  log="$build/fuzz_$name.log"
  mkdir -p "$work"
  if "$build/tests/fuzz/fuzz_$name" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" \
      -timeout=20 -rss_limit_mb=4096 \
      -max_len=8192 -print_final_stats=1 -artifact_prefix="$build/findings/$name-" \
      "$work" "tests/fuzz/corpus/$name" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz: $name: ${runs:-?} inputs in ${seconds} s, corpus $(ls "$work" | wc -l) files, 0 findings"
  else
    tail -n 30 "$log"
    echo "fuzz: $name: FINDING, input saved under $build/findings/ (log: $log)"
    status=1
  fi
done
exit $status
