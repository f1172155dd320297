#!/usr/bin/env python3
"""The results site in a real browser: Debian's chromium, headless, driven by python3-selenium.

Usage: browser_test.py CURVBENCH RESULTS_DIR WORK_DIR

Renders the site from the CSVs of RESULTS_DIR into WORK_DIR/site (`curvbench report --site-only
--site ...`, nothing else is written), then opens every page from file:// and checks:
  - no page logs a console error;
  - every link between pages resolves to a file of the site;
  - every chart renders, with as many series as the page's data has;
  - clicking a leaderboard header reorders the rows in the order results/leaderboard.csv gives,
    and clicking again reverses it; the view's state is in the URL, and reopening that URL shows
    the same order;
  - unticking an estimator family hides exactly its rows.
A screenshot of each page goes to WORK_DIR/screenshots/ for a person to look at; each page's size
and load time is printed (a measurement, not a check). Exits 77 (ctest: skipped) with one line
when chromium, chromedriver or selenium is missing.
"""
import csv
import io
import json
import os
import shutil
import subprocess
import sys
import time
import urllib.parse

SKIP = 77


def skip(reason):
    print(f"site browser test skipped: {reason}")
    sys.exit(SKIP)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    skip("python3-selenium is not installed (make deps installs it)")

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
DRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
if not os.path.exists(CHROMIUM) or not os.path.exists(DRIVER):
    skip("chromium or chromium-driver is not installed (make deps installs them)")

failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def leaderboard_rows(results):
    with open(os.path.join(results, "leaderboard.csv"), encoding="utf-8") as f:
        text = "".join(line for line in f if not line.startswith("#"))
    return list(csv.DictReader(io.StringIO(text)))


