"""What the studio's browser tests share: a throw rendered by `bounce render` and a launch across
the incline rendered by `incline render`, each with its truth in image pixels, and `tribolab
studio` served on a folder with headless Chromium on its page (offline: no host but 127.0.0.1
resolves). The tests (studio_e2e.py, studio_upload_e2e.py, studio_incline_e2e.py) import it
from their own folder."""
import contextlib
import csv
import json
import subprocess

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait


def render_throw(tribolab, video, truth_csv, size):
    """Renders a short throw on a plain background (100 fps, 0.3 m, 50 ms after the bounce)
    into `video`; returns the render's JSON and the ball's truth {frame: (x, y) in pixels}."""
    render = json.loads(subprocess.run(
        [tribolab, "bounce", "render", "--size", size, "--fps", "100", "--height", "0.3", "--after", "0.05",
         "--background", "plain", "--no-floor", "--out", video, "--truth", truth_csv, "--json"],
        check=True, capture_output=True, text=True).stdout)
    return render, throw_truth(render, truth_csv, "ball")


def throw_truth(render, truth_csv, track):
    """A throw's truth of `track` (ball: its centre; ball.A, ball.B: the ends of its major axis)
    {frame: (x, y) in pixels}, from render_throw's render and truth CSV."""
    scale = render["scale_m_per_px"]
    ox, oy = render["origin_px"]
    truth = {}
    with open(truth_csv) as f:
        for row in csv.DictReader(f):
            if row["track"] == track:
                truth[int(row["frame"])] = (ox + float(row["x"]) / scale, oy - float(row["y"]) / scale)
    return truth


def render_incline(tribolab, video, truth_csv, args):
    """Renders a launch across the incline (`incline render ARGS`) into `video`; returns the
    render's JSON and the disc's truth {frame: (x, y) in pixels} (the CSV's x_px, y_px)."""
    render = json.loads(subprocess.run(
        [tribolab, "incline", "render", *args, "--out", video, "--truth", truth_csv, "--json"],
        check=True, capture_output=True, text=True).stdout)
    with open(truth_csv) as f:
        truth = {int(r["frame"]): (float(r["x_px"]), float(r["y_px"])) for r in csv.DictReader(f)}
    return render, truth


def start_page(driver, url, fail, timeout):
    """Loads the page at `url` and waits until it is ready; returns (wait, status, error): a
    WebDriverWait of `timeout` s and readers of the page's status and error lines."""
    wait = WebDriverWait(driver, timeout)
    status = lambda: driver.find_element(By.ID, "status").text
    error = lambda: driver.find_element(By.ID, "error").text
    driver.get(url)
    wait.until(lambda d: status() in ("ready", "failed"))
    if status() != "ready":
        fail("the page did not start: " + error())
    return wait, status, error


def open_clip(driver, url, name, steps, width, zoom, fail):
    """Loads the page at `url`, opens the folder's file `name` from the list, sets the zoom and
    waits until its `steps` frames are offered and the canvas is `width` image pixels wide at
    `zoom`; returns (wait, status, error, canvas): a 20 s WebDriverWait and readers of the
    page's status and error lines."""
    wait, status, error = start_page(driver, url, fail, 20)
    driver.find_element(By.XPATH, "//ul[@id='files']/li[text()='%s']" % name).click()
    wait.until(lambda d: d.find_element(By.ID, "slider").get_attribute("max") == str(steps - 1) or error())
    if error():
        fail("opening: " + error())
    canvas = driver.find_element(By.ID, "canvas")
    Select(driver.find_element(By.ID, "zoom")).select_by_visible_text(str(zoom))
    wait.until(lambda d: canvas.get_attribute("width") == str(width * zoom))
    return wait, status, error, canvas


def image_clicker(driver, canvas, zoom):
    """A function clicking image pixel (x, y) of the page's canvas at `zoom`: Selenium offsets
    from the element's centre, the canvas has a 1 px border, and image pixel x is drawn at CSS
    (x + 0.5) * zoom inside it (page.html, draw())."""
    from selenium.webdriver.common.action_chains import ActionChains

    def click(x, y):
        dx = round((x + 0.5) * zoom + 1 - canvas.size["width"] / 2)
        dy = round((y + 0.5) * zoom + 1 - canvas.size["height"] / 2)
        ActionChains(driver).move_to_element_with_offset(canvas, dx, dy).click().perform()
    return click


def calibrate(driver, click_image, stick, length_m, origin, wait, ended, error, fail):
    """Calibrates by clicking, as a teacher does: the stick's two ends `stick` (x1, y1, x2, y2,
    image px; at half pixels they are clicked exactly at zoom 1), its length typed, the origin
    clicked, then "Apply calibration". Returns the origin as the page read it, px."""
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=stick]").click()
    click_image(stick[0], stick[1])
    click_image(stick[2], stick[3])
    read = [float(v) for v in driver.find_element(By.ID, "stick-text").text.split(":")[1].split("px")[0].split(",")]
    if max(abs(a - b) for a, b in zip(read, stick)) > 1e-6:
        fail("the stick's ends were read at %s, clicked at %s" % (read, list(stick)))
    length = driver.find_element(By.ID, "stick-length")
    length.clear()
    length.send_keys(repr(length_m))
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=origin]").click()
    click_image(*origin)
    clicked = [float(v) for v in driver.find_element(By.ID, "origin-text").text.split(":")[1].split("px")[0].split(",")]
    driver.find_element(By.ID, "apply-calibration").click()
    wait.until(lambda d: ended("calibrating"))
    if error():
        fail("calibration: " + error())
    return clicked


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
