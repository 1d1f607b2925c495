#!/usr/bin/env python3
"""docs_blocks.py: the documentation's computed numbers and figures, each made by the command
written beside it, so that a page cannot say what the program no longer does.

A page holds a generated block as an HTML comment (invisible on the site and on GitHub) that
names the commands and what of their output to show, then the output itself, then a closing
comment with the stamp the block was made under:

    <!-- pamsim-block
    id: table5-bands                 # unique in the docs; its outputs go to renders/docs/<id>
    class: slow                      # cheap | slow | timing (below)
    run: pamsim validate reaching --bands 50 --out {out}   # or a list of commands
    show: [stdout, bands.md, bands.png]   # what of the outputs the page shows
    -->
    ...written by `update`...
    <!-- /pamsim-block {"spec": ..., "version": ..., "digest": ..., ...} -->

Shown outputs: `stdout` (the last command's console output, as a text block; `stdout -N`, its
last N lines; an earlier command's output goes to a file under {out} to be shown), a `.md`
file as it is but for its headings, shown as bold lines (a block adds no section to a page),
a `.csv` file as a Markdown table, a `.json`, `.txt` or
`.toml` file as a code block, a `.png` or `.svg` file copied to docs/generated/<id>/ and shown
as a figure.

The three classes, and what `check` (CI) holds each to:
  cheap   rerun, and its text compared with the page's: the words exactly, every number
          within the block's `tolerance` (relative, default 1e-6: another machine's libm may
          move the last bits); a figure must be there (its data are the text's numbers;
          its pixels depend on the machine's fonts);
  slow    too slow for CI: its stamp's physics digest and version must be the build's (the
          digest names the column sums of a few short reference runs, recorded in
          docs/generated/physics_digest.json: a build that moves any by more than 1e-6,
          a change of the physics, the sensors or the estimator, has another digest);
  timing  wall-clock figures: stamped with the machine and the date, never compared.
Every class: the block's spec must be the one it was made from (an edited command without
a rerun is stale).

    docs_blocks.py update [--class cheap|slow|timing|all] [--id ID] [PAGE...]
    docs_blocks.py check [PAGE...]
    docs_blocks.py lint [PAGE...]
    docs_blocks.py digest
PAMSIM (environment) is the binary `pamsim` in a command stands for (default
build/src/sim/pamsim). `make docs` updates the cheap blocks, then builds the site.
"""

import argparse
import csv
import functools
import glob
import hashlib
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time

import yaml
from docs_files import BLOCK, CLOSE, OPEN, atomic_write
from docs_lint import lint

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
CLASSES = ("cheap", "slow", "timing")
COMMAND_TIMEOUT_S = 1800  # a block's command that hangs ends the run with one line
DEFAULT_TOLERANCE = 1e-6  # a machine's last bits, as for the physics digest
# the short runs the physics digest hashes: a reflex trial, the leg landing, a tensile test
DIGEST_RUNS = [
    ("pamsim run scenarios/drop_mass.toml --no-plot --out {out}/drop", "drop"),
    ("pamsim run scenarios/landing.toml --no-plot --set sim.duration_s=0.6 --out {out}/leg", "leg"),
    ("pamsim tensile --plant models/pams/plant_agonist.toml -o {out}/tensile.csv", "tensile.csv"),
]


class Stale(Exception):
    """A page that disagrees with the program: one line naming the page, the block and why."""


def pamsim_binary():
    return os.path.abspath(os.environ.get("PAMSIM", os.path.join(ROOT, "build/src/sim/pamsim")))


def pages(given):
    if given:
        return [os.path.abspath(p) for p in given]
    found = glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True)
    found = [p for p in found if "/_generated/" not in p]
    return sorted(found + [os.path.join(ROOT, "README.md")])


def parse_spec(text, where):
    try:
        spec = yaml.safe_load(text) or {}
    except yaml.YAMLError as e:
        raise Stale(
            f"{where}: a pamsim-block whose spec is not YAML ({' '.join(str(e).split())})"
        ) from e
    if not isinstance(spec, dict):
        raise Stale(f"{where}: a pamsim-block whose spec is not a mapping of id, class, run, show")
    for key in ("id", "class", "run", "show"):
        if key not in spec:
            raise Stale(f"{where}: a pamsim-block without `{key}`")
    if spec["class"] not in CLASSES:
        raise Stale(f"{where}: block {spec['id']}: class must be one of {CLASSES}")
    for key in ("run", "show"):
        if isinstance(spec[key], str):
            spec[key] = [spec[key]]
        for item in spec[key]:
            if not isinstance(item, (str, int)):
                raise Stale(
                    f"{where}: block {spec['id']}: a {key} item that YAML reads as "
                    f"{type(item).__name__} (a ': ' inside it?); write it as `- |` and "
                    f"the command on the next line"
                )
    spec.setdefault("tolerance", DEFAULT_TOLERANCE)
    return spec


