#!/usr/bin/env python3
"""fiber_nonlinearity_bound.py: the largest nonlinearity of a stretch sensor that a published
linear fit allows, as the fiber sensor's fabric model states it (src/sensing/fiber_hardware.h:
a displacement u reads u (1 + (N / 100) u / S), N % at the span S). Tangsirinaruenart and
Stylios (Materials 12(9) 1469, 2019) report for their stitch sensor over 50 % strain a linear
fit of R^2 = 0.984 and a hysteresis of 6.25 % of its resistance change. Taking the span as the
tested range, and the hysteresis as a loop whose loading and unloading branches part by that
fraction of the range at its middle (half a sine wave each side), this finds by bisection the
N at which a least-squares line through both branches has that R^2, and prints it with the N
that the R^2 alone (no loop) would allow. Everything else that lowers a fit's R^2 (noise, drift)
makes the true N smaller: the result is an upper bound.

    python3 scripts/fiber_nonlinearity_bound.py [--r2 0.984] [--hysteresis 0.0625]
"""

import argparse
import math

SAMPLES = 2001  # per branch, over the range


def r_squared(n_pct, loop):
    """R^2 of a line through both branches of the reading over u in [0, 1] (S = 1)."""
    b = n_pct / 100.0
    xs, ys = [], []
    for i in range(SAMPLES):
        u = i / (SAMPLES - 1)
        reading = u * (1.0 + b * u)
        half = 0.5 * loop * (1.0 + b) * math.sin(math.pi * u)
        xs += [u, u]
        ys += [reading + half, reading - half]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys, strict=True))
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    return sxy * sxy / (sxx * syy)


def bound(r2, loop):
    """The N [%] at which the fit's R^2 falls to r2 (R^2 falls as N grows)."""
    lo, hi = 0.0, 1000.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if r_squared(mid, loop) > r2 else (lo, mid)
    return lo


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--r2", type=float, default=0.984)
    ap.add_argument("--hysteresis", type=float, default=0.0625, help="the loop, of the range")
    a = ap.parse_args()
    if not (0.0 < a.r2 < 1.0 and 0.0 <= a.hysteresis < 1.0):
        raise SystemExit("--r2 must lie in (0, 1) and --hysteresis in [0, 1)")
    if r_squared(0.0, a.hysteresis) <= a.r2:
        r2 = r_squared(0.0, a.hysteresis)
        raise SystemExit(f"the loop alone lowers R^2 to {r2:.4f}: no nonlinearity is left to bound")
    loop_pct, n_loop, n_none = 100 * a.hysteresis, bound(a.r2, a.hysteresis), bound(a.r2, 0.0)
    print(f"R^2 {a.r2:.3f} with a loop of {loop_pct:.2f} % of the range: N <= {n_loop:.0f} %")
    print(f"R^2 {a.r2:.3f} with no loop: N <= {n_none:.0f} %")


if __name__ == "__main__":
    main()
