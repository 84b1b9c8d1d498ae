"""The studio end to end in Debian's headless Chromium, as a teacher would use it: render a
short throw (`bounce render`), start `tribolab studio` on its folder, open the video, calibrate
by clicking a stick's two ends and the origin, click the ball, wait for the track, step through
every frame checking the drawn point against the rendered truth, run the `track kinematics` form
and read g back from its listing, run the `bounce analyze` form and find e within its sigma of
the render's, then drag the ball's point in one frame off by a few pixels
(a correction), wait for the re-tracking, drag the axes' origin and turn the axes by 90 deg
by their x-axis's ring (the tracks follow into the turned axes), and read the saved .trk back
with `track import`: the dragged frame holds the dragged position in the turned axes, the
others are still on the ball; then track a point on the ball's rim with the path tracker and
correct it, which is answered at once and then searched for the mark's look. Screenshots of
each step are left in OUT_DIR.

    /usr/bin/python3 tests/browser/studio_e2e.py TRIBOLAB OUT_DIR
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from studio_browser import calibrate, image_clicker, open_clip, render_throw, studio_page, throw_truth

ZOOM = 1  # chosen in the page: one image pixel is one CSS pixel (the 640x480 film fits the window)


def fail(message):
    print("FAIL: studio: " + message, file=sys.stderr)
    sys.exit(1)


def main(tribolab, out):
    folder = os.path.join(out, "studio_folder")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    # 28 frames of 640x480 on a plain background (the demo film's size: at 320x240 the tracked
    # tips put e_velocity 3.4 sigma from the truth, at 640x480 within 0.1 sigma).
    render, truth = render_throw(tribolab, os.path.join(folder, "throw.avi"), os.path.join(folder, "truth.csv"),
                                 "640x480")
    shutil.copyfile(os.path.join(folder, "throw.avi"), os.path.join(folder, "throw2.avi"))  # a series' second run
    rim = throw_truth(render, os.path.join(folder, "truth.csv"), "ball.A")
    scale = render["scale_m_per_px"]
    with studio_page(tribolab, folder, fail) as (driver, url, logs):
        dragged = run_page(driver, url, out, truth, scale, render["ball_start_px"], render["origin_px"],
                           render["truth"]["e_velocity"], rim)
    errors = [e for e in logs if e["level"] == "SEVERE"]
    if errors:
        fail("script errors: " + json.dumps(errors))
    # The saved Tracker project reads back with `track import`: the ball on every frame, the
    # dragged frame where it was dragged (the CSV beside it gives that frame's world position).
    imported_csv = os.path.join(out, "studio_imported.csv")
    imported = json.loads(subprocess.run([tribolab, "track", "import", os.path.join(folder, "throw.avi.tracks.trk"),
                                          "--track", "ball", "--out", imported_csv, "--json"],
                                         check=True, capture_output=True, text=True).stdout)
    if "ball" not in json.dumps(imported):
        fail("the saved .trk holds no track 'ball': " + json.dumps(imported)[:300])
    with open(os.path.join(folder, "throw.avi.tracks.csv")) as f:
        saved = {int(r["frame"]): r for r in csv.DictReader(f) if r["track"] == "ball"}
    with open(imported_csv) as f:
        back = {int(r["frame"]): r for r in csv.DictReader(f) if r["track"] == "ball"}
    frame, x_px, y_px = dragged
    row = saved[frame]
    if abs(float(row["x_px"]) - x_px) > 1e-3 or abs(float(row["y_px"]) - y_px) > 1e-3 or float(row["score"]) != 1:
        fail("the saved CSV's frame %d is %s, %s px (score %s), dragged to %.3f, %.3f" %
             (frame, row["x_px"], row["y_px"], row["score"], x_px, y_px))
    if frame not in back or abs(float(back[frame]["x"]) - float(row["x"])) > 1e-9 or \
            abs(float(back[frame]["y"]) - float(row["y"])) > 1e-9:
        fail("track import reads frame %d of the .trk as %s, the CSV says %s, %s" %
             (frame, back.get(frame), row["x"], row["y"]))
    if sorted(back) != sorted(truth):
        fail("track import reads frames %s from the .trk, the clip has %s" % (sorted(back), sorted(truth)))
    print("dragged frame %d read back from the .trk at x = %s m, y = %s m" % (frame, back[frame]["x"], back[frame]["y"]))
    print("ok studio")


def run_page(driver, url, out, truth, scale, ball_start, origin_px, e_truth, rim):
    wait, status, error, canvas = open_clip(driver, url, "throw.avi", len(truth), 640, ZOOM, fail)
    driver.save_screenshot(os.path.join(out, "studio_1_opened.png"))

    click_image = image_clicker(driver, canvas, ZOOM)

    # (while an action runs the status shows its progress, "WHAT: frame N of M"; it ends "WHAT: done" or "WHAT: failed")
    ended = lambda what: status() in (what + ": done", what + ": failed")

    def calibrate_and_track():
        # Calibration: a 400 px stick along the floor, its length from the render's scale, and the
        # origin (the render's, to a pixel: that only shifts x, y).
        clicked = calibrate(driver, click_image, (80.5, 400.5, 480.5, 400.5), 400 * scale,
                            (round(origin_px[0]) + 0.5, round(origin_px[1]) + 0.5), wait, ended, error, fail)
        # Track: one click on the ball in frame 0.
        driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=track]").click()
        click_image(*ball_start)
        wait.until(lambda d: ended("tracking"))
        wait.until(lambda d: canvas.get_attribute("data-drawn") not in (None, "", "[]") or error())
        if error():
            fail("tracking: " + error())
        return clicked

    clicked_origin = calibrate_and_track()
    driver.save_screenshot(os.path.join(out, "studio_2_tracked.png"))
    # The plot beside the frame: x, y of the ball and its ends, and the ball's orientation.
    traces = driver.execute_script("return document.getElementById('plot').data.map((t) => t.name)")
    if "ball angle" not in traces or "ball.A angle" in traces:
        fail("the plot's traces are %s: the ball's angle (not its ends') belongs there" % traces)
    # Play: every frame shown in turn to the last, then the button offers Play again.
    driver.find_element(By.ID, "play").click()
    wait.until(lambda d: canvas.get_attribute("data-frame") == str(max(truth)) and
               d.find_element(By.ID, "play").text == "Play")
    driver.execute_script("showFrame(0)")
    wait.until(lambda d: canvas.get_attribute("data-frame") == "0")
    worst = 0
    for frame in sorted(truth):
        if frame > 0:
            driver.find_element(By.ID, "next").click()
        wait.until(lambda d: d.find_element(By.ID, "frame-text").text.startswith("frame %d " % frame))
        wait.until(lambda d: canvas.get_attribute("data-frame") == str(frame))
        drawn = [p for p in json.loads(canvas.get_attribute("data-drawn")) if p["track"] == "ball"]
        if not drawn or drawn[0]["frame"] != frame:
            fail("frame %d: no tracked ball drawn" % frame)
        worst = max(worst, math.hypot(drawn[0]["x_px"] - truth[frame][0], drawn[0]["y_px"] - truth[frame][1]))
    # The ellipse tracker's centre error on rendered film is ~0.05 px in flight and up to ~0.2 px
    # in the contact frames (src/video/ellipse_tracker_test.cpp, cli/bounce_render_test.cpp);
    # 1 px still fails a point drawn half a pixel off or on the wrong frame (the ball moves
    # 15-40 px per frame).
    if worst > 1.0:
        fail("a drawn point is %.2f px from the truth" % worst)
    print("largest distance of a drawn point from the truth: %.3f px" % worst)

    # Analyse: the kinematics form, its defaults; g from the first flight's fitted ay.
    driver.find_element(By.ID, "run-analysis").click()
    wait.until(lambda d: d.find_elements(By.ID, "analysis-table") or error())
    if error():
        fail("analysis: " + error())
    driver.save_screenshot(os.path.join(out, "studio_3_analysed.png"))
    row = driver.find_element(By.CSS_SELECTOR, "#analysis-table tr[data-key='segment_fits.0.ay']")
    cells = row.find_elements(By.TAG_NAME, "td")
    ay, unit = float(cells[1].text), cells[2].text
    # The render's g is 9.8 m/s^2; the fit's sigma is ~0.006 m/s^2 and the stick is clicked
    # exactly (the length typed to 17 digits): 0.1 is 16x the sigma.
    if abs(ay + 9.8) > 0.1 or unit != "m/s^2":
        fail("the first flight's ay is %s %s, the render's is -9.8 m/s^2" % (ay, unit))
    print("first flight: ay = %s %s" % (ay, unit))

    # bounce analyze from its declared form: the ellipse's ends filled in as track_a, track_b;
    # the floor at the render's floor line (image y origin_px[1]) in the clicked frame.
    Select(driver.find_element(By.ID, "analysis-command")).select_by_value("bounce analyze")
    form = driver.find_element(By.ID, "analysis-form")
    if form.find_element(By.NAME, "track_a").get_attribute("value") != "ball.A" or \
            form.find_element(By.NAME, "track_b").get_attribute("value") != "ball.B":
        fail("the bounce analyze form did not offer the ellipse's ends ball.A, ball.B")
    floor = form.find_element(By.NAME, "floor_y")
    floor.clear()
    floor.send_keys(repr((clicked_origin[1] - origin_px[1]) * scale))  # the floor's world y: origin shift
    driver.find_element(By.ID, "run-analysis").click()
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "#analysis-table tr[data-key='e_velocity']") or error())
    if error():
        fail("bounce analyze: " + error())
    driver.save_screenshot(os.path.join(out, "studio_3b_bounce.png"))
    cell = lambda key, i: driver.find_element(By.CSS_SELECTOR, "#analysis-table tr[data-key='%s']" % key) \
        .find_elements(By.TAG_NAME, "td")[i].text
    e_text, sigma_e = cell("e_velocity", 1), float(cell("sigma_e_velocity", 1))
    e = float(e_text)
    if cell("floor_y", 2) != "m" or cell("impact_time", 2) != "s":
        fail("the bounce listing's units: floor_y in '%s', impact_time in '%s'" % (cell("floor_y", 2), cell("impact_time", 2)))
    # The bar: e within its standard uncertainty of the render's truth.
    if not abs(e - e_truth) <= sigma_e:
        fail("bounce analyze: e_velocity = %s +- %s, the render's is %.5f" % (e, sigma_e, e_truth))
    print("bounce analyze: e_velocity = %s +- %s (render: %.5f)" % (e, sigma_e, e_truth))
    # Its report below the listing: the command's own HTML report (throw.avi.bounce.html, the
    # six figures of `bounce analyze --report`), drawn in the page's sandboxed frame.
    if "throw.avi.bounce.html" not in driver.find_element(By.CSS_SELECTOR, "#analysis p").text:
        fail("the listing does not name the report: " + driver.find_element(By.CSS_SELECTOR, "#analysis p").text)
    report = driver.find_element(By.ID, "report")
    wait.until(lambda d: report.is_displayed() and "<title>tribolab bounce analyze" in (report.get_attribute("srcdoc") or ""))
    driver.switch_to.frame(report)
    try:
        wait.until(lambda d: len(d.find_elements(By.CSS_SELECTOR, ".js-plotly-plot .main-svg")) >= 6)
        figures = len(driver.find_elements(By.CSS_SELECTOR, ".js-plotly-plot"))
    finally:
        driver.switch_to.default_content()
    if figures != 6:
        fail("the report in the page draws %d figures, bounce analyze's report has 6" % figures)
    driver.execute_script("arguments[0].scrollIntoView()", report)
    driver.save_screenshot(os.path.join(out, "studio_3c_report.png"))
    driver.execute_script("window.scrollTo(0, 0)")
    print("bounce analyze's report drawn in the page: %d figures" % figures)

    # Correct: drag the ball's point in frame DRAG 4 px right and 3 px up (as many CSS px at zoom 1), off
    # the truth on purpose so that the saved position is seen to be the dragged one.
    DRAG = 10
    while int(canvas.get_attribute("data-frame")) != DRAG:
        current = int(canvas.get_attribute("data-frame"))
        driver.find_element(By.ID, "next" if current < DRAG else "prev").click()
        wait.until(lambda d: canvas.get_attribute("data-frame") != str(current))
    before = [p for p in json.loads(canvas.get_attribute("data-drawn")) if p["track"] == "ball"][0]
    if before["manual"]:
        fail("frame %d is drawn as a manual mark before any drag" % DRAG)
    dx = round((before["x_px"] + 0.5) * ZOOM + 1 - canvas.size["width"] / 2)
    dy = round((before["y_px"] + 0.5) * ZOOM + 1 - canvas.size["height"] / 2)
    ActionChains(driver).move_to_element_with_offset(canvas, dx, dy).click_and_hold() \
        .move_by_offset(2, -1).move_by_offset(2, -2).release().perform()
    wait.until(lambda d: ended("re-tracking ball"))
    if error():
        fail("re-tracking after the drag: " + error())
    wait.until(lambda d: [p for p in json.loads(canvas.get_attribute("data-drawn") or "[]")
                          if p["track"] == "ball" and p["manual"]])
    after = [p for p in json.loads(canvas.get_attribute("data-drawn")) if p["track"] == "ball"][0]
    if abs(after["x_px"] - (before["x_px"] + 4)) > 1e-3 or abs(after["y_px"] - (before["y_px"] - 3)) > 1e-3:
        fail("frame %d dragged from %.3f, %.3f by (4, -3) px is drawn at %.3f, %.3f" %
             (DRAG, before["x_px"], before["y_px"], after["x_px"], after["y_px"]))
    if "marks of ball at frame %d" % DRAG not in driver.find_element(By.ID, "marks-text").text:
        fail("the mark is not listed: " + driver.find_element(By.ID, "marks-text").text)
    driver.save_screenshot(os.path.join(out, "studio_4_corrected.png"))
    # The other frames: the ball again (the ellipse tracker restarts from the mark; the frames
    # before it are as they were).
    worst = 0
    for frame in sorted(truth):
        if frame == DRAG:
            continue
        driver.execute_script("showFrame(arguments[0])", sorted(truth).index(frame))
        wait.until(lambda d: canvas.get_attribute("data-frame") == str(frame))
        drawn = [p for p in json.loads(canvas.get_attribute("data-drawn")) if p["track"] == "ball"]
        if not drawn or drawn[0]["frame"] != frame or drawn[0]["manual"]:
            fail("after the drag, frame %d: no tracked ball drawn" % frame)
        worst = max(worst, math.hypot(drawn[0]["x_px"] - truth[frame][0], drawn[0]["y_px"] - truth[frame][1]))
    if worst > 1.0:
        fail("after the drag, a drawn point is %.2f px from the truth" % worst)
    print("after the drag: largest distance of another drawn point from the truth: %.3f px" % worst)

    # Place: "place the track's point here" and a click in frame PLACE (at a half pixel, so the
    # click lands exactly): a second mark, listed with the first.
    PLACE = 20
    driver.execute_script("showFrame(arguments[0])", sorted(truth).index(PLACE))
    wait.until(lambda d: canvas.get_attribute("data-frame") == str(PLACE))
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=mark]").click()
    px, py = math.floor(truth[PLACE][0]) + 0.5, math.floor(truth[PLACE][1]) + 0.5
    click_image(px, py)
    wait.until(lambda d: ended("re-tracking ball"))
    if error():
        fail("placing a mark: " + error())
    wait.until(lambda d: [p for p in json.loads(canvas.get_attribute("data-drawn") or "[]") if p["track"] == "ball" and p["manual"]])
    placed = [p for p in json.loads(canvas.get_attribute("data-drawn")) if p["track"] == "ball"][0]
    if abs(placed["x_px"] - px) > 1e-6 or abs(placed["y_px"] - py) > 1e-6:
        fail("the point placed at %.1f, %.1f in frame %d is drawn at %.3f, %.3f" % (px, py, PLACE, placed["x_px"], placed["y_px"]))
    if "marks of ball at frames %d, %d" % (DRAG, PLACE) not in driver.find_element(By.ID, "marks-text").text:
        fail("the marks are not listed: " + driver.find_element(By.ID, "marks-text").text)
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=track]").click()

    # A series, as `bounce analyze FILE...` takes it: throw2.avi (a copy of the film) opened,
    # calibrated and tracked as throw.avi was, then analysed with throw.avi's tracks ticked
    # under the form. Its run is throw.avi's first analysis again, to the digit; throw.avi's
    # run now has the two marks.
    driver.find_element(By.XPATH, "//ul[@id='files']/li[text()='throw2.avi']").click()
    wait.until(lambda d: ended("opening throw2.avi"))
    if error():
        fail("opening throw2.avi: " + error())
    calibrate_and_track()
    Select(driver.find_element(By.ID, "analysis-command")).select_by_value("bounce analyze")
    form = driver.find_element(By.ID, "analysis-form")
    floor = form.find_element(By.NAME, "floor_y")
    floor.clear()
    floor.send_keys(repr((clicked_origin[1] - origin_px[1]) * scale))
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "#series input[value='throw.avi']"))
    if driver.find_elements(By.CSS_SELECTOR, "#series input[value='throw2.avi']"):
        fail("the series offers the open video itself")
    driver.find_element(By.CSS_SELECTOR, "#series input[value='throw.avi']").click()
    driver.find_element(By.ID, "run-analysis").click()
    wait.until(lambda d: ended("analysing"))
    if error():
        fail("bounce analyze of a series: " + error())
    if cell("runs.0.file", 1) != '"throw2.avi.tracks.csv"' or cell("runs.1.file", 1) != '"throw.avi.tracks.csv"':
        fail("the series' runs are %s, %s" % (cell("runs.0.file", 1), cell("runs.1.file", 1)))
    if cell("runs.0.e_velocity", 1) != e_text or cell("runs.0.e_velocity", 2) != "":
        fail("the series' first run has e_velocity %s, the same film alone %s" % (cell("runs.0.e_velocity", 1), e_text))
    if cell("summary.n_ok", 1) != "2" or cell("runs.0.impact_time", 2) != "s":
        fail("the series' summary: n_ok %s; runs' impact_time in '%s'" % (cell("summary.n_ok", 1), cell("runs.0.impact_time", 2)))
    wait.until(lambda d: "throw.avi.tracks.csv" in (report.get_attribute("srcdoc") or ""))
    driver.save_screenshot(os.path.join(out, "studio_4a_series.png"))
    print("bounce analyze of a series of 2 videos in the page: e_velocity %s, %s" %
          (cell("runs.0.e_velocity", 1), cell("runs.1.e_velocity", 1)))
    driver.find_element(By.XPATH, "//ul[@id='files']/li[text()='throw.avi']").click()
    wait.until(lambda d: ended("opening throw.avi"))
    wait.until(lambda d: canvas.get_attribute("data-frame") == "0")

    # Axes: drag their origin 20 px right and 10 px down, then the ring at the x-axis's end
    # (kAxisLength = 50 screen px along x) round to straight up: the axes turn by 90 deg and are
    # applied at once; every tracked point's world x, y is then its image offset from the new
    # origin turned clockwise by 90 deg (x = up, y = left), in the stick's metres.
    axes = json.loads(canvas.get_attribute("data-axes"))
    ox, oy = axes["origin_px"]
    if abs(ox - clicked_origin[0]) > 1e-9 or abs(oy - clicked_origin[1]) > 1e-9 or axes["axes_deg"] != 0:
        fail("the axes are drawn at %s, the origin was set at %s with angle 0" % (axes, clicked_origin))
    at_screen = lambda x, y: (round((x + 0.5) * ZOOM + 1 - canvas.size["width"] / 2),
                              round((y + 0.5) * ZOOM + 1 - canvas.size["height"] / 2))
    ActionChains(driver).move_to_element_with_offset(canvas, *at_screen(ox, oy)).click_and_hold() \
        .move_by_offset(10, 5).move_by_offset(10, 5).release().perform()
    wait.until(lambda d: ended("calibrating"))
    if error():
        fail("dragging the axes' origin: " + error())
    ox, oy = ox + 20, oy + 10
    ActionChains(driver).move_to_element_with_offset(canvas, *at_screen(ox + 50 / ZOOM, oy)).click_and_hold() \
        .move_by_offset(-25, -25).move_by_offset(-25, -25).release().perform()
    wait.until(lambda d: ended("calibrating") and json.loads(canvas.get_attribute("data-axes"))["axes_deg"] == 90)
    if error():
        fail("turning the axes: " + error())
    axes = json.loads(canvas.get_attribute("data-axes"))
    if abs(axes["origin_px"][0] - ox) > 1e-9 or abs(axes["origin_px"][1] - oy) > 1e-9:
        fail("the axes' origin dragged to %.1f, %.1f is drawn at %s" % (ox, oy, axes["origin_px"]))
    if driver.find_element(By.ID, "axes-deg").get_attribute("value") != "90":
        fail("the axes angle shows '%s' after turning the axes up" % driver.find_element(By.ID, "axes-deg").get_attribute("value"))
    driver.save_screenshot(os.path.join(out, "studio_4b_axes.png"))
    rows = driver.execute_script("return state.tracks.series.find((s) => s.name === 'ball').rows")
    worst = 0
    for r in rows:
        if r["lost"]:
            continue
        x_want, y_want = -(r["y_px"] - oy) * scale, -(r["x_px"] - ox) * scale
        worst = max(worst, abs(r["x"] - x_want), abs(r["y"] - y_want))
    if worst > 1e-9:
        fail("after turning the axes by 90 deg a point's world position is %.3g m from its image offset turned" % worst)
    print("axes dragged and turned by 90 deg: world x, y are the turned image offsets (worst %.1g m)" % worst)

    # A path-tracked point on the ball's rim (the end A of its major axis in frame 0: the plain
    # ball's centre is flat) and its correction: the answer at once ("re-tracking spot: done"),
    # then the page tracks the clip again so that the frames around the mark are searched for
    # the object as it looks there ("searching the frames around the marks: done"), after which
    # the state has no look pending and the mark stands.
    driver.execute_script("showFrame(0)")
    wait.until(lambda d: canvas.get_attribute("data-frame") == str(sorted(truth)[0]))
    name = driver.find_element(By.ID, "track-name")
    name.clear()
    name.send_keys("spot")
    Select(driver.find_element(By.ID, "track-kind")).select_by_value("point")
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=track]").click()
    click_image(*rim[sorted(rim)[0]])
    wait.until(lambda d: ended("tracking"))
    if error():
        fail("tracking a point: " + error())
    SPOT = sorted(truth)[12]
    driver.execute_script("showFrame(arguments[0])", 12)
    wait.until(lambda d: canvas.get_attribute("data-frame") == str(SPOT))
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=mark]").click()
    click_image(math.floor(rim[SPOT][0]) + 0.5, math.floor(rim[SPOT][1]) + 0.5)
    wait.until(lambda d: ended("searching the frames around the marks") or status() == "re-tracking spot: failed")
    if error() or not status().endswith("done"):
        fail("correcting the point: " + (error() or status()))
    state = driver.execute_async_script("const done = arguments[arguments.length - 1]; api('/api/state').then(done);")
    spot = [s for s in state["starts"] if s["name"] == "spot"]
    if state["looks_pending"] or not spot or [m["frame"] for m in spot[0]["marks"]] != [SPOT]:
        fail("after the search the state is pending %s with the marks %s" % (state["looks_pending"], spot))
    print("a point's correction: answered at once, then the frames around it searched for its look")
    driver.find_element(By.CSS_SELECTOR, "input[name=mode][value=track]").click()
    return DRAG, after["x_px"], after["y_px"]


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
