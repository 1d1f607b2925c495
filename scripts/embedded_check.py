#!/usr/bin/env python3
"""embedded_check.py: the exported controller (`pamsim controller export`) built outside
pamsim, as a lab would build it, held to the simulator's own commands (docs/embedded.md).

  a. trials: each trial's `pamsim run --readings`, its export built in a temporary folder
     with gcc and clang (double) and gcc -DPAMCTL_FLOAT (float), each replaying the trial's
     readings.csv: the double builds' commands must equal pamsim's bit for bit; the float
     build's largest command difference and its trigger ticks against the double build's
     (each differing tick with its margin in double: v - v_thr, or f - f_thr for Ib);
  b. a user's build: a short `pamsim tune` of tune_reflex.toml, its best.toml exported and
     run, built with the export's own Makefile and with its CMakeLists.txt;
  c. microcontrollers: `make lib` with arm-none-eabi-gcc for a Cortex-M4 (float) and a
     Cortex-M7 (double) at 2 and 8 muscles: flash and RAM (arm-none-eabi-size), the board's
     state (example_loop.o's .bss) and pamctl_tick's deepest stack (-fcallgraph-info=su);
  d. another processor: the replay built with arm-linux-gnueabihf-gcc, run under qemu-arm;
then writes OUT/embedded.md. Exit 0 when every build ran and every double build's commands
equal pamsim's, 1 otherwise. Needs make, cmake, gcc, clang, gcc-arm-none-eabi,
gcc-arm-linux-gnueabihf and qemu-user; runs one compile at a time.

    python3 scripts/embedded_check.py --pamsim build/src/sim/pamsim --out build/embedded
    python3 scripts/embedded_check.py --pamsim build/src/sim/pamsim --out DIR --quick
(--quick: drop_mass and landing_reflex only, and the user's build of drop_mass.toml, no tune)
"""

import argparse
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib

from embedded_report import write_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIDES = ("agonist", "antagonist")
# (name, what it checks, scenario, estimator law fitted for it or None)
TRIALS = [
    ("drop_mass", "model reflex", "drop_mass.toml", None),
    ("drop_mass_fiber", "fiber reflex", "drop_mass_fiber.toml", None),
    ("drop_mass_heavy_ia_ib", "Ia and Ib reflexes", "drop_mass_heavy_ia_ib.toml", None),
    ("landing_reflex", "the leg, 8 muscles", "landing_reflex.toml", None),
    ("drop_mass_eq4", "Eq. (4) estimator", "drop_mass.toml", "eq4"),
    ("drop_mass_eq5", "Eq. (5) estimator", "drop_mass.toml", "eq5"),
]
QUICK = ("drop_mass", "landing_reflex")
ARM_FLAGS = {
    "Cortex-M4": "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard",
    "Cortex-M7": "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard",
}
# (processor, float build, MAX_MUSCLES, the trial whose export it builds)
BOARDS = [
    ("Cortex-M4", True, 2, "drop_mass"),
    ("Cortex-M4", True, 8, "landing_reflex"),
    ("Cortex-M7", False, 2, "drop_mass"),
    ("Cortex-M7", False, 8, "landing_reflex"),
]
TOOLS = (
    "make",
    "cmake",
    "gcc",
    "clang",
    "arm-none-eabi-gcc",
    "arm-none-eabi-ar",
    "arm-none-eabi-size",
    "arm-linux-gnueabihf-gcc",
    "arm-linux-gnueabihf-ar",
    "qemu-arm",
)
REPLAY_LINE = re.compile(
    r"ticks (\d+), (?:(commands equal)|first differing tick (\d+), "
    r"largest difference (\S+) Pa)"
)


class Failed(Exception):
    """A command that failed: one line naming it, and its compiler errors if any."""


def run(cmd, cwd=ROOT, ok=(0,)):
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    if done.returncode not in ok:
        errors = [line for line in (done.stderr + done.stdout).splitlines() if "error" in line]
        tail = errors or (done.stderr or done.stdout).strip().splitlines()[-3:]
        raise Failed(f"`{' '.join(cmd)}` failed ({done.returncode}): " + " | ".join(tail))
    return done


