#!/usr/bin/env python3
"""hil_bench.py: `pamsim hil` in real time on this machine, measured in one run: the falling
mass (scenarios/drop_mass.toml) for SECONDS of trial at 100 Hz, its exported controller
(built from the export folder with make) as its own process over UDP on loopback, the plant
paced to the wall clock. From the run's link.csv and summary.json: each tick's jitter (how
late after its due time the readings left), each command's latency (readings out to command
in), and the ticks more than one control period late or missed.

    python3 bench/hil_bench.py [--pamsim build/src/sim/pamsim] [--out DIR] [--seconds 60]
"""

import argparse
import csv
import json
import os
import shutil
import socket
import subprocess
import time


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pamsim", default="build/src/sim/pamsim")
    ap.add_argument("--out", default="renders/bench_hil")
    ap.add_argument("--seconds", type=float, default=60.0)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    ctl = os.path.join(a.out, "ctl")
    subprocess.run(
        [a.pamsim, "controller", "export", "scenarios/drop_mass.toml", "-o", ctl],
        check=True,
        capture_output=True,
    )
    subprocess.run(["make", "-s", "-C", ctl], check=True, capture_output=True)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    run = os.path.join(a.out, "run")
    pamsim = subprocess.Popen(
        [
            a.pamsim,
            "hil",
            "scenarios/drop_mass.toml",
            "--udp",
            f"127.0.0.1:{port}",
            "--realtime",
            "--out",
            run,
            "--set",
            f"sim.duration_s={a.seconds}",
        ],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    time.sleep(0.3)
    board = subprocess.Popen(
        [os.path.join(ctl, "build", "pamctl_hil"), "--udp", f"127.0.0.1:{port}"]
    )
    pamsim.wait(timeout=a.seconds + 120)
    board.wait(timeout=30)
    with open(os.path.join(run, "summary.json")) as f:
        h = json.load(f)["hil"]
    with open(os.path.join(run, "link.csv")) as f:
        rows = list(csv.DictReader(f))
    period_ms = 10.0
    late = sum(1 for r in rows if float(r["jitter_ms"]) > period_ms)
    print(
        f"pamsim hil --realtime, {h['ticks']} ticks at 100 Hz ({a.seconds:g} s) over UDP on "
        "loopback, the exported controller in its own process:"
    )
    print(
        f"  tick jitter: p50 {h['jitter_ms']['p50']:.3f} ms, p99 {h['jitter_ms']['p99']:.3f} ms,"
        f" max {h['jitter_ms']['max']:.3f} ms"
    )
    print(
        f"  command latency: p50 {h['latency_ms']['p50']:.3f} ms, p99 "
        f"{h['latency_ms']['p99']:.3f} ms, max {h['latency_ms']['max']:.3f} ms"
    )
    print(
        f"  ticks more than one period late: {late}; commands missed: {h['missed_ticks']}, "
        f"vented: {h['vented_ticks']}"
    )


if __name__ == "__main__":
    main()
