#!/usr/bin/python3
"""The samples page (samples/web) in a real browser: Debian's Chromium, headless, driven by
Selenium through chromedriver, on the page served from 127.0.0.1 by this process.

Checks, each reported as it passes or fails:
  api          the JavaScript API builds a world (bodies, shapes, joints), steps it, queries it,
               reads its events and debug-draw stream, and destroying it returns the engine's
               bytes (tbGetByteCount back to its baseline)
  hash NAME    for each of five catalogue scenes chosen in the page's scene picker and stepped
               --steps times, the page shows the state hash (tbWorld_GetStateHash) that the native
               `tumble run NAME --steps N` prints, run now by this test
  drag         pressing the mouse on a body and moving it (real pointer events) makes a motor joint
               that pulls the body toward the pointer
  switches     fifty scene switches in the picker leave the engine's byte count where it started
  screenshot   a known frame (ragdolls after 120 steps) written as PNG, not blank: many colours
  console      no error on the browser's console, no error caught by the page

Usage: tests/web/test_page.py --page build/web/web --tumble build/release/samples/tumble
                              [--steps 300] [--screenshot FILE.png]
       tests/web/test_page.py --page build/web/web --tumble build/release/samples/tumble
                              --measure large_pyramid,ragdolls [--steps 300]
The second form checks nothing: it steps each scene --steps times in the browser and in the native
program and prints both mean step times (ms), each taken over the whole run of steps.
Needs: chromium, chromium-driver, python3-selenium (scripts/install-deps.sh web-test); Debian's
python3 (/usr/bin/python3), whose site holds python3-selenium.
"""
import argparse
import functools
import http.server
import math
import os
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib

from selenium import webdriver
from selenium.common.exceptions import WebDriverException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

HASH_SCENES = ["pyramid", "card_house", "ragdolls", "car", "platformer"]
SWITCHES = 50
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
# The network is closed here: without these Chromium hangs on connection attempts (updates, sync,
# QUIC, first-run pages). A fresh profile each run (--user-data-dir, added below).
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--window-size=1280,860"]


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):
        pass


def serve(directory):
    """A static server on 127.0.0.1 at a free port, in a thread of this process."""
    handler = functools.partial(QuietHandler, directory=directory)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def start_browser(profile):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in CHROMIUM_FLAGS + ["--user-data-dir=" + profile]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_script_timeout(120)
    return driver


