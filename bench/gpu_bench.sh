#!/usr/bin/env bash
# gpu_bench.sh: pamsim's speed on a GPU machine, measured in one run, for a lab to repeat on
# its own machine (about 5 minutes on 16 cores):
#   video   the drop-mass trial rendered at 1280x720 (the model's own look) and 640x480
#           (--quality fast) on EGL (the GPU) against OSMesa (llvmpipe, on the CPU), end to end
#           (`pamsim render`, the whole command) and by pamsim_bench (BM_RenderTrial end to end,
#           BM_DrawFrame drawing plus read-back alone, BM_FrameVsMujoco against bare MuJoCo)
#   sweep   scenarios/sweep_reflex.toml (2000 trials) on 1, 2, 4, 8 and 16 threads, and as 16
#           single-thread shard processes at once (the machine's own ceiling), each export
#           compared byte for byte with the one-thread sweep's
#   envs    ThreadedVectorEnv steps per second for 1, 4 and 16 environments
#           (bench/env_throughput.py), where Python imports pamsim and gymnasium
# Usage: bench/gpu_bench.sh [OUT_DIR]   (default renders/gpu_bench; summary.md in it)
#   PAMSIM, PAMSIM_BENCH, PYTHON: the programs (default build/src/sim/pamsim,
#   build/bench/pamsim_bench, python3); SECTIONS: "video sweep envs", or fewer.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-renders/gpu_bench}
pamsim=${PAMSIM:-build/src/sim/pamsim}
bench=${PAMSIM_BENCH:-build/bench/pamsim_bench}
python=${PYTHON:-python3}
sections=${SECTIONS:-video sweep envs}
for s in $sections; do
  case $s in
    video | sweep | envs) ;;
    *) echo "gpu_bench.sh: SECTIONS: unknown section \"$s\" (video, sweep, envs)" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
summary=$out/summary.md