def expected_order(rows, quantity, norm, cls, hidden_groups=(), descending=False):
    """The leaderboard's rows as the CSV orders them: methods in first-seen order, those with a
    value for (quantity, norm) in some class; sorted by cls's error (stable), rows without a
    value last."""
    methods, group, error, shown = [], {}, {}, set()
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
        group[r["method"]] = r["group"]
        if r["quantity"] == quantity and r["norm"] == norm:
            shown.add(r["method"])
            if r["mesh_class"] == cls:
                error[r["method"]] = float(r["error"])
    visible = [m for m in methods if m in shown and group[m] not in hidden_groups]
    with_value = [m for m in visible if m in error and error[m] == error[m]]
    without = [m for m in visible if m not in with_value]
    # Stable: ties keep their first-seen order in either direction.
    with_value.sort(key=lambda m: -error[m] if descending else error[m])
    return with_value + without


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    curvbench, results, work = (os.path.abspath(a) for a in sys.argv[1:])
    site = os.path.join(work, "site")
    shots = os.path.join(work, "screenshots")
    shutil.rmtree(site, ignore_errors=True)
    os.makedirs(shots, exist_ok=True)
    subprocess.run([curvbench, "report", "--results", results, "--site-only", "--site", site,
                    "--experiments-dir", os.path.join(os.path.dirname(results), "experiments")],
                   check=True, stdout=subprocess.DEVNULL)

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--window-size=1400,1000",
                 f"--user-data-dir={os.path.join(work, 'chromium-profile')}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    try:
        pages = sorted(f for f in os.listdir(site) if f.endswith(".html"))
        total = 0
        for page in pages:
            path = os.path.join(site, page)
            size = os.path.getsize(path)
            total += size
            start = time.monotonic()
            driver.get("file://" + path)
            loaded = driver.execute_script(
                "return performance.timing.loadEventEnd - performance.timing.navigationStart")
            seconds = time.monotonic() - start
            print(f"{page}: {size / 1024:.0f} KiB, load {loaded} ms ({seconds:.2f} s with the driver)")
            errors = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            check(not errors, f"{page}: console errors {errors}")
            # Links between pages.
            for href in driver.execute_script(
                    "return Array.from(document.querySelectorAll('a[href]'))"
                    ".map(a => a.getAttribute('href'))"):
                if href.startswith(("http://", "https://", "#")):
                    continue
                target = urllib.parse.unquote(href.split("#")[0])
                check(os.path.exists(os.path.join(site, target)),
                      f"{page}: link {href} does not resolve")
            # Charts: each canvas drawn with its data's series.
            data = json.loads(driver.execute_script(
                "return document.getElementById('site-data').textContent"))
            plots = data.get("plots", {})
            canvases = driver.find_elements(By.CSS_SELECTOR, "canvas[data-plot]")
            for canvas in canvases:
                pid = canvas.get_attribute("data-plot")
                want = len(plots.get(pid, {}).get("series", []))
                got = canvas.get_attribute("data-rendered")
                check(got == str(want), f"{page}: chart {pid} drew {got} series, data has {want}")
            charts = driver.execute_script("return (window.curvbenchCharts || []).length")
            check(charts == len(canvases), f"{page}: {charts} charts for {len(canvases)} canvases")
            driver.save_screenshot(os.path.join(shots, page.replace(".html", ".png")))
        print(f"site: {len(pages)} pages, {total / 1048576:.1f} MiB of HTML; "
              f"with assets {sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(site) for f in fs) / 1048576:.1f} MiB")

        # The leaderboard: sort, reverse, link the state, filter.
        rows = leaderboard_rows(results)
        index = "file://" + os.path.join(site, "index.html")
        driver.get(index)

        def shown():
            return [tr.get_attribute("data-method")
                    for tr in driver.find_elements(By.CSS_SELECTOR, "#leaderboard tbody tr")]

        want_first = expected_order(rows, "H", "L2", None)
        check(shown() == want_first, f"leaderboard's first view: {shown()} != {want_first}")
        header = driver.find_element(By.CSS_SELECTOR, 'th[data-sort="well-shaped:error"]')
        header.click()
        want = expected_order(rows, "H", "L2", "well-shaped")
        check(len(want) > 3, f"leaderboard: only {len(want)} rows for H L2")
        check(shown() == want, f"leaderboard sorted by well-shaped H error: {shown()} != {want}")
        driver.find_element(By.CSS_SELECTOR, 'th[data-sort="well-shaped:error"]').click()
        want_desc = expected_order(rows, "H", "L2", "well-shaped", descending=True)
        check(shown() == want_desc, f"leaderboard reversed: {shown()} != {want_desc}")
        url = driver.current_url
        check("sort=well-shaped%3Aerror" in url or "sort=well-shaped:error" in url,
              f"the sort is not in the URL: {url}")
        driver.get("about:blank")
        driver.get(url)
        check(shown() == want_desc, f"reopened {url}: {shown()} != {want_desc}")
        # Another quantity and norm from the URL alone: a fresh load, then a hash change.
        driver.get("about:blank")
        driver.get(index + "#q=K&norm=Linf&sort=irregular%3Aerror&dir=asc")
        want_k = expected_order(rows, "K", "Linf", "irregular")
        check(shown() == want_k, f"K Linf by irregular error: {shown()} != {want_k}")
        driver.execute_script("location.hash = 'q=normal&norm=L2&sort=isosurface%3Aerror&dir=desc'")
        want_n = expected_order(rows, "normal", "L2", "isosurface", descending=True)
        check(shown() == want_n, f"after a hash change: {shown()} != {want_n}")
        check(driver.find_element(By.ID, "lb-q").get_attribute("value") == "normal",
              "the quantity selector does not follow the hash")
        # Filter: untick the discrete operators.
        driver.get(index)
        box = driver.find_element(By.CSS_SELECTOR, '#lb-hide input[value="discrete operators"]')
        box.click()
        want_f = expected_order(rows, "H", "L2", None, hidden_groups=("discrete operators",))
        check(sorted(shown()) == sorted(want_f),
              f"filtered rows {shown()} != {want_f}")
        discrete = {r["method"] for r in rows if r["group"] == "discrete operators"}
        check(discrete and not (set(shown()) & discrete), "a discrete operator is still shown")
        check("hide=discrete" in urllib.parse.unquote(driver.current_url),
              f"the filter is not in the URL: {driver.current_url}")
        driver.save_screenshot(os.path.join(shots, "index-filtered.png"))
    finally:
        driver.quit()
    print(f"screenshots in {shots}")
    if failures:
        print(f"{len(failures)} failures")
        return 1
    print("site browser test passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