def native_hash(tumble, scene, steps):
    out = subprocess.run([tumble, "run", scene, "--steps", str(steps)], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("state hash: "):
            return line.split(": ", 1)[1].strip()
    raise RuntimeError(f"`tumble run {scene}` printed no state hash:\n{out}")


def png_pixels(path):
    """Width, height and the RGBA rows of an 8-bit RGB or RGBA PNG, not interlaced (what Chromium
    writes): enough to count the colours of a screenshot without an image library."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, color, _, _, interlace = header
    assert depth == 8 and color in (2, 6) and interlace == 0, f"unexpected PNG format {header}"
    channels = 4 if color == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


class Run:
    def __init__(self, driver, args):
        self.driver = driver
        self.args = args
        self.passed = 0
        self.failed = 0

    def check(self, name, ok, detail):
        print(f"web: {'PASS' if ok else 'FAIL'} {name}: {detail}", flush=True)
        if ok:
            self.passed += 1
        else:
            self.failed += 1

    def js(self, script, *arguments):
        return self.driver.execute_script(script, *arguments)

    def choose_scene(self, name, fresh=False):
        """Picks the scene in the page's picker; fresh: built anew (Reset) even when it is on show
        already, where the picker fires no change."""
        picker = Select(self.driver.find_element(By.ID, "scene"))
        shown = picker.first_selected_option.get_attribute("value")
        picker.select_by_value(name)
        if fresh and shown == name:
            self.driver.find_element(By.ID, "reset").click()
        loaded = self.js("return tumbleApp.run.name")
        assert loaded == name, f"the picker shows {loaded}, not {name}"

    def api(self):
        result = self.js("""
            const tb = tumbleApp.tb;
            const before = tb.getByteCount();
            const world = tb.createWorld({ gravity: [0, -10], solver: 'soft', broadPhase: 'tree' });
            const ground = world.createBody({ type: 'static' });
            ground.createBoxShape(20, 1, { center: [0, -1] });
            const box = world.createBody({ type: 'dynamic', position: [0, 4] });
            box.createBoxShape(0.5, 0.5, { contactEvents: true });
            const ball = world.createBody({ type: 'dynamic', position: [2, 3] });
            ball.createCircleShape([0, 0], 0.4, { contactEvents: true });
            const hull = world.createBody({ type: 'dynamic', position: [-2, 3] });
            hull.createPolygonShape([[-0.5, 0], [0.5, 0], [0, 0.8]], { radius: 0.05 });
            const joint = world.createRevoluteJoint(box, ball, [1, 3.5]);
            let begins = 0;
            for (let i = 0; i < 90; ++i) { world.step(1 / 60, 4); begins += world.getContactEvents().begin.length; }
            const ray = world.castRayClosest([0, 10], [0, -20]);
            const overlaps = world.overlapAABB([[-30, -3], [30, 10]]).length;
            const kinds = new Set();
            world.draw({ solidPolygon: () => kinds.add('polygon'), solidCircle: () => kinds.add('circle'),
                         line: () => kinds.add('line') }, [[-30, -30], [30, 30]]);
            const during = tb.getByteCount();
            const y = box.getPosition()[1];
            world.destroy();
            return { before, during, after: tb.getByteCount(), y, begins, ray: ray && ray.point, overlaps,
                     kinds: [...kinds].sort(), joint: joint !== null, valid: world.isValid() };
        """)
        ok = (result["after"] == result["before"] and result["during"] > result["before"] and result["joint"]
              and result["begins"] >= 2 and result["ray"] is not None and result["overlaps"] == 4
              and result["kinds"] == ["circle", "line", "polygon"] and result["valid"] is False
              and 0.0 < result["y"] < 4.0)
        self.check("api", ok, result)

    def hashes(self):
        for name in HASH_SCENES:
            self.choose_scene(name)
            browser = self.js("return tumbleApp.stepScene(arguments[0])", self.args.steps)
            shown = self.driver.find_element(By.ID, "hash").text
            native = native_hash(self.args.tumble, name, self.args.steps)
            self.check(f"hash {name}", browser == native and shown == native,
                       f"{self.args.steps} steps: browser {browser} (page shows {shown}), native {native}")

    def drag(self):
        self.choose_scene("pyramid", fresh=True)
        canvas = self.driver.find_element(By.ID, "view")
        # The top box of the pyramid: a point just under the top of the moving bodies' box.
        start = self.js("""
            const b = tumbleApp.run.bounds();
            const p = [0.5 * (b[0][0] + b[1][0]), b[1][1] - 0.25];
            window.dragProbe = tumbleApp.run.world.bodyAtPoint(p);
            return window.dragProbe && { point: p, screen: tumbleApp.toScreen(p), body: window.dragProbe.getPosition() };
        """)
        if start is None:
            self.check("drag", False, "no body under the top of the pyramid")
            return
        size = canvas.size
        sx, sy = start["screen"]
        offset = (200, 40)  # pixels: to the right and a little down, inside the canvas
        actions = ActionChains(self.driver)
        actions.move_to_element_with_offset(canvas, int(sx - size["width"] / 2), int(sy - size["height"] / 2))
        actions.click_and_hold()
        for k in range(1, 5):
            actions.move_by_offset(offset[0] // 4, offset[1] // 4)
        actions.perform()
        state = self.js("""
            const dragging = tumbleApp.drag !== null;
            tumbleApp.stepScene(90);
            return { dragging, target: tumbleApp.drag && tumbleApp.drag.target, body: window.dragProbe.getPosition() };
        """)
        ActionChains(self.driver).release().perform()
        released = self.js("return tumbleApp.drag === null")
        target = state["target"]
        if not state["dragging"] or target is None:
            self.check("drag", False, f"no drag joint after pressing the mouse on the top box: {state}")
            return
        before = math.dist(start["body"], target)
        after = math.dist(state["body"], target)
        self.check("drag", after < 0.25 * before and released,
                   f"body {start['body']} -> {state['body']}, pointer at {target}: "
                   f"distance {before:.3f} m -> {after:.3f} m, joint gone on release: {released}")

    def switches(self):
        self.choose_scene("pyramid", fresh=True)
        start = self.js("return tumbleApp.tb.getByteCount()")
        names = self.js("return tumbleApp.scenes.map((s) => s.name)")
        others = [n for n in names if n != "pyramid"]
        for k in range(SWITCHES - 1):
            self.choose_scene(others[k % len(others)])
            self.js("tumbleApp.stepScene(3)")
        self.choose_scene("pyramid")
        end = self.js("return tumbleApp.tb.getByteCount()")
        self.check("switches", end == start, f"{SWITCHES} switches: {start} bytes at the start, {end} at the end")

    def screenshot(self):
        self.choose_scene("ragdolls")
        self.js("tumbleApp.stepScene(120)")
        path = self.args.screenshot
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        self.driver.save_screenshot(path)
        width, height, channels, rows = png_pixels(path)
        colours = set()
        for row in rows[::4]:
            for x in range(0, width * channels, 4 * channels):
                colours.add(row[x:x + 3])
        self.check("screenshot", len(colours) >= 32, f"{path}: {width}x{height}, {len(colours)} colours sampled")

    def measure(self, names):
        for name in names:
            self.choose_scene(name, fresh=True)
            browser = self.js("""
                const run = tumbleApp.run;
                const start = performance.now();
                for (let i = 0; i < arguments[0]; ++i) run.step();
                return (performance.now() - start) / arguments[0];
            """, self.args.steps)
            out = subprocess.run([self.args.tumble, "run", name, "--steps", str(self.args.steps)], check=True,
                                 capture_output=True, text=True).stdout
            native = float(next(l for l in out.splitlines() if l.startswith("mean step: ")).split()[2])
            print(f"web: {name}, {self.args.steps} steps: browser {browser:.3f} ms a step, native {native:.3f} ms "
                  f"(browser / native {browser / native:.2f})", flush=True)

    def console(self):
        entries = self.driver.get_log("browser")
        errors = [e for e in entries if e.get("level") == "SEVERE"]
        caught = self.js("return tumbleApp.error")
        self.check("console", not errors and caught is None, f"errors: {errors}, page error: {caught}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--page", required=True, help="the built page: build/web/web")
    parser.add_argument("--tumble", required=True, help="the native tumble program")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--screenshot", default="build/web/page.png")
    parser.add_argument("--measure", help="comma-separated scenes: print browser and native step times, check nothing")
    args = parser.parse_args()
    if not os.path.exists(os.path.join(args.page, "tumble.wasm")):
        sys.exit(f"web: {args.page}/tumble.wasm is missing (scripts/run-web.sh --build-only builds it)")

    server = serve(args.page)
    url = f"http://127.0.0.1:{server.server_address[1]}/?paused"
    began = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="tumble-chromium-") as profile:
        driver = start_browser(profile)
        run = Run(driver, args)
        try:
            driver.get(url)
            WebDriverWait(driver, 60).until(lambda d: d.execute_script("return tumbleApp.ready || tumbleApp.error !== null"))
            if args.measure:
                run.measure(args.measure.split(","))
                return 0
            for part in (run.api, run.hashes, run.drag, run.switches, run.screenshot, run.console):
                try:
                    part_began = time.monotonic()
                    part()
                    print(f"web: {part.__name__} took {time.monotonic() - part_began:.1f} s", flush=True)
                except (WebDriverException, AssertionError, RuntimeError, subprocess.CalledProcessError) as error:
                    run.check(part.__name__, False, f"{type(error).__name__}: {error}")
        finally:
            driver.quit()
            server.shutdown()
    print(f"web: {run.passed} passed, {run.failed} failed ({time.monotonic() - began:.0f} s)")
    return 0 if run.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