def spec_hash(spec_text):
    return hashlib.sha256(" ".join(spec_text.split()).encode()).hexdigest()[:16]


def shown_command(command, block_id):
    return command.rstrip().replace("{out}", f"renders/docs/{block_id}")


def run_commands(spec, out):
    """Runs the block's commands from the repository root; returns the last one's stdout."""
    if os.path.isdir(out):
        shutil.rmtree(out)
    os.makedirs(out)
    stdout = ""
    shown_out = os.path.relpath(out, ROOT) if out.startswith(ROOT + os.sep) else out
    for command in spec["run"]:
        line = command.replace("{out}", shown_out)
        line = re.sub(r"(^|[\s;&|(])pamsim\b", lambda m: m.group(1) + pamsim_binary(), line)
        try:
            done = subprocess.run(
                line,
                shell=True,
                cwd=ROOT,
                capture_output=True,
                text=True,
                env=command_env(),
                stdin=subprocess.DEVNULL,
                timeout=COMMAND_TIMEOUT_S,
            )
        except subprocess.TimeoutExpired:
            raise Stale(f"block {spec['id']}: `{command}` ran over {COMMAND_TIMEOUT_S} s") from None
        if done.returncode != 0:
            raise Stale(
                f"block {spec['id']}: `{command}` failed ({done.returncode}): "
                f"{(done.stderr or done.stdout).strip().splitlines()[-1:]}"
            )
        stdout = as_shown(done.stdout)
    return stdout


def command_env():
    """The commands' environment: the binary's folder first on PATH, as getting-started has
    the reader put build/src/sim, so a script's `--pamsim "$(command -v pamsim)"` finds it."""
    env = dict(os.environ)
    env["PATH"] = os.path.dirname(pamsim_binary()) + os.pathsep + env.get("PATH", "")
    return env


def as_shown(text):
    """Text as the reader's own run prints it: `pamsim`, and paths from the repository."""
    return text.replace(pamsim_binary(), "pamsim").replace(ROOT + os.sep, "")


def csv_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    lines = ["| " + " | ".join(rows[0]) + " |", "|" + " --- |" * len(rows[0])]
    lines += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return "\n".join(lines)


def render_show(item, spec, out, stdout, check=False):
    """One shown output as Markdown; a figure is copied into docs/generated/<id>/, or with
    `check` compared with the copy there."""
    item = str(item)
    if item.startswith("stdout"):
        lines = stdout.rstrip("\n").splitlines()
        parts = item.split()
        if len(parts) == 2:
            lines = lines[int(parts[1]) :]
        return "```text\n" + "\n".join(lines) + "\n```"
    path = os.path.join(out, item)
    if not os.path.isfile(path):
        raise Stale(f"block {spec['id']}: its command wrote no {item}")
    if item.endswith(".md"):  # its headings as bold lines: a block adds none to the page's
        with open(path) as f:
            text = as_shown(f.read()).strip()
        return re.sub(r"^#{1,6}\s+(.*?)\s*#*$", r"**\1**", text, flags=re.M)
    if item.endswith(".csv"):
        return csv_table(path)
    if item.endswith((".json", ".txt", ".toml")):
        lexer = {".json": "json", ".txt": "text", ".toml": "toml"}[os.path.splitext(item)[1]]
        with open(path) as f:
            return f"```{lexer}\n{as_shown(f.read()).rstrip()}\n```"
    if item.endswith((".png", ".svg")):
        target = os.path.join(ROOT, "docs", "generated", spec["id"], os.path.basename(item))
        if check:  # its data are the block's numbers; its pixels depend on the fonts
            if not os.path.isfile(target):
                raise Stale(
                    f"block {spec['id']}: the figure {item} is not in docs/generated/{spec['id']}/"
                )
        else:
            os.makedirs(os.path.dirname(target), exist_ok=True)
            shutil.copyfile(path, target)
        shown = os.path.relpath(target, os.path.dirname(spec["page"]))  # GitHub's and Sphinx's
        return f"![{spec['id']}: {item}]({shown})"
    raise Stale(
        f"block {spec['id']}: cannot show {item} "
        "(stdout, .md, .csv, .json, .txt, .toml, .png, .svg)"
    )


def body_of(spec, out, stdout, check=False):
    commands = "\n".join(shown_command(c, spec["id"]) for c in spec["run"])
    parts = ["```sh\n" + commands + "\n```"]
    parts += [render_show(item, spec, out, stdout, check) for item in spec["show"]]
    return "\n\n".join(parts) + "\n"