now() { date +%s.%N; }
# seconds from $1 to $2 (now's stamps)
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.6f\n", b - a }'; }
# $1 / $2 times $4 (default 1) to $3 decimals; "-" where either is not a number (a failed run)
quotient() {
  python3 -c "import sys; a, b, d, k = sys.argv[1:]; print(f'{float(k) * float(a) / float(b):.{d}f}')" \
    "$1" "$2" "$3" "${4:-1}" 2>/dev/null || echo "-"
}
machine() {
  local cpu gpu
  cpu=$(grep -m1 "model name" /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
  gpu=$(nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | head -1)
  echo "Measured $(date -u +%Y-%m-%d) by $("$pamsim" --version) on ${cpu:-an unknown CPU}," \
    "$(nproc) cores; GPU: ${gpu:-none found} (name, driver)."
}

# one `pamsim render` on backend $1 at $2 x $3 with quality $4 and fps $5: a table row
render_row() {
  local log=$out/render-$1-$2x$3-$5.log t0 t1
  t0=$(now)
  "$pamsim" render scenarios/drop_mass.toml --backend "$1" --width "$2" --height "$3" \
    --quality "$4" --fps "$5" --quiet --force -o "$out/video-$1-$2x$3-$5.mp4" 2>"$log"
  local rc=$?
  t1=$(now)
  local frames gl
  frames=$(sed -n 's/.*: \([0-9]*\) frames of .*/\1/p' "$log")
  gl=$(sed -n 's/^pamsim: GL: //p' "$log")
  if [ "$rc" -ne 0 ] || [ -z "$frames" ]; then
    echo "| $1 | $2x$3 $4 | failed: $(tail -1 "$log") | | |"; return
  fi
  local rate
  rate=$(quotient "$frames" "$(elapsed "$t0" "$t1")" 1)
  echo "$1 $2x$3 $frames $rate" >>"$out/render-rates.txt"
  echo "| $1 | $2x$3 $4, $frames frames | $rate" \
    "| $(sed -n 's/.* s, \([0-9.]*\) frames\/s$/\1/p' "$log") | $gl |"
}

# EGL's whole-command rate over OSMesa's, per size and length, from render-rates.txt
render_ratios() {
  python3 -c "
import collections, sys
r = collections.defaultdict(dict)
for b, size, frames, rate in (l.split() for l in open(sys.argv[1])):
    r[(size, frames)][b] = float(rate)
print('EGL over OSMesa, whole command: ' + '; '.join(
    f'{s}, {n} frames: {v[\"egl\"] / v[\"osmesa\"]:.2f}x' for (s, n), v in r.items()
    if len(v) == 2) + '.')" "$out/render-rates.txt"
}

video() {
  rm -f "$out/render-rates.txt"
  echo "**Video**"
  echo
  echo "| backend | frames | whole command [frames/s] | pamsim's own count [frames/s] | GL |"
  echo "| --- | --- | --- | --- | --- |"
  for b in egl osmesa; do
    render_row $b 1280 720 default 30
    render_row $b 1280 720 default 240
    render_row $b 640 480 fast 30
    render_row $b 640 480 fast 240
  done
  echo
  render_ratios
  echo
  for b in egl osmesa; do
    MUJOCO_GL=$b "$bench" --benchmark_filter='RenderTrial|DrawFrame|FrameVsMujoco' \
      --benchmark_out="$out/render-$b.json" --benchmark_out_format=json >"$out/bench-$b.log" 2>&1
  done
  MUJOCO_GL=egl "$bench" --benchmark_filter='EncodeFrame' \
    --benchmark_out="$out/encode.json" --benchmark_out_format=json >"$out/bench-encode.log" 2>&1
  python3 bench/gpu_bench_table.py "$out"/render-egl.json "$out"/render-osmesa.json \
    "$out"/encode.json
}

# 2000 trials on $1 threads into $out/sweep-t$1: trials per second
sweep_rate() {
  local t0 t1
  t0=$(now)
  "$pamsim" sweep scenarios/sweep_reflex.toml --threads "$1" --quiet --out "$out/sweep-t$1" \
    >/dev/null 2>"$out/sweep-t$1.log" || { echo failed; return; }
  t1=$(now)
  "$pamsim" export "$out/sweep-t$1/sweep.db" -o "$out/sweep-t$1/trials.csv" 2>/dev/null
  quotient 2000 "$(elapsed "$t0" "$t1")" 1
}

sweep() {
  echo "**Sweep: scenarios/sweep_reflex.toml, 2000 trials**"
  echo
  echo "| run | trials/s | speed-up over 1 thread | same trials.csv as 1 thread |"
  echo "| --- | --- | --- | --- |"
  local one rate threads16 t0 t1 dir=$out/sweep-shards
  for t in 1 2 4 8 16; do
    rate=$(sweep_rate $t)
    [ "$t" = 1 ] && one=$rate
    [ "$t" = 16 ] && threads16=$rate
    echo "| --threads $t | $rate | $(quotient "$rate" "$one" 2)" \
      "| $(cmp -s "$out/sweep-t1/trials.csv" "$out/sweep-t$t/trials.csv" && echo yes || echo NO) |"
  done
  mkdir -p "$dir"
  t0=$(now)
  for i in $(seq 0 15); do
    "$pamsim" sweep scenarios/sweep_reflex.toml --threads 1 --quiet --shard "$i/16" \
      --out "$dir" >/dev/null 2>"$dir/shard-$i.log" &
  done
  wait
  t1=$(now)
  "$pamsim" merge "$dir/sweep.db" "$dir"/sweep.shard-*-of-16.db >/dev/null 2>&1
  "$pamsim" export "$dir/sweep.db" -o "$dir/trials.csv" 2>/dev/null
  rate=$(quotient 2000 "$(elapsed "$t0" "$t1")" 1)
  echo "| 16 single-thread processes | $rate | $(quotient "$rate" "$one" 2)" \
    "| $(cmp -s "$out/sweep-t1/trials.csv" "$dir/trials.csv" && echo yes || echo NO) |"
  echo
  echo "16 threads reach $(quotient "$threads16" "$rate" 0 100) %" \
    "of the 16 processes' rate."
}

envs() {
  echo "**Vector environment**"
  echo
  echo '```text'
  "$python" bench/env_throughput.py 1 4 16 2>&1 | tail -5
  echo '```'
}

{ machine; echo; } >"$summary.part"
for s in $sections; do
  $s >>"$summary.part"
  echo >>"$summary.part"
done
mv "$summary.part" "$summary"
cat "$summary"
