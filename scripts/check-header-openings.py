#!/usr/bin/env python3
"""check-header-openings.py: how long the comment block that opens each C/C++ header is.

A header's opening is its leading comment lines (after stripping, lines that start with `//`,
`/*` or `*`; leading blank lines are skipped) before the first line that is not a comment. A
header should open with what the file is for and why, in a few lines; longer explanations
belong beside the code they explain. Measures every *.h under the folders given (default
`src` and `python`, relative to the repository root), leaving out the generated
src/sim/io/embedded_sources.h, prints the mean and the longest, and lists each header over
--max-lines. Exit 1 when the mean is over --max-mean or any header is over --max-lines,
0 otherwise.

    python3 scripts/check-header-openings.py
    python3 scripts/check-header-openings.py src --max-mean 8 --max-lines 25
"""

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXCLUDED = {"src/sim/io/embedded_sources.h"}
COMMENT_STARTS = ("//", "/*", "*")


def opening_lines(path: Path) -> int:
    """The number of leading comment lines of `path`, leading blank lines skipped."""
    count = 0
    with path.open(encoding="utf-8", errors="replace") as f:
        for line in f:
            text = line.strip()
            if not text and count == 0:
                continue
            if not text.startswith(COMMENT_STARTS):
                break
            count += 1
    return count


def display(path: Path) -> str:
    """`path` relative to the repository root where it lies inside it, else as it is."""
    try:
        return path.resolve().relative_to(ROOT).as_posix()
    except ValueError:
        return path.as_posix()


def headers(folders: list[str]) -> list[Path]:
    """Every *.h under `folders` (relative to the repository root), less EXCLUDED."""
    found: list[Path] = []
    for folder in folders:
        base = ROOT / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*.h")):
            if display(path) not in EXCLUDED:
                found.append(path)
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="*", default=["src", "python"])
    parser.add_argument("--max-mean", type=float, default=8.0)
    parser.add_argument("--max-lines", type=int, default=25)
    args = parser.parse_args()

    files = headers(args.folders)
    if not files:
        print("check-header-openings: no headers found", file=sys.stderr)
        return 2
    counts = {display(path): opening_lines(path) for path in files}
    mean = sum(counts.values()) / len(counts)
    longest = max(counts, key=lambda name: counts[name])
    over = sorted((n, name) for name, n in counts.items() if n > args.max_lines)
    ok = mean <= args.max_mean and not over
    print(
        f"check-header-openings: {len(counts)} headers, mean {mean:.1f} comment lines "
        f"(max mean {args.max_mean:g}), longest {counts[longest]} ({longest}, "
        f"max {args.max_lines})"
    )
    for n, name in reversed(over):
        print(f"  over {args.max_lines}: {name}: {n}")
    if mean > args.max_mean:
        print(f"  mean {mean:.2f} is over {args.max_mean:g}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