def version():
    try:
        return subprocess.run(
            [pamsim_binary(), "--version"], capture_output=True, text=True, check=True
        ).stdout.split()[-1]
    except (OSError, subprocess.CalledProcessError) as e:
        raise Stale(
            f"cannot run {pamsim_binary()} --version ({e}): build pamsim, or set PAMSIM"
        ) from e


# the physics digest's record: the reference numbers and the id the slow blocks carry
DIGEST_FILE = os.path.join(ROOT, "docs", "generated", "physics_digest.json")
# how far a machine's last bits may move a reference number (relative, as
# tests/sim/core/reference_trajectory_test.cc holds trajectories)
DIGEST_TOLERANCE = 1e-6


def reference_numbers():
    """The reference runs' CSV columns, each summed: the physics as a few hundred numbers."""
    numbers = []
    with tempfile.TemporaryDirectory() as tmp:
        for command, output in DIGEST_RUNS:
            run_commands({"id": "digest", "run": [command]}, os.path.join(tmp, "run"))
            path = os.path.join(tmp, "run", output)
            files = (
                [path] if os.path.isfile(path) else sorted(glob.glob(os.path.join(path, "*.csv")))
            )
            for name in files:
                with open(name, newline="") as f:
                    rows = list(csv.reader(f))
                for c in range(len(rows[0])):
                    try:
                        numbers.append(sum(float(r[c]) for r in rows[1:]))
                    except ValueError:  # a text column
                        continue
    return numbers


def same_numbers(a, b):
    return len(a) == len(b) and all(
        abs(x - y) <= DIGEST_TOLERANCE * max(abs(x), abs(y), 1.0)
        for x, y in zip(a, b, strict=False)
    )


@functools.cache
def physics_digest():
    """The physics' id: the recorded one (DIGEST_FILE) while this build reproduces the
    recorded reference numbers within DIGEST_TOLERANCE (another machine's last bits aside),
    else a new one made from the numbers."""
    now = reference_numbers()
    if os.path.isfile(DIGEST_FILE):
        with open(DIGEST_FILE) as f:
            recorded = json.load(f)
        if same_numbers(recorded["numbers"], now):
            return recorded["id"]
    return hashlib.sha256(json.dumps([f"{x:.6g}" for x in now]).encode()).hexdigest()[:12]


def record_digest():
    """Writes DIGEST_FILE for this build's physics, when it is not already its record."""
    digest = physics_digest()
    if os.path.isfile(DIGEST_FILE):
        with open(DIGEST_FILE) as f:
            if json.load(f)["id"] == digest:
                return
    os.makedirs(os.path.dirname(DIGEST_FILE), exist_ok=True)
    atomic_write(DIGEST_FILE, json.dumps({"id": digest, "numbers": reference_numbers()}) + "\n")


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{cpu}, {os.cpu_count()} cores"


def stamp_of(spec, spec_text):
    stamp = {
        "spec": spec_hash(spec_text),
        "version": version(),
        "class": spec["class"],
        "date": time.strftime("%Y-%m-%d"),
    }
    if spec["class"] == "slow":
        record_digest()
        stamp["digest"] = physics_digest()
    if spec["class"] == "timing":
        stamp["machine"] = machine()
    return stamp


def stamp_line(stamp):
    """What the reader sees of the stamp."""
    made = f"Made by pamsim {stamp['version']} on {stamp['date']}"
    if stamp["class"] == "cheap":
        return f"<sub>{made}; rerun and compared at every CI run.</sub>"
    if stamp["class"] == "slow":
        return f"<sub>{made}, physics digest {stamp['digest']}.</sub>"
    return f"<sub>{made}, measured on {stamp['machine']}.</sub>"


def block_out(spec):
    """Where a block's commands write: renders/docs/<id>, as the reader's run would."""
    return os.path.join(ROOT, "renders", "docs", spec["id"])


def make_block(spec_text, spec):
    out = block_out(spec)
    stdout = run_commands(spec, out)
    stamp = stamp_of(spec, spec_text)
    body = body_of(spec, out, stdout) + "\n" + stamp_line(stamp) + "\n"
    return f"{OPEN}\n{spec_text}-->\n{body}{CLOSE} {json.dumps(stamp, sort_keys=True)} -->"


def blocks(text, path):
    for m in BLOCK.finditer(text):
        spec = parse_spec(m.group("spec"), os.path.relpath(path, ROOT))
        spec["page"] = path
        try:
            stamp = json.loads(m.group("stamp").strip() or "{}")
        except json.JSONDecodeError:
            stamp = {}  # a stamp edited by hand: the block counts as never made
        yield m, spec, stamp


