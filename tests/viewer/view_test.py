#!/usr/bin/env python3
"""view_test.py PAMSIM OUT: `pamsim view` on a virtual display (Debian's Xvfb), driven by
--script. One scripted session of the falling mass: the window draws the arm as `pamsim render`
draws the frame at the same time (the scene's middle, where the arm moves, within a mean
absolute difference of MAX_MEAN_DIFF of 255 per channel: the same renderer, once on GLX and
once on OSMesa); a scripted pause holds the state (two screenshots 0.4 s of wall time apart are
the same); a scripted drop drops the mass (the impact follows the drop by the free fall of
0.14 m, not the scenario's own drop time); a slider move to a lower threshold gives the trigger
time of the trial with that threshold from the start, not the default's; the record is a folder
that `pamsim run --from` runs again byte for byte. The viewer exits 0 on a scripted close, and
on SIGTERM with the signal's code, its record complete. Bad input (a script's bad line, a bad
value, a scenario that cannot run, no display) is one line and exit 2 with nothing written.
Exit 0 when every check holds.

    python3 tests/viewer/view_test.py build/src/sim/pamsim /tmp/view_test
"""

import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from virtual_display import VirtualDisplay  # noqa: E402

try:
    import numpy as np
    from PIL import Image
except ModuleNotFoundError:  # Debian's python3-pil serves /usr/bin/python3 alone
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
    raise

SCENARIO = "scenarios/drop_mass.toml"
SCENE_W, SCENE_H = 1280, 720  # the scene's pixels, as render's frame (viewer_window.h)
MIDDLE = (slice(120, 620), slice(320, 1080))  # rows, columns of the frame clear of overlays
MAX_MEAN_DIFF = 2.0
DROP_S, SET_S, THRESHOLD = 0.8, 0.6, 40
FALL_S = math.sqrt(2 * 0.14 / 9.81)  # 0.169 s: the mass's fall into the basket

SESSION = """# the falling mass, watched
0.5 pause
0.5 screenshot {out}/paused_a.png
0.5 wait 0.4
0.5 screenshot {out}/paused_b.png
0.5 play
{set_s} set reflex.v_thr_mm_s {threshold}
{drop_s} drop
1.6 close
"""


def viewer_env(env):
    """`env` for a viewer's process. Under `make sanitize`, GLFW loads the GL driver with
    dlopen and unloads it on exit, leaving blocks LeakSanitizer cannot name (an unloaded
    module): the window's process is checked for memory errors but not leaks there; the
    viewer's own code is leak-checked by tests/sim/view and tests/sim/core, with no window."""
    if "ASAN_OPTIONS" not in env:
        return env
    return dict(env, ASAN_OPTIONS=env["ASAN_OPTIONS"] + ":detect_leaks=0")


def view(pamsim, env, *args, timeout=120):
    env = viewer_env(env)
    return subprocess.run(
        [pamsim, "view", SCENARIO, *args], env=env, capture_output=True, text=True, timeout=timeout
    )