def make(export, build, *variables, target=None):
    """The export's Makefile with make variables `variables` ("CC=clang"), into `build`."""
    return run(
        ["make", "-C", export, f"BUILD={build}"] + ([target] if target else []) + list(variables)
    )


def replay(command, readings, out_csv):
    """(equal, ticks, first differing tick or None, largest difference [Pa]) of a replay
    program's comparison with readings.csv's commands."""
    done = run(command + [readings, out_csv], ok=(0, 1))
    m = REPLAY_LINE.search(done.stderr)
    if not m:
        raise Failed(f"`{' '.join(command)}`: no comparison line ({done.stderr.strip()})")
    if m.group(2):
        return {"equal": True, "ticks": int(m.group(1)), "tick": None, "largest_pa": 0.0}
    return {
        "equal": False,
        "ticks": int(m.group(1)),
        "tick": int(m.group(3)),
        "largest_pa": float(m.group(4)),
    }


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [r[k] for r in rows[1:]] for k, name in enumerate(rows[0])}


def fit_estimators(pamsim, work, law):
    """`--set` overrides that make the estimator the `law` fitted to a noisy tensile test of
    each plant (the fitted files in `work`)."""
    sets = []
    for side in SIDES:
        data = os.path.join(work, f"tensile_{side}.csv")
        if not os.path.isfile(data):
            run(
                [
                    pamsim,
                    "tensile",
                    "--plant",
                    f"models/pams/plant_{side}.toml",
                    "--pressures-MPa",
                    "0.2,0.3,0.4,0.5,0.6,0.7",
                    "--max-deformation-mm",
                    "15",
                    "--noise-pressure-MPa",
                    "0.001",
                    "--noise-force-N",
                    "0.05",
                    "--noise-length-mm",
                    "0.01",
                    "--seed",
                    "1",
                    "-o",
                    data,
                    "--force",
                ]
            )
        fitted = os.path.join(work, f"{side}_{law}.toml")
        run(
            [
                pamsim,
                "fit",
                "--model",
                law,
                data,
                "--sensors-from",
                f"models/pams/table4_{side}.toml",
                "-o",
                fitted,
                "--force",
            ]
        )
        sets += ["--set", f"model.{side}_params={fitted}"]
    return sets


def triggers(columns, names):
    """{(muscle, "Ia" | "Ib", tick)} of a replay's out.csv."""
    found = set()
    for m in names:
        for kind, column in (("Ia", f"trigger_{m}"), ("Ib", f"tension_trigger_{m}")):
            found |= {(m, kind, t) for t, x in enumerate(columns[column]) if x == "1"}
    return found


def margin(kind, muscle, tick, config, double, readings):
    """How far the double build was from the threshold at a tick where the float build's
    trigger differs: v - v_thr [mm/s] (Ia), or Eq. (9)'s f - f_thr [N] (Ib)."""
    reflex = config["reflex"]
    if kind == "Ia":
        v = float(double[f"velocity_{muscle}_m_s"][tick])
        return f"v - v_thr = {(v - reflex['ia']['v_thr_m_s']) * 1e3:+.6g} mm/s"
    f = eq9_force(config, muscle, readings[f"gauge_{muscle}_V"][tick])
    rate = " (the rate trigger is on too)" if reflex["ib"]["df_thr_n_s"] > 0 else ""
    return f"f - f_thr = {f - reflex['ib']['f_thr_n']:+.6g} N{rate}"


def float_against_double(double_csv, float_csv, readings_csv, config):
    double, single = read_columns(double_csv), read_columns(float_csv)
    readings = read_columns(readings_csv)
    names = config["muscle_names"]
    largest = max(
        abs(float(a) - float(b))
        for m in names
        for a, b in zip(double[f"p_cmd_{m}_Pa"], single[f"p_cmd_{m}_Pa"], strict=False)
    )
    moved = max(
        abs(float(a) - float(b))
        for m in names
        for a, b in zip(double[f"velocity_{m}_m_s"], single[f"velocity_{m}_m_s"], strict=False)
        if math.isfinite(float(a) - float(b))
    )
    in_double, in_float = triggers(double, names), triggers(single, names)
    differing = [
        {
            "muscle": m,
            "kind": k,
            "tick": t,
            "time_s": float(double["time_s"][t]),
            "in": "double" if (m, k, t) in in_double else "float",
            "margin": margin(k, m, t, config, double, readings),
        }
        for m, k, t in sorted(in_double ^ in_float, key=lambda x: (x[2], x[0]))
    ]
    return {
        "largest_kpa": largest / 1e3,
        "velocity_mm_s": moved * 1e3,
        "double_triggers": len(in_double),
        "differing": differing,
        "closest": closest(config, double, readings),
    }


