#!/usr/bin/env python3
"""hil_test.py PAMSIM OUT: `pamsim hil` with the exported controller as a separate process
(built from its export folder with make), traffic on loopback only, every wait bounded.
  - exact: over UDP and over a serial line (a socat pseudo-terminal pair) in lockstep, the
    trajectory.csv is `pamsim run`'s byte for byte;
  - faults, deterministic in lockstep: 5 % of commands dropped (each held, the count within
    the binomial's band, the same run twice the same), a burst of 20 dropped (hil.hold_ticks
    held, then vented: the valve command 0 in the log), corrupted bytes on the serial line
    (refused by the CRC, held), the controller killed mid-trial (held, vented, then the run
    ends in one line, exit 5, its outputs complete);
  - bad input: a port in use, a missing device, a peer of another version, a fault fraction
    out of range: one line, exit 2.
Exit 0 when every check holds.

    python3 tests/hil/hil_test.py build/src/sim/pamsim /tmp/hil_test
"""

import csv
import json
import math
import os
import shutil
import signal
import socket
import struct
import subprocess
import sys
import time

SCENARIO = "scenarios/drop_mass.toml"
OUTPUTS = ["link.csv", "provenance.json", "scenario.toml", "summary.json", "trajectory.csv"]
TICKS = 300  # drop_mass: 3 s at 100 Hz


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def read(path):
    with open(path, "rb") as f:
        return f.read()


