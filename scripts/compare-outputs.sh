#!/usr/bin/env bash
# Runs the shipped scenarios' commands with two pamsim binaries and compares what they write,
# file by file, byte for byte: the check that a refactoring changed no output. Left out of the
# comparison, because they differ from run to run by design: provenance.json (start time, wall
# time, git commit) and the databases themselves (their timing metrics and meta): a sweep
# database is compared as `pamsim export` prints it (timing columns aside), a tuning database
# through its evaluations.csv and best.toml. PNG, SVG and PDF plots are compared too
# (gnuplot writes the same bytes for the same data); MP4 frames through a decode would need
# FFmpeg's tools, so the video is compared as its bytes (libx264 is deterministic here).
#
#   scripts/compare-outputs.sh OLD_PAMSIM NEW_PAMSIM [WORK_DIR]
#
# The runs' own folder names (WORK/old, WORK/new) are compared as one name.
# Prints one line per differing output and "N same, M differ"; exits 1 if any differ.
set -euo pipefail
old=$(realpath "$1")
new=$(realpath "$2")
work=$(realpath -m "${3:-$(mktemp -d)}")
cd "$(dirname "$0")/.."
root=$(pwd)

# every command, run once per binary into its own folder (paths relative to the repository)
run_all() {
  local pamsim=$1 out=$2
  mkdir -p "$out"
  # every shipped run scenario (the arm, the pulley rig, the leg's eight muscles)
  for s in drop_mass drop_mass_fiber drop_mass_heavy drop_mass_heavy_ia_ib drop_mass_heavy_ib \
           drop_mass_ideal drop_mass_passive pulley_sine_5kg pulley_sine_10kg reaching \
           landing landing_reflex hopping squat_jump; do
    "$pamsim" run "scenarios/$s.toml" --out "$out/run_$s" --no-plot > "$out/run_$s.stdout"
  done
  "$pamsim" run scenarios/drop_mass.toml --trials 4 --threads 2 --out "$out/run_trials" \
    > "$out/run_trials.stdout"
  "$pamsim" run scenarios/drop_mass.toml --set reflex.v_thr_mm_s=60 --out "$out/run_set" \
    > "$out/run_set.stdout"
  "$pamsim" sweep scenarios/sweep_smoke.toml --threads 2 --quiet --out "$out/sweep" \
    > /dev/null 2>&1
  "$pamsim" export "$out/sweep/sweep.db" -o "$out/sweep/export.csv"
  "$pamsim" report "$out/sweep/sweep.db" --out "$out/report" > "$out/report.stdout"
  "$pamsim" replay "$out/sweep/sweep.db" --trial 1 --out "$out/replay" > "$out/replay.stdout" \
    2> /dev/null
  "$pamsim" keys scenarios/drop_mass.toml > "$out/keys.stdout"
  "$pamsim" render scenarios/drop_mass.toml --set sim.duration_s=1.3 --width 320 --height 240 \
    -o "$out/render.mp4" --quiet > /dev/null 2>&1
  # a short tuning: same evaluations, same outputs
  sed -e 's/^generations *=.*/generations = 2/' -e 's/^held_out_seeds *=.*/held_out_seeds = 2/' \
    scenarios/tune_reflex.toml > "$out/tune_short.toml"
  sed -i "s#^base *= *\"\\(.*\\)\"#base = \"$root/scenarios/\\1\"#" "$out/tune_short.toml"
  "$pamsim" tune "$out/tune_short.toml" --threads 2 --quiet --out "$out/tune" \
    > "$out/tune.stdout" 2> /dev/null
}

# a reused folder's earlier outputs would hide a file the new binary no longer writes
rm -rf "$work/old" "$work/new"
mkdir -p "$work"
run_all "$old" "$work/old"
run_all "$new" "$work/new"

same=0
differ=0
while IFS= read -r -d '' f; do
  rel=${f#"$work/old/"}
  case "$rel" in
    */provenance.json|*.db|*.db-wal|*.db-shm|*/tune.db*) continue ;;
  esac
  # the two runs' folders appear in messages and headers: compared as one name
  if [ ! -e "$work/new/$rel" ]; then
    differ=$((differ + 1))
    echo "only old: $rel"
    continue
  fi
  if cmp -s <(sed "s#$work/old#WORK#g" "$f") <(sed "s#$work/new#WORK#g" "$work/new/$rel"); then
    same=$((same + 1))
  else
    differ=$((differ + 1))
    echo "differs: $rel"
  fi
done < <(find "$work/old" -type f -print0 | sort -z)
# files only the new run wrote
while IFS= read -r -d '' f; do
  rel=${f#"$work/new/"}
  [ -e "$work/old/$rel" ] || { differ=$((differ + 1)); echo "only new: $rel"; }
done < <(find "$work/new" -type f -print0 | sort -z)
echo "compare-outputs: $same same, $differ differ (in $work)"
[ "$differ" -eq 0 ]