def closest(config, double, readings):
    """The double build's nearest approach to each threshold over every tick and muscle:
    min |v - v_thr| [mm/s] and min |f - f_thr| [N] (Eq. (9)), for the reflexes it runs."""
    reflex, names, found = config["reflex"], config["muscle_names"], {}
    if reflex["stretch"]:
        found["Ia"] = finite_min(
            abs(float(v) - reflex["ia"]["v_thr_m_s"]) * 1e3
            for m in names
            for v in double[f"velocity_{m}_m_s"]
        )
    if reflex["tension"]:
        found["Ib"] = finite_min(
            abs(eq9_force(config, m, g) - reflex["ib"]["f_thr_n"])
            for m in names
            for g in readings[f"gauge_{m}_V"]
        )
    return found


def finite_min(values):
    return min((x for x in values if math.isfinite(x)), default=math.nan)


def eq9_force(config, muscle, gauge_v):
    gauge = config["muscles"][config["muscle_names"].index(muscle)]
    return (float(gauge_v) - gauge["gauge_v_base_v"]) / gauge["gauge_q_v_per_n"]


def reflexes(config):
    """The reflexes an export runs, in words."""
    r = config["reflex"]
    parts = ["Ia (" + ("fiber" if r["sensor"] == 1 else "model") + ")"] if r["stretch"] else []
    return " + ".join(parts + (["Ib"] if r["tension"] else [])) or "none"


def check_trial(pamsim, work, trial):
    name, what, scenario, law = trial
    where = os.path.join(work, name)
    sets = fit_estimators(pamsim, work, law) if law else []
    run(
        [
            pamsim,
            "run",
            f"scenarios/{scenario}",
            "--readings",
            "--no-plot",
            "--out",
            os.path.join(where, "run"),
        ]
        + sets
    )
    export = os.path.join(where, "export")
    run([pamsim, "controller", "export", f"scenarios/{scenario}", "-o", export] + sets)
    readings = os.path.join(where, "run", "readings.csv")
    with open(os.path.join(export, "pamctl_config.json")) as f:
        config = json.load(f)
    result = {
        "name": name,
        "what": what,
        "scenario": scenario,
        "law": law,
        "export": export,
        "readings": readings,
        "muscles": config["muscle_count"],
        "reflexes": reflexes(config),
    }
    for build, variables in (
        ("gcc", ["CC=gcc"]),
        ("clang", ["CC=clang"]),
        ("float", ["CC=gcc", "FLOAT=1"]),
    ):
        make(export, os.path.join(where, build), *variables)
        result[build] = replay(
            [os.path.join(where, build, "pamctl_replay")],
            readings,
            os.path.join(where, f"{build}.csv"),
        )
    with open(os.path.join(where, "gcc.csv")) as a, open(os.path.join(where, "clang.csv")) as b:
        result["gcc_is_clang"] = a.read() == b.read()
    result["float_vs_double"] = float_against_double(
        os.path.join(where, "gcc.csv"), os.path.join(where, "float.csv"), readings, config
    )
    return result


def short_tuning(pamsim, work):
    """tune_reflex.toml cut to 2 generations and 2 held-out seeds, its base made absolute
    (as scripts/compare-outputs.sh makes it); returns its best.toml and the tuned keys."""
    with open("scenarios/tune_reflex.toml") as f:
        text = f.read()
    text = re.sub(r"(?m)^generations *=.*", "generations = 2", text)
    text = re.sub(r"(?m)^held_out_seeds *=.*", "held_out_seeds = 2", text)
    text = re.sub(
        r'(?m)^base *= *"(.*)"',
        lambda m: f'base = "{os.path.join(ROOT, "scenarios", m.group(1))}"',
        text,
    )
    tune = os.path.join(work, "tune_short.toml")
    with open(tune, "w") as f:
        f.write(text)
    out = os.path.join(work, "tune")
    run([pamsim, "tune", tune, "--threads", "2", "--quiet", "--no-plot", "--out", out])
    best = os.path.join(out, "best.toml")
    with open(best, "rb") as f:
        reflex = tomllib.load(f)["reflex"]
    return best, {k: reflex[k] for k in ("v_thr_mm_s", "k_MPa_s_per_mm") if k in reflex}


