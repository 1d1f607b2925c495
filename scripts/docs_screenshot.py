#!/usr/bin/env python3
"""docs_screenshot.py [SITE] [--out DIR]: the built documentation site as a reader sees it in
a 1280x900 window, in headless Chromium (Debian's chromium). Builds nothing: SITE is what
`make docs` (scripts/docs.sh) wrote, build/docs by default.

For each page (index, identification, command-line; --pages for others) it
  * takes a screenshot of the window, OUT/<page>.png (the top of the page), and one of the
    whole page at the window's width, OUT/<page>-full.png, to look at;
  * checks that no <pre> block is cut: Chromium loads a copy of the page (written to a
    temporary folder, its <base> the site's folder, so the site's own CSS and scripts apply)
    with a script that, once the page has loaded, measures every visible <pre> and writes
    what it found into the page, which Chromium then prints (--dump-dom). A block is cut when
    its text is wider than its box (it scrolls: part of it is hidden), when its box reaches
    past the page's content column, or past the window; the page itself must not scroll
    sideways either. Tables are not checked, only counted: furo puts each in a frame that
    scrolls sideways when the table is wider than the column.
The window is the reader's: its vertical scroll bar, where Chromium draws one, takes its
width from the page (the line says how wide the page is).
It prints one line per page and exits 1 when any block is cut, 2 when there is no site or
Chromium fails.
OUT defaults to SITE/../docs-screenshots (build/docs-screenshots).
"""

import argparse
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

PAGES = ["index", "identification", "command-line"]
REPORT_ID = "pamsim-overflow-report"

# Runs in the page once it has loaded: the window's width, the content column's box, and
# each visible <pre> against them (1 px of slack for subpixel rounding).
MEASURE = rf"""
<script>
window.addEventListener("load", function () {{
  var root = document.documentElement;
  var view = root.clientWidth;
  var column = document.querySelector("article[role=main]") ||
               document.querySelector(".body") || document.body;
  var col = column.getBoundingClientRect();
  var cut = [], count = 0;
  document.querySelectorAll("pre").forEach(function (pre) {{
    if (!pre.offsetParent) return;                     // not shown (display: none)
    count++;
    var box = pre.getBoundingClientRect();
    var why = [];
    if (pre.scrollWidth > pre.clientWidth + 1)
      why.push("text " + pre.scrollWidth + " px wide in a " + pre.clientWidth + " px box");
    if (box.right > col.right + 1)
      why.push("box ends at " + Math.round(box.right) + " px, the column at " +
               Math.round(col.right));
    if (box.right > view + 1)
      why.push("box ends at " + Math.round(box.right) + " px, past the window's " + view);
    if (why.length)
      cut.push({{text: pre.textContent.trim().slice(0, 100), why: why}});
  }});
  var tables = 0;                                      // furo frames tables: they scroll
  document.querySelectorAll(".table-wrapper").forEach(function (w) {{
    if (w.offsetParent && w.scrollWidth > w.clientWidth + 1) tables++;
  }});
  var out = document.createElement("div");
  out.id = "{REPORT_ID}";
  out.textContent = JSON.stringify({{
    window: view, column_left: Math.round(col.left), column_right: Math.round(col.right),
    page_scroll_width: root.scrollWidth, page_height: root.scrollHeight, pre: count,
    cut: cut, scrolling_tables: tables}});
  document.body.appendChild(out);
}});
</script>
"""


def chromium(binary, args, timeout=120):
    cmd = [
        binary,
        "--headless",
        "--disable-gpu",
        "--no-sandbox",
        "--no-first-run",
        "--disable-extensions",
        "--mute-audio",
    ] + args
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if r.returncode != 0:
        sys.stderr.write(r.stderr)
        raise RuntimeError(f"chromium failed ({r.returncode}): {' '.join(cmd)}")
    return r.stdout


def screenshot(binary, url, png, width, height):
    chromium(binary, ["--screenshot=" + png, f"--window-size={width},{height}", url])
    if not os.path.isfile(png):
        raise RuntimeError("chromium wrote no " + png)


def measure(binary, site, page, width, height, tmp):
    """The report MEASURE writes into a copy of SITE/page.html, loaded at width x height."""
    with open(os.path.join(site, page + ".html"), encoding="utf-8") as f:
        text = f.read()
    base = f'<base href="file://{os.path.abspath(site)}/">'
    text, n = re.subn(r"(<head[^>]*>)", lambda m: m.group(1) + base, text, count=1)
    if n != 1:
        raise RuntimeError(page + ".html has no <head>")
    text = text.replace("</body>", MEASURE + "</body>", 1)
    copy = os.path.join(tmp, page + ".html")
    with open(copy, "w", encoding="utf-8") as f:
        f.write(text)
    dom = chromium(
        binary,
        [
            f"--window-size={width},{height}",
            "--virtual-time-budget=5000",
            "--dump-dom",
            "file://" + copy,
        ],
    )
    m = re.search(rf'<div id="{REPORT_ID}">(.*?)</div>', dom, re.S)
    if not m:
        raise RuntimeError("the measuring script left no report in " + page + ".html")
    return json.loads(html.unescape(m.group(1)))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("site", nargs="?", default=os.path.join(here, "..", "build", "docs"))
    ap.add_argument("--out", help="the screenshots' folder (default: SITE/../docs-screenshots)")
    ap.add_argument("--pages", nargs="+", default=PAGES, help="page names, without .html")
    ap.add_argument("--width", type=int, default=1280)
    ap.add_argument("--height", type=int, default=900)
    ap.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    a = ap.parse_args()
    site = os.path.abspath(a.site)
    out = os.path.abspath(a.out or os.path.join(site, "..", "docs-screenshots"))
    if not os.path.isfile(os.path.join(site, "index.html")):
        print(
            f"docs_screenshot: no site at {site} (make docs, or scripts/docs.sh)", file=sys.stderr
        )
        return 2
    os.makedirs(out, exist_ok=True)
    failed = False
    try:
        with tempfile.TemporaryDirectory(prefix="docs_screenshot.") as tmp:
            for page in a.pages:
                url = f"file://{site}/{page}.html"
                r = measure(a.chromium, site, page, a.width, a.height, tmp)
                png = os.path.join(out, page + ".png")
                screenshot(a.chromium, url, png, a.width, a.height)
                # the whole page: the window as tall as the page (Chromium's limit 16384 px)
                full = os.path.join(out, page + "-full.png")
                tall = min(16384, max(a.height, r["page_height"]))
                screenshot(a.chromium, url, full, a.width, tall)
                wide = r["page_scroll_width"] > r["window"] + 1
                cut = f"{len(r['cut'])} cut" if r["cut"] else "none cut"
                sideways = (
                    f", the page scrolls sideways ({r['page_scroll_width']} px)" if wide else ""
                )
                tables = r["scrolling_tables"]
                frames = f"; {tables} wide tables scroll in their frames" if tables else ""
                print(
                    f"{page}.html: {r['pre']} <pre> blocks, {cut}; column {r['column_left']}-"
                    f"{r['column_right']} px of the window's {r['window']}{sideways}{frames}; {png}"
                )
                for c in r["cut"]:
                    print("  cut: {!r}: {}".format(c["text"], "; ".join(c["why"])))
                failed |= bool(r["cut"]) or wide
    except (RuntimeError, OSError, subprocess.TimeoutExpired) as e:
        print(f"docs_screenshot: {e}", file=sys.stderr)
        return 2
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
