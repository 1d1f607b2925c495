#!/usr/bin/env python3
"""view_bench.py: `pamsim view`'s frame rate with its figures on, measured in one run: the
falling mass (scenarios/drop_mass.toml) watched live for 3 s of its trial at real time on a
virtual display (Debian's Xvfb; Mesa draws on the CPU there, as on a machine without a GPU),
once at each --quality, the frames per second the viewer reports on closing: the scene
(1280x720), MuJoCo's UI and the four live figures drawn every frame, as fast as the machine
allows (no vertical sync).

    python3 bench/view_bench.py [--pamsim build/src/sim/pamsim] [--out DIR]
"""

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from virtual_display import VirtualDisplay  # noqa: E402

SCRIPT = "0 play\n3.0 close\n"


def frame_rate(pamsim, env, script, quality):
    done = subprocess.run(
        [pamsim, "view", "scenarios/drop_mass.toml", "--script", script, "--quality", quality],
        env=env,
        capture_output=True,
        text=True,
        check=True,
        timeout=120,
    )
    line = [x for x in done.stderr.splitlines() if x.startswith("pamsim view:")][0]
    rate = float(re.search(r"\(([0-9.]+) frames/s", line).group(1))
    gl = line.split("; ", 1)[1]
    return rate, gl


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pamsim", default="build/src/sim/pamsim")
    ap.add_argument("--out", default="renders/bench_view")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    script = os.path.join(a.out, "play.txt")
    with open(script, "w") as f:
        f.write(SCRIPT)
    with VirtualDisplay() as env:
        rates = {q: frame_rate(a.pamsim, env, script, q) for q in ("default", "fast")}
    gl = rates["default"][1]
    print(f"pamsim view, figures on, 3 s of the falling mass at real time ({gl}):")
    for quality, (rate, _) in rates.items():
        print(f"  --quality {quality}: {rate:.1f} frames/s")
    print(f"  fast / default: {rates['fast'][0] / rates['default'][0]:.2f}")


if __name__ == "__main__":
    main()