def users_build(pamsim, work, quick):
    """The export of a tuned scenario built as its user would: `make` in the folder (gcc and
    clang), and CMake."""
    where = os.path.join(work, "user")
    if quick:
        scenario, tuned = os.path.join(ROOT, "scenarios", "drop_mass.toml"), {}
    else:
        scenario, tuned = short_tuning(pamsim, work)
    export = os.path.join(where, "export")
    run([pamsim, "controller", "export", scenario, "-o", export])
    run([pamsim, "run", scenario, "--readings", "--no-plot", "--out", os.path.join(where, "run")])
    readings = os.path.join(where, "run", "readings.csv")
    run(["make", "-C", export])
    run(["make", "-C", export, "BUILD=build-clang", "CC=clang"])
    run(["cmake", "-S", export, "-B", os.path.join(export, "cmake-build")])
    run(["cmake", "--build", os.path.join(export, "cmake-build")])
    return {
        "scenario": "drop_mass.toml" if quick else "best.toml of a short tune",
        "tuned": tuned,
        "make": replay(
            [os.path.join(export, "build", "pamctl_replay")],
            readings,
            os.path.join(where, "make.csv"),
        ),
        "make_clang": replay(
            [os.path.join(export, "build-clang", "pamctl_replay")],
            readings,
            os.path.join(where, "make_clang.csv"),
        ),
        "cmake": replay(
            [os.path.join(export, "cmake-build", "pamctl_replay")],
            readings,
            os.path.join(where, "cmake.csv"),
        ),
    }


def call_graph(build):
    """{title: (name, stack bytes or None for a function defined elsewhere, qualifier)} and
    {title: [callee titles]} of the .ci files (VCG) in `build`."""
    nodes, edges = {}, {}
    node = re.compile(
        r'node: \{ title: "([^"]+)" label: "([^"\\]+)(?:\\n[^"]*?)?'
        r'(?:\\n(\d+) bytes \(([\w,]+)\))?"'
    )
    edge = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    for name in sorted(os.listdir(build)):
        if not name.endswith(".ci"):
            continue
        with open(os.path.join(build, name)) as f:
            for line in f:
                if m := node.match(line):
                    if m.group(3) is not None or m.group(1) not in nodes:
                        nodes[m.group(1)] = (m.group(2), m.group(3) and int(m.group(3)), m.group(4))
                elif m := edge.match(line):
                    edges.setdefault(m.group(1), [])
                    if m.group(2) not in edges[m.group(1)]:
                        edges[m.group(1)].append(m.group(2))
    return nodes, edges


def deepest(title, nodes, edges, seen=()):
    """(bytes, path of (name, bytes or None)) of the deepest call chain from `title` (of two
    as deep, the longer: it shows the external call at its end); an external function counts
    0 bytes, a cycle stops the chain (the library has none)."""
    name, size, _ = nodes.get(title, (title, None, None))
    best = (0, [])
    for callee in edges.get(title, []):
        if callee not in seen:
            best = max(
                best,
                deepest(callee, nodes, edges, seen + (title,)),
                key=lambda b: (b[0], len(b[1])),
            )
    return (size or 0) + best[0], [(name, size)] + best[1]


def arm_size(archive_or_object, total=True):
    out = run(["arm-none-eabi-size", "-t" if total else "-A", archive_or_object]).stdout
    if total:
        text, data, bss = (int(x) for x in out.strip().splitlines()[-1].split()[:3])
        return {"text": text, "data": data, "bss": bss}
    return {
        s[0]: int(s[1])
        for s in (line.split() for line in out.splitlines())
        if len(s) >= 2 and s[0].startswith(".") and s[1].isdigit()
    }


