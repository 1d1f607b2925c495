#!/usr/bin/env python3
"""docs_generate.py PAMSIM OUT: the documentation's reference pages, written from the program
itself so that they cannot go stale: every key of a scenario and of the other files
(`pamsim keys --json`, one table per kind), trajectory.csv's channels (`pamsim keys
--channels`), every command's options (`pamsim <command>
--help`), the references (CITATION.cff), and the C++ library's public headers with their
opening comments (CMakeLists.txt's PAMSIM_PUBLIC_HEADERS). scripts/docs.sh runs it before
Sphinx.
"""

import json
import os
import subprocess
import sys

import yaml
from docs_files import atomic_write

KINDS = [
    ("scenario", [], "A scenario file"),
    ("params", ["--params"], "A muscle's parameter file (the estimator's spring law)"),
    ("plant", ["--plant"], "A plant file (the physical muscle)"),
    ("pneumatics", ["--pneumatics"], "The pneumatics file (valve, chamber, regulator)"),
    ("calibration", ["--calibration"], "A calibration file (pamsim calibrate's)"),
    ("sweep", ["--sweep"], "A sweep file's design keys"),
    ("tune", ["--tune"], "A tuning file's search keys"),
    ("identify", ["--identify"], "An identification file's search and judgement keys"),
]


def prose(text):
    """Text a page shows as written: no HTML tags read into it ("<m>"), no Markdown markup."""
    return (
        str(text)
        .replace("&", "&amp;")
        .replace("<", "&lt;")
        .replace(">", "&gt;")
        .replace("*", "\\*")
        .replace("_", "\\_")
        .replace("\n", " ")
    )


def key_list(pamsim, flags):
    """Each key as a definition: its name and unit, then its meaning, values and default."""
    rows = json.loads(
        subprocess.run(
            [pamsim, "keys", "--json", *flags], check=True, capture_output=True, text=True
        ).stdout
    )
    lines = []
    for r in rows:
        unit = f" [{r['unit']}]" if r["unit"] else ""
        lines += [
            f"`{r['key']}`{prose(unit)}",
            f": {prose(r['meaning'])}; allowed: {prose(r['allowed'])}; "
            f"default: {prose(r['default'])}",
            "",
        ]
    return "\n".join(lines), len(rows)


def channel_list(pamsim, *args):
    """trajectory.csv's channels (`pamsim keys --channels [SCENARIO] --json`) as a table."""
    rows = json.loads(
        subprocess.run(
            [pamsim, "keys", "--channels", *args, "--json"],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    )
    lines = ["| column | unit | SI per unit | meaning | from |", "|---|---|---|---|---|"]
    for r in rows:
        source = r["source"] + (" (measured)" if r["measured"] else "")
        lines.append(
            f"| `{r['column']}` | {prose(r['unit'])} | {r['si_per_unit']:.6g} | "
            f"{prose(r['meaning'])} | {prose(source)} |"
        )
    return "\n".join(lines) + "\n", len(rows)


def commands(pamsim):
    """Each command's --help, in the order `pamsim --help` lists them."""
    top = subprocess.run([pamsim, "--help"], capture_output=True, text=True).stdout
    names = []
    in_list = False
    for line in top.splitlines():
        if line.strip().lower().startswith("subcommands"):
            in_list = True
        elif in_list and line.startswith("  ") and line.split():
            names.append(line.split()[0])
    if len(names) < 10:  # the help's layout changed: a page without the commands must not build
        sys.exit(
            f"docs_generate: found {len(names)} commands in `pamsim --help`'s Subcommands "
            f"list, expected every command (run, sweep, identify, ...)"
        )
    out = []
    for name in names:
        text = subprocess.run([pamsim, name, "--help"], capture_output=True, text=True).stdout
        out += [
            f"## `pamsim {name}`",
            "",
            "```text",
            text.replace(pamsim, "pamsim").rstrip(),
            "```",
            "",
        ]
    return "\n".join(out)


def references(citation):
    with open(citation) as f:
        cff = yaml.safe_load(f)
    out = []
    for ref in cff.get("references", []):
        names = ", ".join(
            a.get("family-names", a.get("name", ""))
            + (", " + a["given-names"] if "given-names" in a else "")
            for a in ref.get("authors", [])
        )
        where = ref.get("journal") or ref.get("collection-title") or ""
        parts = [names, f'"{" ".join(ref["title"].split())}"']
        if where:
            parts.append(f"*{' '.join(where.split())}*")
        for field, fmt in (
            ("volume", "vol. {}"),
            ("issue", "no. {}"),
            ("start", "p. {}"),
            ("year", "{}"),
            ("doi", "doi:{}"),
        ):
            if field in ref:
                parts.append(fmt.format(ref[field]))
        out.append("- " + ", ".join(parts) + ".")
        if "notes" in ref:
            out.append("  " + " ".join(ref["notes"].split()))
    return "\n".join(out) + "\n"


def public_headers(root):
    """The installed headers, as CMakeLists.txt's PAMSIM_PUBLIC_HEADERS lists them."""
    with open(os.path.join(root, "CMakeLists.txt")) as f:
        text = f.read()
    block = text[text.index("set(PAMSIM_PUBLIC_HEADERS") :]
    block = block[len("set(PAMSIM_PUBLIC_HEADERS") : block.index(")")]
    return block.split()


def first_comment(path):
    """A header's opening paragraph (to its first empty comment line): what the file is for,
    its papers named as the headers name them (as docs/references.md does)."""
    lines = []
    with open(path) as f:
        for line in f:
            if not line.startswith("//") or not line[2:].strip():
                break
            lines.append(line[2:].strip())
    return " ".join(lines)


def cpp_api(root):
    """The C++ library's public headers by room, each with its opening comment."""
    rooms = {}  # each folder's headers, the folders in the order the list first names them
    for header in public_headers(root):
        rooms.setdefault(os.path.dirname(header), []).append(header)
    out = []
    for folder, headers in rooms.items():
        out += ["", f"## `{folder}/`", ""]
        for header in headers:
            about = first_comment(os.path.join(root, "src", header))
            name = os.path.basename(header)
            about = about.split(": ", 1)[1] if about.startswith(name) else about
            out += [f"`pamsim/{header}`", f": {prose(about)}", ""]
    return "\n".join(out).lstrip("\n") + "\n"


def main():
    pamsim, out = os.path.abspath(sys.argv[1]), sys.argv[2]
    os.makedirs(out, exist_ok=True)
    for name, flags, what in KINDS:
        table, n = key_list(pamsim, flags)
        command = " ".join(["pamsim keys", *flags])
        atomic_write(
            os.path.join(out, f"keys_{name}.md"),
            f"{what}: {n} keys, as `{command}` lists them.\n\n{table}",
        )
    atomic_write(os.path.join(out, "commands.md"), commands(pamsim))
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    table, n = channel_list(pamsim)
    atomic_write(
        os.path.join(out, "channels.md"),
        f"{n} rows, as `pamsim keys --channels` lists them.\n\n{table}",
    )
    table, n = channel_list(pamsim, os.path.join(root, "scenarios", "drop_mass.toml"))
    atomic_write(
        os.path.join(out, "channels_drop_mass.md"),
        f"{n} columns, as `pamsim keys --channels scenarios/drop_mass.toml` lists them.\n\n{table}",
    )
    atomic_write(os.path.join(out, "references.md"), references(os.path.join(root, "CITATION.cff")))
    atomic_write(os.path.join(out, "cpp_api.md"), cpp_api(root))


if __name__ == "__main__":
    main()
