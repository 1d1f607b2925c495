#!/usr/bin/env python3
"""identify_coverage.py: does `pamsim identify` know how sure it is? Identifies N synthetic
arms whose truth is known and counts how often each stated interval contains it.

Each arm is examples/identify/arm.toml with its own truth, drawn (seeded) from the ranges of
its family (identify_families.py: `example`, the worked example's walls, damping and dead
time; `harder`, friction and the regulator's valve), a noise seed of its own, and instruments
of its own: a zero error of each of the family's instruments, added to what the lab's logger
keeps (make_recordings.py's logger: its channels, rate and 5 significant digits). The
identification fits every parameter and offset from the model's values (the model's trials
without noise and with ideal ADCs, the worked example's overrides; the recordings' and the
model's chamber solver at arm.toml's tight tolerance, their contacts at arm.toml's soft onset
or --contact-onset-mm's), and each arm's identify.csv gives its
value, standard error (HAC), plain standard error, interval and verdict; the summary counts
the arms explained, those whose search "did not settle", and the wall time of each. A control
arm whose encoder is read 60 ms late (a delay the model lacks) must come out "does not explain".

    python3 scripts/identify_coverage.py [--family example|harder] [--arms 20] [--seed 1]
        [--threads 2] [--starts N] [--runs N] [--stall-generations N] [--generations N]
        [--population N] [--searched-offsets] [--contact-onset-mm MM] [--only 6,8]
        [--pamsim build/src/sim/pamsim]
        [--out renders/identify_coverage[_harder]]

writes OUT/coverage.csv (one row per arm and parameter) and OUT/coverage.md (the summary the
docs show); an interrupted run started again skips the arms it finished and resumes the one
it was in (each arm's identify.db). About a minute per arm on 2 cores.
"""

import argparse
import csv
import math
import os
import random
import shutil
import subprocess
import sys
import time
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "examples", "identify"))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import make_recordings  # noqa: E402  (the example's logger: channels, rates, a gap)
from identify_families import FAMILIES  # noqa: E402

# the family's parameters, instruments, recordings and search (identify_families.py), set by
# main from --family
TRUTH_RANGES, OFFSET_RANGES, RECORDINGS, SEARCH = {}, {}, {}, {}
# the identification file's search keys a run may set (--starts, --runs, ...)
SEARCH_OPTIONS = (
    "starts",
    "runs",
    "stall_generations",
    "generations",
    "population",
    "polish_iterations",
)
# the model predicts the expected reading as the worked example's does, with its overrides
# (no noise of its own, ideal ADCs: its identify.toml says why); its solver's tolerance is
# arm.toml's
with open(os.path.join(ROOT, "examples", "identify", "identify.toml"), "rb") as _f:
    MODEL_OVERRIDES = tomllib.load(_f)["overrides"]
CONTROL_DELAY_S = 0.06
# --contact-onset-mm: sim.contact_soft_onset_mm for the arms and the model alike (unset:
# arm.toml's)
CONTACT = []


def draw_arm(rng):
    """One arm's truth: {key: value} and {channel: offset}."""
    truth = {}
    for key, ((lo, hi), _, scale) in TRUTH_RANGES.items():
        u = rng.random()
        truth[key] = lo * (hi / lo) ** u if scale == "log" else lo + (hi - lo) * u
    offsets = {c: lo + (hi - lo) * rng.random() for c, ((lo, hi), _) in OFFSET_RANGES.items()}
    return truth, offsets


def toml_list(items):
    return "[" + ", ".join("'" + s + "'" for s in items) + "]"


def identify_text(noise_seed):
    lines = [f'base = "{os.path.join(ROOT, "examples", "identify", "arm.toml")}"']
    lines += [f"{k} = {v}" for k, v in SEARCH.items()]
    lines += ["seed = 1", "overrides = " + toml_list(MODEL_OVERRIDES + CONTACT), ""]
    for key, (_, (lo, hi), scale) in TRUTH_RANGES.items():
        lines += [
            "[[parameter]]",
            f'key = "{key}"',
            f"from = {lo}",
            f"to = {hi}",
            f'scale = "{scale}"',
            "",
        ]
    for channel, (_, (lo, hi)) in OFFSET_RANGES.items():
        lines += [
            "[[parameter]]",
            f'key = "channel.{channel}.offset"',
            f"from = {lo}",
            f"to = {hi}",
            "",
        ]
    for name, (sets, _, _, held_out) in RECORDINGS.items():
        lines += [
            "[[recording]]",
            f'file = "{name}.csv"',
            f"set = {toml_list(sets)}",
            f"held_out = {'true' if held_out else 'false'}",
            "",
        ]
    return "\n".join(lines)


