#!/usr/bin/env python3
"""fiber_nonlinearity_bound_test.py: scripts/fiber_nonlinearity_bound.py against its closed
form. Without a loop, a reading u + b u^2 over u uniform in [0, 1] fitted by a line leaves
1 - R^2 = (b^2 / 180) / (1/12 + b/6 + 4 b^2 / 45), so the bound for a given R^2 is the positive
root of a quadratic in b; a loop lowers R^2 by itself, so it lowers the bound.

    python3 tests/scripts/fiber_nonlinearity_bound_test.py
"""

import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fiber_nonlinearity_bound as fnb  # noqa: E402


def closed_form_pct(r2):
    c = 1.0 - r2
    qa, qb, qc = 1 / 180 - 4 * c / 45, -c / 6, -c / 12
    return 100 * (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


def main():
    for r2 in (0.999, 0.99, 0.984):
        got, want = fnb.bound(r2, 0.0), closed_form_pct(r2)
        # the script samples the range at 2001 points: within 0.5 % of the continuous root
        assert abs(got - want) <= 5e-3 * want, (r2, got, want)
    assert fnb.r_squared(0.0, 0.0) > 1 - 1e-12  # a straight reading fits exactly
    assert fnb.r_squared(0.0, 0.0625) < 1.0
    assert fnb.bound(0.984, 0.0625) < fnb.bound(0.984, 0.0)
    print("fiber_nonlinearity_bound: the closed form holds")


if __name__ == "__main__":
    main()
