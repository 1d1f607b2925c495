#!/usr/bin/env bash
# install-deps.sh [--demo]: installs every Debian package pamsim needs to build, test, plot
# and render; with --demo only what building pamsim and running the demo need (make demo:
# no test, sanitizer, fuzz, MPI, Slurm, Python-module or docs packages).
# Idempotent: when all are present it only asks dpkg, which takes well under a second.
set -euo pipefail

# pamsim itself: build it, run a scenario, plot and render it
packages=(
  build-essential cmake pkg-config
  libmujoco-dev libqhull-dev libgl-dev      # MuJoCo 2.2.2; its CMake config needs qhull and OpenGL
  libsundials-dev                            # CVODE 6.4 for the valve and chamber ODE
  libeigen3-dev                              # least squares in identification
  libboost-dev                               # Boost.Math root finding (TOMS 748) for the plant laws
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libsqlite3-dev                             # sweep results
  libpagmo-dev                               # pamsim tune: CMA-ES, NSGA-II (pagmo2)
  libceres-dev                               # pamsim identify: Levenberg-Marquardt, covariances
  libosmesa6-dev                             # headless rendering (OSMesa, llvmpipe)
  libegl-dev libgl1-mesa-dri                 # the EGL backend and Mesa's software driver for it
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev   # MP4 encoding
  gnuplot-nox                                # plots (pngcairo terminal)
  libcmark-gfm-dev libcmark-gfm-extensions-dev   # report pages: Markdown tables as HTML
  libglfw3-dev                               # pamsim view: the live window (GLFW on GLX)
  python3                                    # scripts/*.py and the demo's summary line
)
# the rest: the tests, the sanitizer and fuzz builds, MPI, Slurm, the Python module, the docs
[ "${1:-}" = "--demo" ] || packages+=(
  pmccabe                                    # scripts/check-sizes.sh: function lengths
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev                   # make fuzz: libFuzzer and clang's sanitizer runtimes
  libomp-14-dev                              # clang's OpenMP, which SUNDIALS' CMake config asks for
  libopenmpi-dev openmpi-bin                 # sweeps over MPI ranks (-DPAMSIM_MPI=ON, mpirun)
  slurm-wlm munge                            # tests/slurm: a one-node Slurm for scripts/slurm/
  pybind11-dev python3-dev python3-numpy python3-pytest   # the Python module and its tests
  python3-pandas python3-matplotlib          # DataFrames in the module; the example script
  python3-venv python3-pip                   # pip install . into a fresh virtual environment
  python3-sphinx python3-myst-parser python3-yaml   # make docs: the site and its generated pages
  furo                                       # the docs' theme: a wide column, a sidebar that folds
  chromium                                   # scripts/docs_screenshot.py: the site in a 1280 px window
  chromium-driver python3-selenium           # tests/browser: report pages driven in Chromium
  xvfb xauth                                 # tests/viewer: pamsim view on a virtual display
  socat                                      # tests/hil: a serial line as a pseudo-terminal pair
  jq                                         # the docs' generated blocks pick numbers from JSON
  clang-format-14                            # scripts/format.sh: the C and C++ as .clang-format says
  gcc-arm-none-eabi libnewlib-arm-none-eabi  # the embedded controller for Cortex-M (make embedded)
  gcc-arm-linux-gnueabihf libc6-dev-armhf-cross qemu-user   # ... for 32-bit ARM Linux, run by qemu-arm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    SUDO=sudo
  else
    SUDO=
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# ruff from the Python registry, pinned, in the checkout's own .tools/ (scripts/format.sh
# formats and lints the Python with it); not for the demo
readonly RUFF_VERSION=0.17.6
tools="$(cd "$(dirname "$0")/.." && pwd)/.tools"
if [ "${1:-}" != "--demo" ] && ! "$tools/bin/ruff" --version 2>/dev/null | grep -qx "ruff $RUFF_VERSION"; then
  echo "install-deps: installing ruff $RUFF_VERSION into $tools"
  python3 -m venv "$tools"
  "$tools/bin/pip" install --quiet "ruff==$RUFF_VERSION"
fi