def make_arm(pamsim, folder, truth, offsets, noise_seed, delays=None):
    """The arm's recordings and identification file in `folder` (kept if already there)."""
    os.makedirs(folder, exist_ok=True)
    sets = [f"{k}={v!r}" for k, v in truth.items()] + [f"seed={noise_seed}"] + CONTACT
    for name, (commands, channels, rate, _) in RECORDINGS.items():
        if not os.path.exists(os.path.join(folder, name + ".csv")):
            make_recordings.record(
                pamsim,
                name,
                commands,
                channels,
                rate,
                None,
                folder,
                truth=sets,
                offsets=offsets,
                delays=delays,
            )
    path = os.path.join(folder, "identify.toml")
    with open(path + ".tmp", "w") as f:
        f.write(identify_text(noise_seed))
    os.replace(path + ".tmp", path)
    return path


def identify(pamsim, path, threads):
    """Runs (or resumes) the identification; its output folder. A result or database of
    another identification file (other settings: --starts, --searched-offsets) is removed."""
    out = os.path.join(os.path.dirname(path), "result")
    made_from = os.path.join(out, "identify.toml")
    with open(path) as f:
        text = f.read()
    if os.path.exists(made_from):
        with open(made_from) as f:
            if f.read() != text:
                shutil.rmtree(out)
    if os.path.exists(os.path.join(out, "identify.csv")):
        return out
    os.makedirs(out, exist_ok=True)
    write_atomically(made_from, text)
    args = [
        pamsim,
        "identify",
        path,
        "--out",
        out,
        "--threads",
        str(threads),
        "--no-plot",
        "--quiet",
    ]
    fresh = not os.path.exists(os.path.join(out, "identify.db"))
    if not fresh:
        args.append("--resume")
    start = time.monotonic()
    done = subprocess.run(args, stdout=subprocess.DEVNULL)
    if done.returncode != 0:  # pamsim said why on stderr; the arm's database is kept
        sys.exit(
            f"identify_coverage.py: pamsim identify {path} exited {done.returncode}; "
            "run the script again to resume"
        )
    # the wall time of an identification run from start to end (a resumed one's is partial)
    write_atomically(
        os.path.join(out, "seconds.txt"), f"{time.monotonic() - start:.1f}" if fresh else ""
    )
    return out


def seconds(out):
    """The arm's wall time in seconds, NaN where it is unknown (resumed, or older)."""
    try:
        with open(os.path.join(out, "seconds.txt")) as f:
            return float(f.read() or "nan")
    except (OSError, ValueError):
        return math.nan


def unsettled(rows):
    """Whether identify said the search did not settle (a verdict that blames the search)."""
    return any("the search did not settle" in r["verdict"] for r in rows)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def arm_rows(arm, out, truth, offsets, level_z):
    """One row per parameter: truth, value, both standard errors, inside, z, verdict."""
    known = dict(truth)
    known.update({f"channel.{c}.offset": v for c, v in offsets.items()})
    rows = []
    for p in read_csv(os.path.join(out, "identify.csv")):
        t, v = known[p["key"]], float(p["identified"])
        se, plain = float(p["std_error"] or "nan"), float(p["std_error_plain"] or "nan")
        lo, hi = float(p["interval_lo"] or "nan"), float(p["interval_hi"] or "nan")
        rows.append(
            {
                "arm": arm,
                "key": p["key"],
                "truth": t,
                "identified": v,
                "std_error": se,
                "std_error_plain": plain,
                "interval_lo": lo,
                "interval_hi": hi,
                "inside": int(lo <= t <= hi),
                "inside_plain": int(abs(v - t) <= level_z * plain),
                "z": abs(v - t) / se if se > 0 else math.nan,
                "verdict": p["verdict"],
            }
        )
    return rows


def explained(out):
    """Whether every fitted channel is explained, and the held-out angle RMSE before / after."""
    fits = read_csv(os.path.join(out, "identify_fits.csv"))
    fitted = all(f["explained"] == "1" for f in fits if f["held_out"] == "0")
    held = [f for f in fits if f["held_out"] == "1"]
    return fitted, float(held[0]["rmse_before"]), float(held[0]["rmse_after"])


def trusted(row):
    """The verdict "identified" (strongly correlated or not), the model explaining the
    recordings."""
    return row["verdict"].startswith("identified") and "not to be trusted" not in row["verdict"]