def metrics(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def scene_of_screenshot(path):
    """The scene region of a window's screenshot: right of the UI, above the figures."""
    image = np.asarray(Image.open(path).convert("RGB"), dtype=np.int16)
    return image[:SCENE_H, image.shape[1] - SCENE_W :]


def check_session(pamsim, env, out):
    script = os.path.join(out, "session.txt")
    with open(script, "w") as f:
        f.write(SESSION.format(out=out, set_s=SET_S, threshold=THRESHOLD, drop_s=DROP_S))
    record = os.path.join(out, "record")
    done = view(pamsim, env, "--script", script, "--record", record)
    assert done.returncode == 0, done.stderr
    assert "frames/s" in done.stderr, done.stderr
    a = scene_of_screenshot(os.path.join(out, "paused_a.png"))
    b = scene_of_screenshot(os.path.join(out, "paused_b.png"))
    assert np.array_equal(a, b), "the paused state moved"
    # render's frame at t = 0.5 (10 frames per second: frame 5)
    frames = os.path.join(out, "frames")
    subprocess.run(
        [
            pamsim,
            "render",
            SCENARIO,
            "--png-dir",
            frames,
            "--fps",
            "10",
            "--set",
            "sim.duration_s=1.2",
            "--quiet",
        ],
        check=True,
        capture_output=True,
    )
    frame = np.asarray(
        Image.open(os.path.join(frames, "frame_00005.png")).convert("RGB"), dtype=np.int16
    )
    diff = float(np.abs(a[MIDDLE] - frame[MIDDLE]).mean())
    print(f"view_test: scene against render's frame at 0.5 s: mean |difference| {diff:.2f}")
    assert diff <= MAX_MEAN_DIFF, diff
    return record


def check_record(pamsim, out, record):
    got = metrics(record)
    impact = got["impact_time_s"]
    assert DROP_S < impact < DROP_S + FALL_S + 0.05, impact  # not the scenario's 1.0 s
    rerun = os.path.join(out, "rerun")
    subprocess.run(
        [pamsim, "run", "--from", record, "--out", rerun, "--no-plot"],
        check=True,
        capture_output=True,
    )
    with (
        open(os.path.join(record, "trajectory.csv"), "rb") as f1,
        open(os.path.join(rerun, "trajectory.csv"), "rb") as f2,
    ):
        assert f1.read() == f2.read(), "run --from differs from the record"

    # the threshold the slider gave is the next trigger's
    def trigger(folder, threshold):
        subprocess.run(
            [
                pamsim,
                "run",
                SCENARIO,
                "--out",
                folder,
                "--no-plot",
                "--set",
                f"drop.time_s={DROP_S}",
                "--set",
                f"reflex.v_thr_mm_s={threshold}",
                "--set",
                "sim.duration_s=1.6",
            ],
            check=True,
            capture_output=True,
        )
        return metrics(folder)["first_trigger_time_s"]

    lowered, default = (
        trigger(os.path.join(out, "low"), THRESHOLD),
        trigger(os.path.join(out, "default"), 70),
    )
    assert got["first_trigger_time_s"] == lowered != default, (got, lowered, default)


def check_sigterm(pamsim, env, out):
    script = os.path.join(out, "held.txt")
    shot = os.path.join(out, "held.png")
    with open(script, "w") as f:
        f.write(f"0.2 pause\n0.2 screenshot {shot}\n0.2 wait 60\n")
    record = os.path.join(out, "held")
    p = subprocess.Popen(
        [pamsim, "view", SCENARIO, "--script", script, "--record", record],
        env=viewer_env(env),
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 60
    while not os.path.exists(shot) and time.monotonic() < deadline and p.poll() is None:
        time.sleep(0.1)
    p.send_signal(signal.SIGTERM)
    err = p.communicate(timeout=30)[1]
    assert p.returncode == 128 + signal.SIGTERM, (p.returncode, err)
    files = sorted(os.listdir(record))
    assert files == [
        "provenance.json",
        "scenario.toml",
        "summary.json",
        "trajectory.csv",
        "view_changes.json",
    ], files


def check_bad_input(pamsim, env, out):
    cases = {
        "a bad line": ("0.1 pause\n0.5 jump\n", [], "bad.txt:2: unknown command 'jump'"),
        "a bad value": ("0.1 set reflex.v_thr_mm_s -5\n", [], "bad.txt:1"),
        "a fixed key": ("0.1 set reflex.sensor 1\n", [], "cannot change during a trial"),
        "a scenario that cannot run": (
            "0.1 pause\n",
            ["--set", "sim.timestep_s=-1"],
            "sim.timestep_s",
        ),
    }
    record = os.path.join(out, "never")
    for what, (text, extra, expected) in cases.items():
        script = os.path.join(out, "bad.txt")
        with open(script, "w") as f:
            f.write(text)
        r = view(pamsim, env, "--script", script, "--record", record, *extra)
        lines = r.stderr.strip().splitlines()
        assert r.returncode == 2 and len(lines) == 1 and expected in lines[0], (what, r.stderr)
        assert not os.path.exists(record), what
    no_display = {k: v for k, v in env.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    r = view(pamsim, no_display, "--record", record)
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1 and "pamsim render" in lines[0], r.stderr
    assert not os.path.exists(record)


def main():
    pamsim, out = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with VirtualDisplay() as env:
        record = check_session(pamsim, env, out)
        check_record(pamsim, out, record)
        check_sigterm(pamsim, env, out)
        check_bad_input(pamsim, env, out)
    print("view_test: every check holds")


if __name__ == "__main__":
    main()