def update_page(path, classes, only, seen):
    """Makes `path`'s blocks of `classes` (or of the ids in `only`) again, writing the page
    after each one (a long run interrupted keeps the blocks it made); returns the wall time its
    cheap blocks took."""
    with open(path) as f:
        text = f.read()
    where = os.path.relpath(path, ROOT)
    todo = []
    for _, spec, _ in blocks(text, path):
        if spec["id"] in seen:
            raise Stale(f"{where}: block id {spec['id']} is also in {seen[spec['id']]}")
        seen[spec["id"]] = where
        if spec["class"] in classes and (not only or spec["id"] in only):
            todo.append(spec["id"])
    cheap_s = 0.0
    for block_id in todo:
        with open(path) as f:  # as it is now: the page may have been edited meanwhile
            text = f.read()
        m, spec = next((m, spec) for m, spec, _ in blocks(text, path) if spec["id"] == block_id)
        started = time.time()
        made = make_block(m.group("spec"), spec)
        took = time.time() - started
        cheap_s += took if spec["class"] == "cheap" else 0.0
        print(f"{where}: {spec['id']} ({spec['class']}, {took:.1f} s)")
        with open(path) as f:
            text = f.read()
        m = next(m for m, spec, _ in blocks(text, path) if spec["id"] == block_id)
        if text[m.start() : m.end()] != made:
            atomic_write(path, text[: m.start()] + made + text[m.end() :])
    return cheap_s


def update(paths, classes, only):
    seen = {}
    for path in paths:
        cheap_s = update_page(path, classes, only, seen)
        if cheap_s:
            print(
                f"{os.path.relpath(path, ROOT)}: its cheap blocks took {cheap_s:.1f} s "
                f"(CI reruns them all)"
            )


def first_difference(page, program, tolerance, first_line=1):
    """The first line where the page's text and the program's differ in a word, or in a
    number by more than `tolerance` (relative), numbered from `first_line`; None if none
    does."""
    a, b = page.splitlines(), program.splitlines()
    for i in range(max(len(a), len(b))):
        x = a[i] if i < len(a) else ""
        y = b[i] if i < len(b) else ""
        if NUMBER.split(x) != NUMBER.split(y):
            return f"line {first_line + i}: the page has {x.strip()!r}, the program {y.strip()!r}"
        for u, v in zip(NUMBER.findall(x), NUMBER.findall(y), strict=False):
            fu, fv = float(u), float(v)
            if abs(fu - fv) > tolerance * max(abs(fu), abs(fv)):
                return (
                    f"line {first_line + i}: the page has {u}, the program {v} (tolerance "
                    f"{tolerance:g})"
                )
    return None


def check_block(m, spec, stamp, where):
    name = f"{where}: block {spec['id']}"
    if not stamp:
        raise Stale(f"{name} was never made: run `make docs`")
    if stamp.get("spec") != spec_hash(m.group("spec")):
        raise Stale(f"{name}: its commands changed since it was made: run `make docs`")
    if spec["class"] == "slow":
        for key, now in (("version", version()), ("digest", physics_digest())):
            if stamp.get(key) != now:
                raise Stale(
                    f"{name} was made under {key} {stamp.get(key)}, the build is {now}: "
                    f"rerun it (docs_blocks.py update --id {spec['id']} --class slow)"
                )
    elif spec["class"] == "timing":
        if not stamp.get("machine") or not stamp.get("date"):
            raise Stale(f"{name}: a timing without its machine and date")
    else:
        out = block_out(spec)
        program = body_of(spec, out, run_commands(spec, out), check=True)
        page = m.group("body")
        page = page[: page.rfind("<sub>")].rstrip("\n") + "\n" if "<sub>" in page else page
        first_line = m.string.count("\n", 0, m.start("body")) + 1
        problem = first_difference(page, program, float(spec["tolerance"]), first_line)
        if problem:
            raise Stale(f"{name} disagrees with the program, {problem}: run `make docs`")


def check(paths):
    problems, count = [], 0
    for path in paths:
        with open(path) as f:
            text = f.read()
        where = os.path.relpath(path, ROOT)
        for m, spec, stamp in blocks(text, path):
            count += 1
            try:
                check_block(m, spec, stamp, where)
            except Stale as e:
                problems.append(str(e))
    for p in problems:
        print(p, file=sys.stderr)
    print(f"docs_blocks: {count} blocks, {len(problems)} stale")
    return 1 if problems else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("action", choices=["update", "check", "lint", "digest"])
    parser.add_argument("pages", nargs="*")
    parser.add_argument("--class", dest="cls", default="cheap", choices=[*CLASSES, "all"])
    parser.add_argument("--id", action="append", default=[])
    args = parser.parse_args()
    paths = pages(args.pages)
    try:
        if args.action == "update":
            update(paths, CLASSES if args.cls == "all" else (args.cls,), args.id)
            return 0
        if args.action == "check":
            return check(paths)
        if args.action == "lint":
            return lint(paths)
        print(physics_digest())
        return 0
    except Stale as e:
        print(f"docs_blocks: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