def median(values):
    v = sorted(x for x in values if math.isfinite(x))
    if not v:
        return math.nan
    mid = len(v) // 2
    return v[mid] if len(v) % 2 else 0.5 * (v[mid - 1] + v[mid])


def pct(n, d):
    return f"{n}/{d} ({100.0 * n / d:.0f} %)" if d else "-"


def summary(rows, arms, control, args):
    """coverage.md: per parameter and in all, against the claims the docs make."""
    keys = list(dict.fromkeys(r["key"] for r in rows))
    md = [
        f"# `pamsim identify`: coverage over {len(arms)} synthetic arms",
        "",
        f"`python3 scripts/identify_coverage.py {command_options(args)}`: "
        f"the {args.family} family; each arm's truth drawn from its ranges "
        "(scripts/identify_families.py), its recordings made by pamsim with a noise seed and "
        f"instruments of its own; {len(TRUTH_RANGES) + len(OFFSET_RANGES)} parameters "
        f"fitted per arm{search_text()}.",
        "",
        "| parameter | 95 % interval contains the truth | plain s^2 (J^T J)^-1 interval does "
        "| median width, interval / plain | largest error in standard errors where "
        '"identified" | "identified", the recordings explained |',
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for key in keys + ["all"]:
        rs = [r for r in rows if key in ("all", r["key"])]
        ident = [r for r in rs if trusted(r)]
        md.append(
            f"| `{key}` | {pct(sum(r['inside'] for r in rs), len(rs))} | "
            f"{pct(sum(r['inside_plain'] for r in rs), len(rs))} | "
            f"{median([r['std_error'] / r['std_error_plain'] for r in rs]):.2f} | "
            f"{max([r['z'] for r in ident], default=math.nan):.1f} | "
            f"{pct(len(ident), len(rs))} |"
        )
    far = sum(1 for r in rows if trusted(r) and r["z"] > 5)
    good = sum(1 for a in arms if a["explained"] and a["identified"])
    explained_arms = sum(a["explained"] for a in arms)
    times = [a["seconds"] for a in arms if math.isfinite(a["seconds"])]
    md += [
        "",
        f"- Parameter-arm pairs whose interval contains the truth: "
        f"{pct(sum(r['inside'] for r in rows), len(rows))} (claim: at least 90 %).",
        f'- "identified" but more than 5 standard errors from the truth: {far} (claim: none).',
        f'- Arms "explained" with every parameter "identified": {pct(good, len(arms))} '
        "(claim: at least 80 %).",
        f"- Arms whose fitted channels are all explained: {pct(explained_arms, len(arms))}; "
        f'"the search did not settle": {sum(a["unsettled"] for a in arms)}.',
        f"- Wall time per arm on {args.threads} threads: median {median(times):.0f} s, "
        f"largest {max(times, default=math.nan):.0f} s.",
        f"- Held-out angle RMSE, median over the arms: "
        f"{median([a['before'] for a in arms]):.3g} deg before, "
        f"{median([a['after'] for a in arms]):.3g} deg after.",
    ]
    if control is not None:
        md.append(
            f"- The control arm (encoder read {CONTROL_DELAY_S * 1000:.0f} ms late, a delay "
            f"the model lacks): {'explained (a miss)' if control else 'does not explain'}."
        )
    return "\n".join(md) + "\n"


def command_options(args):
    """The options the run was made with, as its command line gives them."""
    out = f"--family {args.family} --arms {args.arms} --seed {args.seed}"
    for name in SEARCH_OPTIONS:
        value = getattr(args, name)
        if value is not None:
            out += f" --{name.replace('_', '-')} {value}"
    out += " --searched-offsets" if args.searched_offsets else ""
    if args.contact_onset_mm is not None:
        out += f" --contact-onset-mm {args.contact_onset_mm:g}"
    return out + (f" --only {args.only}" if args.only else "")


def search_text():
    """The search settings the identification files give, or none (the file's defaults)."""
    given = {k: v for k, v in SEARCH.items() if k != "profile_offsets"}
    if not given:
        return ", the identification file's default search"
    return ", search " + ", ".join(f"{k} = {v}" for k, v in given.items())


def write_atomically(path, text):
    with open(path + ".tmp", "w", newline="") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def rows_csv(rows):
    fields = list(rows[0].keys())
    lines = [",".join(fields)]
    for r in rows:
        lines.append(
            ",".join(
                f'"{r[f]}"'
                if f == "verdict"
                else (f"{r[f]:.6g}" if isinstance(r[f], float) else str(r[f]))
                for f in fields
            )
        )
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--arms", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--pamsim", default=os.path.join(ROOT, "build", "src", "sim", "pamsim"))
    ap.add_argument("--out", help="default renders/identify_coverage[_<family>]")
    ap.add_argument("--no-control", action="store_true", help="skip the misspecified arm")
    ap.add_argument("--family", choices=sorted(FAMILIES), default="example")
    ap.add_argument("--starts", type=int, help="identify's `starts` (1 to 20)")
    ap.add_argument("--runs", type=int, help="identify's `runs`")
    ap.add_argument("--stall-generations", type=int, help="identify's `stall_generations`")
    ap.add_argument("--generations", type=int, help="identify's `generations`")
    ap.add_argument("--population", type=int, help="identify's `population`")
    ap.add_argument("--polish-iterations", type=int, help="identify's `polish_iterations`")
    ap.add_argument(
        "--searched-offsets",
        action="store_true",
        help="CMA-ES searches the offsets like the other parameters (identify's "
        "profile_offsets = false) instead of setting them at their best",
    )
    ap.add_argument(
        "--contact-onset-mm",
        type=float,
        help="sim.contact_soft_onset_mm of the arms and the model (0: MuJoCo's own contact; "
        "default arm.toml's)",
    )
    ap.add_argument(
        "--only",
        default="",
        help="identify only these of the --arms arms, e.g. 6,8 (each drawn as in the full run)",
    )
    args = ap.parse_args()
    try:
        only = {int(a) for a in args.only.split(",") if a.strip()}
    except ValueError:
        sys.exit(f"identify_coverage.py: --only must list arm numbers, got {args.only!r}")
    if (
        args.arms < 1
        or args.threads < 1
        or not 1 <= (args.starts or 1) <= 20
        or any(not 0 <= a < args.arms for a in only)
    ):
        sys.exit(
            "identify_coverage.py: --arms and --threads must be at least 1, --starts "
            "within [1, 20], --only's arms below --arms"
        )
    family = FAMILIES[args.family]
    TRUTH_RANGES.update(family["truth"])
    OFFSET_RANGES.update(family["offsets"])
    RECORDINGS.update(family["recordings"])
    SEARCH.update(family["search"])
    for name in SEARCH_OPTIONS:
        if getattr(args, name) is not None:
            SEARCH[name] = getattr(args, name)
    SEARCH["profile_offsets"] = "false" if args.searched_offsets else "true"
    if args.contact_onset_mm is not None:
        if not 0.0 <= args.contact_onset_mm <= 10.0:
            sys.exit("identify_coverage.py: --contact-onset-mm must be within [0, 10]")
        CONTACT.append(f"sim.contact_soft_onset_mm={args.contact_onset_mm!r}")
    if args.out is None:
        suffix = "" if args.family == "example" else "_" + args.family
        args.out = os.path.join(ROOT, "renders", "identify_coverage" + suffix)
    rng = random.Random(args.seed)
    rows, arms = [], []
    for i in range(args.arms):
        truth, offsets = draw_arm(rng)
        if only and i not in only:
            continue
        folder = os.path.join(args.out, f"arm_{i:02d}")
        out = identify(
            args.pamsim, make_arm(args.pamsim, folder, truth, offsets, 100 + i), args.threads
        )
        r = arm_rows(i, out, truth, offsets, 1.959963984540054)
        fitted, before, after = explained(out)
        arms.append(
            {
                "explained": fitted,
                "before": before,
                "after": after,
                "identified": all(trusted(x) for x in r),
                "unsettled": unsettled(r),
                "seconds": seconds(out),
            }
        )
        rows += r
        print(
            f"arm {i:02d}: {sum(x['inside'] for x in r)}/{len(r)} inside, "
            f"{'explained' if fitted else 'NOT explained'}"
            f"{', the search did not settle' if arms[-1]['unsettled'] else ''}, "
            f"{arms[-1]['seconds']:.0f} s",
            flush=True,
        )
    control = None
    if not args.no_control:
        truth, offsets = draw_arm(random.Random(args.seed + 10**6))
        folder = os.path.join(args.out, "control_delayed_encoder")
        out = identify(
            args.pamsim,
            make_arm(args.pamsim, folder, truth, offsets, 99, {"angle_deg": CONTROL_DELAY_S}),
            args.threads,
        )
        control = explained(out)[0]
    write_atomically(os.path.join(args.out, "coverage.csv"), rows_csv(rows))
    write_atomically(os.path.join(args.out, "coverage.md"), summary(rows, arms, control, args))
    print(open(os.path.join(args.out, "coverage.md")).read())


if __name__ == "__main__":
    main()
