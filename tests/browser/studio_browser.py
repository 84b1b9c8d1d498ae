"""What the studio's browser tests share: a throw rendered by `bounce render` and a launch across
the incline rendered by `incline render`, each with its truth in image pixels, and `tribolab
studio` served on a folder with headless Chromium on its page (offline: no host but 127.0.0.1
resolves). The tests (studio_e2e.py, studio_upload_e2e.py, studio_incline_e2e.py) import it
from their own folder."""
import contextlib
import csv
import json
import os
import subprocess

from selenium import webdriver
from selenium.webdriver.chrome.service import Service


def render_throw(tribolab, video, truth_csv, size):
    """Renders a short throw on a plain background (100 fps, 0.3 m, 50 ms after the bounce)
    into `video`; returns the render's JSON and the ball's truth {frame: (x, y) in pixels}."""
    render = json.loads(subprocess.run(
        [tribolab, "bounce", "render", "--size", size, "--fps", "100", "--height", "0.3", "--after", "0.05",
         "--background", "plain", "--no-floor", "--out", video, "--truth", truth_csv, "--json"],
        check=True, capture_output=True, text=True).stdout)
    scale = render["scale_m_per_px"]
    ox, oy = render["origin_px"]
    truth = {}
    with open(truth_csv) as f:
        for row in csv.DictReader(f):
            if row["track"] == "ball":
                truth[int(row["frame"])] = (ox + float(row["x"]) / scale, oy - float(row["y"]) / scale)
    return render, truth


def render_incline(tribolab, video, truth_csv, args):
    """Renders a launch across the incline (`incline render ARGS`) into `video`; returns the
    render's JSON and the disc's truth {frame: (x, y) in pixels} (the CSV's x_px, y_px)."""
    render = json.loads(subprocess.run(
        [tribolab, "incline", "render", *args, "--out", video, "--truth", truth_csv, "--json"],
        check=True, capture_output=True, text=True).stdout)
    with open(truth_csv) as f:
        truth = {int(r["frame"]): (float(r["x_px"]), float(r["y_px"])) for r in csv.DictReader(f)}
    return render, truth


@contextlib.contextmanager
def studio_page(tribolab, folder, fail):
    """`tribolab studio FOLDER` and a headless Chromium; yields (driver, url) and afterwards
    the browser's log entries are in the returned list `logs` (filled when the block ends).
    The server is stopped whatever happens; `fail(message)` reports a server that printed no URL."""
    server = subprocess.Popen([tribolab, "studio", folder], stdout=subprocess.PIPE, text=True)
    logs = []
    try:
        server.stdout.readline()
        url = server.stdout.readline().strip()
        if "token=" not in url:
            fail("no URL printed: " + url)
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,1000",
                  "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]:  # offline: no other host resolves
            options.add_argument(a)
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        try:
            yield driver, url, logs
        finally:
            logs.extend(driver.get_log("browser"))
            driver.quit()
    finally:
        server.terminate()
        server.wait(timeout=10)
