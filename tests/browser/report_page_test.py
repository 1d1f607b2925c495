#!/usr/bin/env python3
"""report_page_test.py PAMSIM OUT: the pages of `pamsim report --html` opened in headless
Chromium (Debian's chromium and chromium-driver, driven through Selenium). The smoke sweep's
page: its heat maps, points and best points are all there; hovering a cell shows its point's
numbers, the same as points.csv's; clicking the best point's cell opens its replayed trials. A
short tuning's page: its best setting and one convergence marker per evaluation. The page of
`validate reaching`'s folder: Table V as a table, the paper's cells in it, and Fig. 7 drawn.
On every page the console has no error and the page requested nothing (no resource of any
kind, no http address in it). Exit 0 when every check holds.

    python3 tests/browser/report_page_test.py build/src/sim/pamsim /tmp/report_page
"""

import csv
import os
import shutil
import subprocess
import sys

try:
    from selenium import webdriver
except ModuleNotFoundError:  # Debian's python3-selenium serves /usr/bin/python3 alone
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
    raise
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

TUNING = """base = "{base}"
generations = 2
population = 5
seeds = 1
held_out_seeds = 1
[[parameter]]
key = "reflex.v_thr_mm_s"
from = 20.0
to = 150.0
[[objective]]
metric = "peak_drop_deg"
"""


def run(*args):
    subprocess.run(list(args), check=True, capture_output=True)


def make_pages(pamsim, out):
    """The three pages: the sweep's, the tuning's and the validation folder's."""
    tuning = os.path.join(out, "tune")
    os.makedirs(tuning)
    with open(os.path.join(tuning, "tune.toml"), "w") as f:
        f.write(TUNING.format(base=os.path.abspath("scenarios/drop_mass.toml")))
    run(pamsim, "tune", os.path.join(tuning, "tune.toml"), "--out", tuning, "--no-plot")
    run(pamsim, "report", os.path.join(tuning, "tune.db"), "--html", "--no-plot", "--force")
    validation = os.path.join(out, "validate")
    run(pamsim, "validate", "reaching", "--quiet", "--out", validation)
    run(pamsim, "report", validation, "--html")
    return {
        name: os.path.abspath(os.path.join(out, name, "report.html"))
        for name in ("tune", "validate")
    }


def make_page(pamsim, out):
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run(
        [pamsim, "sweep", "scenarios/sweep_smoke.toml", "--out", out],
        check=True,
        capture_output=True,
    )
    subprocess.run(
        [pamsim, "report", os.path.join(out, "sweep.db"), "--html", "--no-plot"],
        check=True,
        capture_output=True,
    )
    return os.path.abspath(os.path.join(out, "report.html"))


def browser():
    options = webdriver.ChromeOptions()
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1300,1000"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)


def check(ok, what):
    if not ok:
        raise AssertionError(what)


def shown(value):
    """A number as the page's script writes it: four significant digits, JavaScript's form."""
    return repr(float(f"{value:.4g}")).removesuffix(".0")


def check_hover(driver, out):
    with open(os.path.join(out, "points.csv")) as f:
        point0 = next(r for r in csv.DictReader(f) if r["point"] == "0")
    cell = driver.find_element(
        By.CSS_SELECTOR, 'rect.cell[data-map="map-peak_drop_deg"][data-ix="0"][data-iy="0"]'
    )
    ActionChains(driver).move_to_element(cell).perform()
    tip = driver.find_element(By.ID, "tip")
    check(tip.is_displayed(), "hovering a cell shows no tooltip")
    text = tip.text
    check("point 0:" in text, f"the tooltip does not name point 0: {text!r}")
    mean = shown(float(point0["peak_drop_deg_mean"]))
    check(f"peak_drop_deg: {mean} \u00b1" in text, f"peak drop {mean} not in {text!r}")


def check_best(driver):
    best = driver.find_element(By.CSS_SELECTOR, "rect.cell.marked")
    ActionChains(driver).move_to_element(best).click().perform()
    opened = [
        d
        for d in driver.find_elements(By.CSS_SELECTOR, "details.trials")
        if d.get_attribute("open") is not None
    ]
    check(len(opened) == 1, f"clicking the best cell opened {len(opened)} trial sections")
    lines = opened[0].find_elements(By.CSS_SELECTOR, "svg.chart polyline.series")
    check(len(lines) >= 3, f"the best point shows {len(lines)} series, not its trials' curves")
    check(all(len(p.get_attribute("points").split()) > 50 for p in lines), "an empty series")


def check_clean(driver, page):
    """No console error, no request, no web address in the file."""
    html = open(page, encoding="utf-8").read()
    check("http://" not in html and "https://" not in html, f"{page} names a web address")
    errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
    check(not errors, f"console errors: {errors}")
    fetched = driver.execute_script(
        "return performance.getEntriesByType('resource').map(e => e.name)"
    )
    check(fetched == [], f"the page requested {fetched}")


def check_tune(driver, page):
    driver.get("file://" + page)
    with open(os.path.join(os.path.dirname(page), "evaluations.csv")) as f:
        stored = len(list(csv.DictReader(f)))  # the tuning's own table, one row each
    rows = driver.find_elements(By.CSS_SELECTOR, "table#evaluations tr")
    markers = driver.find_elements(By.CSS_SELECTOR, "svg.chart circle.marker")
    check(
        stored > 5 and len(rows) == stored + 1 and len(markers) == stored,
        f"{stored} evaluations stored, {len(rows) - 1} rows, {len(markers)} markers",
    )
    best = driver.find_element(By.CSS_SELECTOR, "table#best").text
    check("reflex.v_thr_mm_s" in best and "peak_drop_deg" in best, f"best setting: {best!r}")
    check_clean(driver, page)


def check_validation(driver, page):
    driver.get("file://" + page)
    table = driver.find_element(By.CSS_SELECTOR, "section[data-file='table5.md'] table").text
    check("(8.82 / 5.24)" in table, "Table V's agonist cell with the paper's numbers")
    img = driver.find_element(By.CSS_SELECTOR, "figure img")
    check(driver.execute_script("return arguments[0].naturalWidth", img) > 0, "Fig. 7 not drawn")
    check_clean(driver, page)


def main():
    pamsim, out = sys.argv[1], sys.argv[2]
    page = make_page(pamsim, out)
    others = make_pages(pamsim, out)
    driver = browser()
    try:
        driver.get("file://" + page)
        check("sweep_smoke.toml" in driver.find_element(By.TAG_NAME, "h1").text, "no title")
        maps = driver.find_elements(By.CSS_SELECTOR, "svg.heatmap")
        check(len(maps) >= 2, f"{len(maps)} heat maps")
        for m in maps:
            check(len(m.find_elements(By.CSS_SELECTOR, ".cell")) == 16, "a map without 16 cells")
        rows = driver.find_elements(By.CSS_SELECTOR, "table#points tr")
        check(len(rows) == 17, f"{len(rows) - 1} rows of points, not 16")
        check(len(driver.find_elements(By.CSS_SELECTOR, "details.trials")) == 3, "best points")
        check_hover(driver, out)
        check_best(driver)
        check_clean(driver, page)
        check_tune(driver, others["tune"])
        check_validation(driver, others["validate"])
    finally:
        driver.quit()
    print("report pages (sweep, tuning, validation): every check holds in Chromium")


if __name__ == "__main__":
    main()
