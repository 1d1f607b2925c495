#!/usr/bin/env bash
# The main job: the falling-mass experiment with the model-based stretch reflex, and its
# passive baseline with the same seed. Outputs: renders/drop_mass/{trajectory.csv,
# summary.json, angle.png, angle_vs_passive.png, scenario.toml, provenance.json,
# drop_mass.mp4} and renders/drop_mass_passive/ (all but the video); angle_vs_passive.png
# draws both trials on one axis, as the paper's Fig. 8 does. The video is the same trial (same seed,
# bit-identical physics), rendered headlessly. --force: a second `make demo` replaces the first's.
set -euo pipefail
pamsim="${1:-build/src/sim/pamsim}"
cd "$(dirname "$0")/.."

"$pamsim" run scenarios/drop_mass_passive.toml --out renders/drop_mass_passive --force > /dev/null
"$pamsim" run scenarios/drop_mass.toml --out renders/drop_mass --force > /dev/null
"$pamsim" compare renders/drop_mass renders/drop_mass_passive --label-a "stretch reflex" \
  --label-b "passive" -o renders/drop_mass/angle_vs_passive.png --force > /dev/null
"$pamsim" render scenarios/drop_mass.toml --plot -o renders/drop_mass/drop_mass.mp4 --force

# the headline numbers, reflex vs passive
python3 - <<'PY' 2>/dev/null || cat renders/drop_mass/summary.json
import json
r = json.load(open("renders/drop_mass/summary.json"))
p = json.load(open("renders/drop_mass_passive/summary.json"))
print(f"impact at {r['impact_time_s']:.3f} s; reflex triggered at {r['first_trigger_time_s']:.3f} s, "
      f"{r['mistrips']} mistrips")
print(f"lowest angle: {r['min_angle_deg']:.2f} deg with the reflex, "
      f"{p['min_angle_deg']:.2f} deg passive (start {r['start_angle_deg']:.2f} deg)")
print("outputs: renders/drop_mass/{trajectory.csv,summary.json,angle.png,angle_vs_passive.png,"
      "drop_mass.mp4}")
PY
