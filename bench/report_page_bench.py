#!/usr/bin/env python3
"""report_page_bench.py: what a sweep's shared page costs, measured in one run: the reflex
sweep's 2 000 trials (scenarios/sweep_reflex.toml: 400 points x 5 seeds) run once, its
`pamsim report --html` page made, and the page opened five times in headless Chromium
(Debian's chromium-driver through Selenium): the time from the navigation's start to the
load event's end (the page parsed, its script run), best and median, beside the page's size
and the time pamsim took to make it.

    python3 bench/report_page_bench.py [--pamsim build/src/sim/pamsim] [--out DIR]
"""

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "browser"))
import report_page_test  # noqa: E402  (its browser)

OPENS = 5


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pamsim", default="build/src/sim/pamsim")
    ap.add_argument("--out", default="renders/bench_report_page")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    subprocess.run(
        [a.pamsim, "sweep", "scenarios/sweep_reflex.toml", "--quiet", "--out", a.out],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    started = time.perf_counter()
    subprocess.run(
        [a.pamsim, "report", os.path.join(a.out, "sweep.db"), "--html", "--no-plot"],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    made_s = time.perf_counter() - started
    page = os.path.abspath(os.path.join(a.out, "report.html"))
    driver = report_page_test.browser()
    times = []
    try:
        for _ in range(OPENS):
            driver.get("file://" + page)
            load = "return performance.getEntriesByType('navigation')[0].loadEventEnd;"
            times.append(driver.execute_script(load))
    finally:
        driver.quit()
    with open(page, encoding="utf-8") as f:
        html = f.read()
    points = html.count('<details class="trials"')  # the replayed points, their series (seeds)
    trials = sum(len(s.split("<polyline")) - 1 for s in html.split("<svg")[1:] if "joint [" in s)
    print(
        f"sweep page of 2000 trials: {os.path.getsize(page) / 1e6:.2f} MB, made in {made_s:.1f} s "
        f"({points} best points' {trials} trials replayed); opened in Chromium in "
        f"{min(times):.0f} ms best, {statistics.median(times):.0f} ms median of {OPENS}"
    )


if __name__ == "__main__":
    main()