def start_hil(pamsim, link, out, *args):
    """pamsim hil on `link` into `out`, its output and errors piped."""
    return subprocess.Popen(
        [pamsim, "hil", SCENARIO, *link, "--out", out, *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def hil(pamsim, out, link, *args, controller=None, timeout=120):
    """pamsim hil with `controller` (argv) started once pamsim listens; (result, summary)."""
    p = start_hil(pamsim, link, out, "--force", *args)
    board = None
    if controller:
        time.sleep(0.3)
        board = subprocess.Popen(controller, stderr=subprocess.DEVNULL)
    out_text, err = p.communicate(timeout=timeout)
    if board:
        board.wait(timeout=30)
    summary = None
    if os.path.exists(os.path.join(out, "summary.json")):
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    return p.returncode, err, summary


def export_controller(pamsim, out):
    folder = os.path.join(out, "ctl")
    subprocess.run(
        [pamsim, "controller", "export", SCENARIO, "-o", folder], check=True, capture_output=True
    )
    subprocess.run(["make", "-s", "-C", folder], check=True, capture_output=True)
    return os.path.join(folder, "build", "pamctl_hil")


def check_exact(pamsim, out, board):
    run = os.path.join(out, "run")
    subprocess.run(
        [pamsim, "run", SCENARIO, "--out", run, "--no-plot"], check=True, capture_output=True
    )
    port = free_port()
    udp = os.path.join(out, "udp")
    rc, err, summary = hil(
        pamsim,
        udp,
        ["--udp", f"127.0.0.1:{port}"],
        controller=[board, "--udp", f"127.0.0.1:{port}"],
    )
    assert rc == 0, err
    assert read(os.path.join(udp, "trajectory.csv")) == read(os.path.join(run, "trajectory.csv"))
    assert summary["hil"]["missed_ticks"] == 0 and summary["hil"]["ticks"] == TICKS, summary["hil"]
    assert sorted(os.listdir(udp)) == OUTPUTS
    serial = os.path.join(out, "serial")
    rc, err, summary = with_pty(
        out, lambda a, b: hil(pamsim, serial, ["--serial", a], controller=[board, "--serial", b])
    )
    assert rc == 0, err
    assert read(os.path.join(serial, "trajectory.csv")) == read(os.path.join(run, "trajectory.csv"))
    return run


def with_pty(out, body):
    """`body(a, b)` with a socat pseudo-terminal pair a <-> b."""
    a, b = os.path.join(out, "ptyA"), os.path.join(out, "ptyB")
    socat = subprocess.Popen(
        ["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"], stderr=subprocess.DEVNULL
    )
    try:
        deadline = time.monotonic() + 10
        while not (os.path.exists(a) and os.path.exists(b)) and time.monotonic() < deadline:
            time.sleep(0.05)
        return body(a, b)
    finally:
        socat.terminate()
        socat.wait(timeout=10)


def applied(folder):
    with open(os.path.join(folder, "link.csv")) as f:
        return [row["applied"] for row in csv.DictReader(f)]


def check_drops(pamsim, out, board):
    trajectories = []
    for k in range(2):
        port = free_port()
        folder = os.path.join(out, f"drop{k}")
        rc, err, summary = hil(
            pamsim,
            folder,
            ["--udp", f"127.0.0.1:{port}"],
            "--drop-fraction",
            "0.05",
            "--fault-seed",
            "3",
            controller=[board, "--udp", f"127.0.0.1:{port}"],
        )
        assert rc == 0, err
        h = summary["hil"]
        band = 3 * math.sqrt(TICKS * 0.05 * 0.95)  # the binomial's 3 sigma
        assert abs(h["dropped_by_fault"] - TICKS * 0.05) <= band, h
        assert h["missed_ticks"] == h["dropped_by_fault"] == h["held_ticks"] + h["vented_ticks"], h
        assert applied(folder).count("held") == h["held_ticks"]
        trajectories.append(read(os.path.join(folder, "trajectory.csv")))
    assert trajectories[0] == trajectories[1], "a faulty lockstep run is not repeatable"


def check_burst(pamsim, out, board):
    port = free_port()
    folder = os.path.join(out, "burst")
    rc, err, summary = hil(
        pamsim,
        folder,
        ["--udp", f"127.0.0.1:{port}"],
        "--drop-burst",
        "100:20",
        controller=[board, "--udp", f"127.0.0.1:{port}"],
    )
    assert rc == 0, err
    kinds = applied(folder)
    assert kinds[100:103] == ["held"] * 3 and kinds[103:120] == ["vented"] * 17, kinds[95:125]
    assert kinds[120] == "board"
    with open(os.path.join(folder, "trajectory.csv")) as f:
        rows = list(csv.DictReader(f))
    assert all(float(rows[t]["p_cmd_ago_MPa"]) == 0.0 for t in range(103, 120))


def check_corruption(pamsim, out, board):
    folder = os.path.join(out, "corrupt")
    rc, err, summary = with_pty(
        out,
        lambda a, b: hil(
            pamsim,
            folder,
            ["--serial", a],
            "--corrupt-fraction",
            "0.003",
            controller=[board, "--serial", b],
        ),
    )
    assert rc == 0, err
    h = summary["hil"]
    assert h["bad_checksum"] > 0 and h["missed_ticks"] > 0, h
    assert sorted(os.listdir(folder)) == OUTPUTS


def check_killed(pamsim, out, board):
    port = free_port()
    folder = os.path.join(out, "killed")
    p = start_hil(
        pamsim,
        ["--udp", f"127.0.0.1:{port}"],
        folder,
        *["--set", "hil.link_lost_s=0.5", "--set", "hil.command_timeout_ms=50"],
        *["--set", "sim.duration_s=300", "--set", "drop.time_s=1"],
    )
    time.sleep(0.3)
    controller = subprocess.Popen([board, "--udp", f"127.0.0.1:{port}"])
    time.sleep(1.0)
    controller.send_signal(signal.SIGKILL)
    controller.wait(timeout=10)
    err = p.communicate(timeout=60)[1]
    assert p.returncode == 5, (p.returncode, err)
    assert "no packet from the controller" in err.strip().splitlines()[-1], err
    assert sorted(os.listdir(folder)) == OUTPUTS
    kinds = applied(folder)
    first_miss = kinds.index("held")
    assert kinds[first_miss : first_miss + 3] == ["held"] * 3 and kinds[-1] == "vented", kinds[-15:]
    with open(os.path.join(folder, "trajectory.csv")) as f:
        assert len(list(csv.DictReader(f))) == len(kinds) - 1  # up to the tick it ended


def check_bad_input(pamsim, out):
    def refused(args, expected):
        r = subprocess.run(
            [
                pamsim,
                "hil",
                SCENARIO,
                "--out",
                os.path.join(out, "never"),
                "--connect-timeout-s",
                "5",
                *args,
            ],
            capture_output=True,
            text=True,
            timeout=60,
        )
        lines = r.stderr.strip().splitlines()
        assert r.returncode == 2 and len(lines) == 1 and expected in lines[0], (args, r.stderr)
        assert not os.path.exists(os.path.join(out, "never")), args

    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as taken:
        taken.bind(("127.0.0.1", 0))
        refused(["--udp", f"127.0.0.1:{taken.getsockname()[1]}"], "cannot listen there")
    refused(["--serial", "/dev/no_such_tty"], "--serial /dev/no_such_tty: cannot open it")
    refused(["--udp", "127.0.0.1:1", "--drop-fraction", "1.5"], "--drop-fraction must be in [0, 1]")
    # a peer whose hello is of pamhil version 9
    port = free_port()
    hello = bytearray(struct.pack("<BBBBBBBBIId", 0xA5, 0x5A, 9, 2, 0, 2, 0, 0, 0, 0xFFFFFFFF, 0.0))
    hello += bytes(16) + b"\0\0"
    p = start_hil(pamsim, ["--udp", f"127.0.0.1:{port}"], os.path.join(out, "never"))
    time.sleep(0.3)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.sendto(bytes(hello), ("127.0.0.1", port))
    err = p.communicate(timeout=30)[1]
    assert p.returncode == 2 and "another pamhil version" in err, err


def main():
    pamsim, out = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    board = export_controller(pamsim, out)
    check_exact(pamsim, out, board)
    check_drops(pamsim, out, board)
    check_burst(pamsim, out, board)
    check_corruption(pamsim, out, board)
    check_killed(pamsim, out, board)
    check_bad_input(pamsim, out)
    print("hil_test: every check holds")


if __name__ == "__main__":
    main()
