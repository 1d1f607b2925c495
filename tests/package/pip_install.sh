#!/usr/bin/env bash
# pip_install.sh BUILD_DIR WORK_DIR: the Python package as a user installs it. In a fresh
# virtual environment of the first python3 on PATH, `pip install .` of this checkout (pip
# fetches scikit-build-core, pybind11 and numpy from the registry), built against the pamsim
# of BUILD_DIR installed into WORK_DIR/prefix, so that only the module compiles (a user's
# plain `pip install .` builds pamsim too); then `pip wheel .` and that wheel installed into a
# second environment. Each imports pamsim from outside the source tree, with no PYTHONPATH,
# and runs a trial. Then the Gymnasium environments' tests (python/tests/test_envs.py) with
# gymnasium from the registry, one generation of examples/learn_reflex.py, and the package's
# typing and style: ruff, mypy --strict, and the stub of the compiled module against the
# module itself (mypy.stubtest).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > /dev/null
unset PYTHONPATH
settings=(-Ccmake.define.PAMSIM_PREBUILT="$work/prefix" -Cbuild-dir="$work/build")

check() {   # check VENV: the package imports and runs a short trial there
  (cd "$work" && "$1/bin/python" - "$source_dir" <<'PY'
import sys, pamsim
scenario = sys.argv[1] + "/scenarios/drop_mass.toml"
result = pamsim.run(scenario, {"sim.duration_s": 0.6, "drop.time_s": 0.2})
assert pamsim.__file__.startswith(sys.prefix), pamsim.__file__
print("pamsim", pamsim.__version__, "from", pamsim.__file__.rsplit("/", 2)[0],
      "peak drop", round(result.summary["peak_drop_deg"], 3), "deg")
PY
  )
}

python3 -m venv "$work/venv"
start=$SECONDS
"$work/venv/bin/pip" install --quiet "$source_dir" "${settings[@]}"
echo "pip install . ($(python3 --version)): $((SECONDS - start)) s"
check "$work/venv"

start=$SECONDS
"$work/venv/bin/pip" wheel --quiet --no-deps -w "$work/wheels" "$source_dir" "${settings[@]}"
echo "pip wheel .: $((SECONDS - start)) s, $(ls "$work/wheels")"
python3 -m venv "$work/venv2"
"$work/venv2/bin/pip" install --quiet "$work"/wheels/pamsim-*.whl
check "$work/venv2"

# the Gymnasium environments, as a user gets them (gymnasium from the registry)
"$work/venv/bin/pip" install --quiet gymnasium cma pytest ruff mypy
(cd "$work" && "$work/venv/bin/python" -c \
  "import pamsim, gymnasium; gymnasium.make('pamsim/DropMass-v0'); print('DropMass-v0 made')")
(cd "$work" && "$work/venv/bin/python" -m pytest -q -p no:cacheprovider \
   "$source_dir/python/tests/test_envs.py")
# the learning example runs (one generation; its table in the docs comes from 25)
(cd "$work" && "$work/venv/bin/python" -W ignore "$source_dir/examples/learn_reflex.py" \
   --generations 1 --out "$work/learn_reflex.csv" | tail -4)
"$work/venv/bin/ruff" check --config "$source_dir/pyproject.toml" "$source_dir/python" \
  "$source_dir/examples/learn_reflex.py" "$source_dir/examples/drop_mass_eval.py" \
  "$source_dir/examples/ppo_drop_mass.py" "$source_dir/bench/env_throughput.py"
(cd "$work" && "$work/venv/bin/mypy" --config-file "$source_dir/pyproject.toml" -p pamsim &&
 "$work/venv/bin/python" -m mypy.stubtest --mypy-config-file "$source_dir/pyproject.toml" \
   --allowlist "$source_dir/python/stubtest_allowlist.txt" pamsim._pamsim)