def board_build(work, trials, board):
    processor, single, muscles, trial = board
    export = trials[trial]["export"]
    build = os.path.join(work, "boards", f"{processor}_{muscles}")
    result = {
        "processor": processor,
        "precision": "float" if single else "double",
        "max_muscles": muscles,
        "trial": trial,
    }
    try:
        make(
            export,
            build,
            "CC=arm-none-eabi-gcc",
            "AR=arm-none-eabi-ar",
            f"MAX_MUSCLES={muscles}",
            f"TARGET_FLAGS={ARM_FLAGS[processor]}",
            "EXTRA_CFLAGS=-fstack-usage -fcallgraph-info=su",
            *(["FLOAT=1"] if single else []),
            target="lib",
        )
    except Failed as e:
        return {**result, "error": str(e).replace(work, "TMP")}
    lib = arm_size(os.path.join(build, "libpamctl.a"))
    loop = arm_size(os.path.join(build, "example_loop.o"), total=False)
    nodes, edges = call_graph(build)
    stack, path = deepest("pamctl_tick", nodes, edges)
    dynamic = sorted({q for _, _, q in nodes.values() if q and "dynamic" in q})
    return {
        **result,
        "flash": lib["text"] + lib["data"],
        "lib_ram": lib["data"] + lib["bss"],
        "state_ram": loop.get(".bss", 0) + loop.get(".data", 0),
        "stack": stack,
        "path": path,
        "dynamic": dynamic,
    }


def qemu_replay(work, trial):
    """drop_mass's export built for ARMv7-A Linux (static) and replayed under qemu-arm."""
    build = os.path.join(work, "qemu")
    make(
        trial["export"],
        build,
        "CC=arm-linux-gnueabihf-gcc",
        "AR=arm-linux-gnueabihf-ar",
        "LDFLAGS=-static",
    )
    out = os.path.join(work, "qemu.csv")
    result = replay(
        ["qemu-arm", "-L", "/usr/arm-linux-gnueabihf", os.path.join(build, "pamctl_replay")],
        trial["readings"],
        out,
    )
    if not result["equal"]:  # where it first moved: an estimate or only a command
        host, arm = read_columns(os.path.join(work, trial["name"], "gcc.csv")), read_columns(out)
        result["first_column"] = next(
            ((t, c) for t in range(len(host["tick"])) for c in host if host[c][t] != arm[c][t]),
            None,
        )
    return result


def versions():
    found = {}
    for tool in ("gcc", "clang", "arm-none-eabi-gcc", "arm-linux-gnueabihf-gcc", "qemu-arm"):
        if shutil.which(tool):
            first = run([tool, "--version"]).stdout.splitlines()[0]
            found[tool] = re.search(r"\d+\.\d+(\.\d+)?", first.split(")")[-1] or first).group(0)
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pamsim", default="build/src/sim/pamsim")
    ap.add_argument("--out", required=True, help="folder for embedded.md")
    ap.add_argument("--quick", action="store_true", help="a subset (no tune, 2 trials)")
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder")
    args = ap.parse_args()
    pamsim, out = os.path.abspath(args.pamsim), os.path.abspath(args.out)
    os.chdir(ROOT)
    missing = [t for t in TOOLS if not shutil.which(t)]
    if missing or not os.access(pamsim, os.X_OK):
        sys.exit(
            f"embedded_check: not found: {', '.join(missing or [pamsim])} "
            f"(scripts/install-deps.sh installs the compilers and qemu-user)"
        )
    started = time.time()
    work = tempfile.mkdtemp(prefix="embedded_check_")
    try:
        trials = {}
        for trial in TRIALS:
            if not args.quick or trial[0] in QUICK:
                trials[trial[0]] = check_trial(pamsim, work, trial)
                print(f"embedded_check: {trial[0]} done", flush=True)
        user = users_build(pamsim, work, args.quick)
        boards = [board_build(work, trials, b) for b in BOARDS]
        qemu = qemu_replay(work, trials["drop_mass"])
    except Failed as e:
        sys.exit(
            f"embedded_check: {e}"
            + (f" (in {work})" if args.keep else " (--keep keeps the temporary folder)")
        )
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    passed = write_report(
        os.path.join(out, "embedded.md"),
        list(trials.values()),
        user,
        boards,
        qemu,
        versions(),
        ARM_FLAGS,
    )
    print(
        f"embedded_check: wrote {os.path.join(out, 'embedded.md')} in "
        f"{time.time() - started:.0f} s; "
        + ("every double build equal" if passed else "FAILED: see the report")
    )
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
