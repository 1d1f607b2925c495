#!/usr/bin/env bash
# fit-estimators.sh: the lab's pipeline for the arm's two muscles and the leg's eight
# (Yoshida and Hosoda, Sec. II-A):
# a static tensile test on each physical plant (models/pams/plant_<m>.toml), then the
# Eq. (2)-(3) least-squares fit, written as the estimator's parameter file
# models/pams/fitted_<m>.toml (strain gauge q and geometry copied from Table IV's file).
# The drop-mass scenarios invert these fits; the leg's (models/pams/leg/plant_<m>.toml ->
# models/pams/leg/fitted_<m>.toml) carry the arm agonist's gauge (Table IV's q) and their
# plant's own geometry; the arm's muscles as Table I builds them
# (models/pams/table1/plant_<m>.toml -> models/pams/table1/fitted_<m>.toml) Table IV's gauge
# and their plant's identified braid angle. Rerun after changing a plant file;
# tests/sim/cli/cli_plant_test.cc checks that the committed files are what this script writes.
#
# Protocol: the arm's pressure range, 0.2-0.7 MPa in 0.1 MPa steps (the reaching task's
# 0.2-0.6 MPa and the valve's 0.7 MPa top); 2.5 mm steps from the free length to 15 mm
# and back (Yoshida and Hosoda); instrument noise of the paper's sensors: PSE540 pressure 1 kPa,
# FGP-5 force gauge 0.05 N, DS-025 encoder 0.01 mm (standard deviations, assumptions of
# their repeatability class), seed 1.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
pamsim="$(realpath "${1:-$root/build/src/sim/pamsim}")"
out="${2:+$(realpath "$2")}"
cd "$root"
csv_dir="${out:-renders/tensile}"
out="${out:-models/pams}"
mkdir -p "$csv_dir" "$out" "$out/leg" "$out/table1"
sensors="$(mktemp)"
trap 'rm -f "$sensors"' EXIT

# fit_plant PLANT CSV SENSORS FITTED [SAID]: the protocol's tensile test of PLANT into CSV,
# the Eq. (2)-(3) fit with SENSORS' gauge and geometry into FITTED, whose provenance names
# SAID in place of a temp SENSORS file
fit_plant() {
  "$pamsim" tensile --plant "$1" --pressures-MPa 0.2,0.3,0.4,0.5,0.6,0.7 \
    --max-deformation-mm 15 --noise-pressure-MPa 0.001 --noise-force-N 0.05 \
    --noise-length-mm 0.01 --seed 1 -o "$2" --force
  "$pamsim" fit --model eq3 "$2" --sensors-from "$3" -o "$4" --force
  if [ -n "${5:-}" ]; then sed -i "s|--sensors-from $3|--sensors-from $5|" "$4"; fi
}

for m in agonist antagonist; do
  fit_plant "models/pams/plant_$m.toml" "$csv_dir/plant_$m.csv" "models/pams/table4_$m.toml" \
    "$out/fitted_$m.toml"
done
# the leg's muscles: the same protocol on each plant; the strain gauge is the arm
# agonist's (Table IV q), the geometry the plant's own length and sleeve
for m in IL GM RF VAS BFS GAS SOL TA; do
  length=$(sed -n 's/^length_mm = \([0-9.]*\).*/\1/p' "models/pams/leg/plant_$m.toml")
  diameter=$(sed -n 's/^diameter_mm = \([0-9.]*\).*/\1/p' "models/pams/leg/plant_$m.toml")
  sed -e "s/^length_mm = .*/length_mm = $length/" -e "s/^sleeve_diameter_mm = .*/sleeve_diameter_mm = $diameter/" \
    -e "s/^bladder_diameter_mm = .*/bladder_diameter_mm = $diameter/" models/pams/table4_agonist.toml > "$sensors"
  fit_plant "models/pams/leg/plant_$m.toml" "$csv_dir/leg_$m.csv" "$sensors" "$out/leg/fitted_$m.toml" \
    "models/pams/table4_agonist.toml (q, with the plant geometry)"
done
# the arm's muscles as Table I builds them (models/pams/table1/, identified by
# examples/table1): the arm's protocol; the strain gauge is Table IV's, the geometry the
# plant's (its identified braid angle, not Table IV's assumed 25 deg)
for m in agonist antagonist; do
  angle=$(sed -n 's/^braid_angle_deg = \([0-9.]*\).*/\1/p' "models/pams/table1/plant_$m.toml")
  sed -e "s/^braid_angle_deg = .*/braid_angle_deg = $angle   # [deg] the plant's (identified)/" \
    "models/pams/table4_$m.toml" > "$sensors"
  fit_plant "models/pams/table1/plant_$m.toml" "$csv_dir/table1_$m.csv" "$sensors" \
    "$out/table1/fitted_$m.toml" "models/pams/table4_$m.toml (q; the braid angle of the plant)"
done
