#!/usr/bin/env python3
"""`lucent preview` as a user sees it, in a real headless Chromium driven over WebDriver
(chromedriver, plain HTTP, python3's urllib only).

One long-lived page: the scene is saved three times (a colour change, an error, a fix) and
each time the screenshot must show it: the new colour; the last image dimmed with the
messages of `lucent check` word for word; the image back, bright. Requests without the token
are refused. A second preview of another scene runs beside the first on another port, each
page showing its own scene, a save of one leaving the other alone. Many saves do not make
the process grow. Ctrl-C stops both cleanly.

Usage: preview_in_browser.py LUCENT WORKDIR
"""
import atexit
import base64
import json
import os
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

LUCENT, WORK = sys.argv[1], sys.argv[2]
SAVES = int(os.environ.get("LUCENT_PREVIEW_SAVES", "300"))


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def scene_text(ambient, extra=""):
    # A box filling the view in one flat colour (ambient only), so a screenshot's pixels
    # say which save it shows. The error save puts an unknown attribute on line 5.
    return f"""<scene version="1">
  <render width="240" height="160"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="0 0 10"/>
  <box min="-9 -9 -1" max="9 9 0"{extra}><material ambient="{ambient}" diffuse="0"/></box>
</scene>
"""


def save(path, text):
    # As editors do: a temporary file renamed over the scene.
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http_status(url):
    try:
        with urllib.request.urlopen(url, timeout=10) as r:
            return r.status
    except urllib.error.HTTPError as e:
        return e.code


class Preview:
    """A `lucent preview` process and the address it printed."""
    running = []  # killed at exit, if a failed check left them running

    def __init__(self, scene, *options):
        self.scene = scene
        self.log = open(scene + ".log", "w")
        self.process = subprocess.Popen([LUCENT, "preview", scene, *options], stdout=subprocess.PIPE,
                                        stderr=self.log, text=True)
        Preview.running.append(self.process)
        line = self.process.stdout.readline()
        if "http://" not in line:
            fail(f"lucent preview printed no address: {line!r}")
        self.url = line[line.index("http://"):].split()[0]
        self.base, self.token = self.url.split("/?token=")

    def rss_kb(self):
        with open(f"/proc/{self.process.pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        fail("no VmRSS")

    def stop(self):
        self.process.send_signal(signal.SIGINT)
        try:
            status = self.process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            fail("lucent preview did not stop within 5 s of Ctrl-C")
        if status != 0:
            fail(f"lucent preview exited {status} after Ctrl-C")


@atexit.register
def kill_previews():
    for process in Preview.running:
        if process.poll() is None:
            process.kill()
            process.wait()


class Browser:
    """One headless Chromium session over WebDriver."""

    def __init__(self):
        self.port = free_port()
        self.driver = subprocess.Popen(["chromedriver", f"--port={self.port}"],
                                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.root = f"http://127.0.0.1:{self.port}"
        for _ in range(100):
            try:
                self.call("GET", "/status")
                break
            except OSError:
                time.sleep(0.1)
        args = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--hide-scrollbars", "--force-device-scale-factor=1", "--window-size=900,600",
                f"--user-data-dir={WORK}/profile"]
        caps = {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": {
            "binary": "/usr/bin/chromium", "args": args}}}}
        self.session = self.call("POST", "/session", caps)["sessionId"]

    def call(self, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else None
        request = urllib.request.Request(self.root + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(request, timeout=60) as r:
            return json.loads(r.read())["value"]

    def open(self, url):
        self.call("POST", f"/session/{self.session}/url", {"url": url})

    def script(self, code):
        return self.call("POST", f"/session/{self.session}/execute/sync", {"script": code, "args": []})

    def screenshot(self, name):
        png = base64.b64decode(self.call("GET", f"/session/{self.session}/screenshot"))
        path = f"{WORK}/{name}.png"
        with open(path, "wb") as f:
            f.write(png)
        subprocess.run(["oiiotool", path, "-o", f"{WORK}/{name}.ppm"], check=True)
        return read_ppm(f"{WORK}/{name}.ppm")

    def wait_for(self, generation, phase, timeout=30):
        """Waits until the page shows render `generation` in `phase`."""
        end = time.time() + timeout
        while time.time() < end:
            shown = self.script("return [document.body.dataset.generation, document.body.dataset.phase]")
            if shown == [str(generation), phase]:
                return
            time.sleep(0.05)
        fail(f"the page shows {shown}, not render {generation} {phase}, after {timeout} s")

    def quit(self):
        try:
            self.call("DELETE", f"/session/{self.session}")
        finally:
            self.driver.terminate()
            self.driver.wait(timeout=10)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(maxsplit=4)
    width, height = int(parts[1]), int(parts[2])
    return width, height, parts[4]


def canvas_mean(browser, shot):
    """The mean colour of the screenshot inside the canvas (a margin in from its edges)."""
    r = browser.script("const r = document.getElementById('image').getBoundingClientRect();"
                       "return [r.left, r.top, r.width, r.height];")
    width, _, pixels = shot
    x0, y0 = int(r[0]) + 10, int(r[1]) + 10
    x1, y1 = int(r[0] + r[2]) - 10, int(r[1] + r[3]) - 10
    if x1 - x0 < 50 or y1 - y0 < 50:
        fail(f"the canvas is not shown at its size: {r}")
    sums, n = [0, 0, 0], 0
    for y in range(y0, y1, 3):
        for x in range(x0, x1, 3):
            i = 3 * (y * width + x)
            for c in range(3):
                sums[c] += pixels[i + c]
            n += 1
    return [s / n for s in sums]


def expect_colour(label, mean, colour, low=200, high=40):
    """`colour`: the channel (0 red, 1 green, 2 blue) that must be bright, the others dark."""
    if mean[colour] < low or any(mean[c] > high for c in range(3) if c != colour):
        fail(f"{label}: the image's mean colour is {[round(m) for m in mean]}")
    print(f"{label}: mean colour {[round(m) for m in mean]}")


def check_token(preview):
    for url, expected in [(preview.base + "/", 403), (preview.base + "/?token=", 403),
                          (preview.base + "/?token=" + "0" * 32, 403),
                          (preview.base + "/events", 403), (preview.url, 200),
                          (preview.base + "/nothing?token=" + preview.token, 404)]:
        got = http_status(url)
        if got != expected:
            fail(f"GET {url.replace(preview.token, 'TOKEN')}: status {got}, expected {expected}")
    print("token: refused without it (403), served with it")
    port = preview.base.rsplit(":", 1)[1]
    taken = subprocess.run([LUCENT, "preview", preview.scene, "--port", port], capture_output=True,
                           text=True, timeout=20)
    expected = f"lucent: error: cannot serve the preview on 127.0.0.1 port {port}: Address already in use\n"
    if taken.returncode != 3 or taken.stderr != expected:
        fail(f"a second preview on a port in use: status {taken.returncode}, {taken.stderr!r}")
    print("a port in use: refused with status 3")


def three_saves(browser, preview, scene):
    """The colour change, the error, the fix, each checked in the screenshot."""
    browser.open(preview.url)
    browser.wait_for(1, "done")
    expect_colour("first render (red)", canvas_mean(browser, browser.screenshot("red")), 0)

    save(scene, scene_text("0 1 0"))
    browser.wait_for(2, "done")
    green = canvas_mean(browser, browser.screenshot("green"))
    expect_colour("after the colour change (green)", green, 1)

    save(scene, scene_text("0 1 0", ' bogus="2"'))
    browser.wait_for(3, "invalid")
    time.sleep(0.2)  # the dimming is applied once the images before it are drawn
    shown = browser.script("return document.getElementById('messages').innerText").strip()
    check = subprocess.run([LUCENT, "check", scene], capture_output=True, text=True)
    if check.returncode != 2 or shown != check.stderr.strip():
        fail(f"the page's messages differ from lucent check's:\n{shown}\n---\n{check.stderr}")
    if f"{scene}:5:" not in shown:
        fail(f"the messages do not name line 5: {shown}")
    dimmed = canvas_mean(browser, browser.screenshot("error"))
    # The last good image stays (still green, nothing else), at about a third of its light.
    if not (0.2 * green[1] < dimmed[1] < 0.5 * green[1]) or dimmed[0] > 20 or dimmed[2] > 20:
        fail(f"the invalid scene's image is not the last one dimmed: {dimmed} after {green}")
    print(f"error: the messages of lucent check shown; the image dimmed to {round(dimmed[1])}")

    save(scene, scene_text("0 0 1"))
    browser.wait_for(4, "done")
    time.sleep(0.2)
    expect_colour("after the fix (blue)", canvas_mean(browser, browser.screenshot("fixed")), 2)
    if not browser.script("return document.getElementById('messages').hidden"):
        fail("the messages are still shown after the fix")


def post_status(url):
    try:
        with urllib.request.urlopen(urllib.request.Request(url, data=b"", method="POST"), timeout=10) as r:
            return r.status
    except urllib.error.HTTPError as e:
        return e.code


def save_button_and_pixel(browser, preview, scene):
    """The button writes SCENE.png (blue now); the pointer's pixel is read out."""
    output = scene[:-len(".xml")] + ".png"
    if post_status(preview.base + "/save") != 403 or http_status(preview.url.replace("/?", "/save?")) != 404:
        fail("/save answers without the token, or to a GET")
    if os.path.exists(output):
        fail(f"{output} exists before the button is pressed")
    browser.script("document.getElementById('save').click()")
    end = time.time() + 10
    while time.time() < end and not browser.script("return document.getElementById('saved').textContent"):
        time.sleep(0.05)
    said = browser.script("return document.getElementById('saved').textContent")
    if not said.startswith(f"wrote '{output}' (240x160)"):
        fail(f"the save button says {said!r}")
    subprocess.run(["oiiotool", output, "-o", f"{WORK}/saved.ppm"], check=True)
    width, height, pixels = read_ppm(f"{WORK}/saved.ppm")
    centre = 3 * (height // 2 * width + width // 2)
    if (width, height) != (240, 160) or list(pixels[centre:centre + 3]) != [0, 0, 255]:
        fail(f"the saved image is {width}x{height}, its centre {list(pixels[centre:centre + 3])}")
    os.remove(output)
    shown = browser.script("""const c = document.getElementById('image'), r = c.getBoundingClientRect();
        c.dispatchEvent(new MouseEvent('mousemove', {clientX: r.left + r.width * 0.25 + 0.5,
                                                     clientY: r.top + r.height * 0.5 + 0.5}));
        return document.getElementById('pixel').textContent;""")
    if shown != "pixel 60, 80: sRGB 0 0 255 · linear 0.000 0.000 1.000":
        fail(f"the pixel under the pointer reads {shown!r}")
    print(f"save button: {said}; pointer: {shown}")


SLIDER_SCENE = """<scene version="1">
  <param name="red" value="0.5"/>
  <animation frames="3" clock-from="0" clock-to="1"/>
  <render width="120" height="80"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="0 0 10"/>
  <box min="-9 -9 -1" max="9 9 0"><material ambient="${red} 0 ${clock}" diffuse="0"/></box>
</scene>
"""


def move_slider(browser, name, value):
    browser.script(f"""const s = document.querySelector('#controls input[data-name="{name}"]');
        s.value = {value}; s.dispatchEvent(new Event('input'));""")


def sliders(browser, scene):
    """A numeric <param> and the frame of an animation, each a slider that renders again."""
    save(scene, SLIDER_SCENE)
    preview = Preview(scene)
    try:
        browser.open(preview.url)
        browser.wait_for(1, "done")
        names = browser.script("return [...document.querySelectorAll('#controls input')].map("
                               "s => [s.dataset.name, s.min, s.max, s.value])")
        if names != [["red", "0", "1", "0.5"], ["frame", "1", "3", "1"], ["samples", "1", "16", "1"]]:
            fail(f"the sliders are {names}")
        # linear 0.5 is sRGB byte 188
        expect_colour("sliders: red 0.5, frame 1", canvas_mean(browser, browser.screenshot("slider-1")), 0, 180, 5)
        move_slider(browser, "red", 1)
        browser.wait_for(2, "done")
        expect_colour("sliders: red 1", canvas_mean(browser, browser.screenshot("slider-2")), 0, 250, 5)
        move_slider(browser, "frame", 3)
        browser.wait_for(3, "done")
        mean = canvas_mean(browser, browser.screenshot("slider-3"))
        if mean[0] < 250 or mean[2] < 250 or mean[1] > 5:
            fail(f"frame 3 (clock 1) is not magenta: {mean}")
        move_slider(browser, "samples", 4)
        browser.wait_for(4, "done")
        rays = browser.script("return document.getElementById('stats').textContent")
        if "primary 38400" not in rays:  # 120 x 80 pixels, 4 samples each
            fail(f"the samples slider did not give 4 samples a pixel: {rays}")
        for query, expected in [("name=blue&value=1", 400), ("name=red&value=x", 400),
                                ("name=frame&value=4", 400), ("name=samples&value=0", 400),
                                ("name=frame&value=2", 200)]:
            got = post_status(f"{preview.base}/set?token={preview.token}&{query}")
            if got != expected:
                fail(f"POST /set?{query}: {got}, expected {expected}")
        if post_status(f"{preview.base}/set?name=red&value=1") != 403:
            fail("/set answers without the token")
        print(f"sliders: {names} render again; frame 3 magenta {[round(m) for m in mean]}")
        region(browser, preview)
    finally:
        preview.stop()


def half_means(browser, shot):
    """The mean colours of the canvas's left and right thirds in the screenshot."""
    r = browser.script("const r = document.getElementById('image').getBoundingClientRect();"
                       "return [r.left, r.top, r.width, r.height];")
    width, _, pixels = shot
    def mean(x0, x1):
        sums, n = [0, 0, 0], 0
        for y in range(int(r[1]) + 5, int(r[1] + r[3]) - 5, 2):
            for x in range(x0, x1, 2):
                i = 3 * (y * width + x)
                for c in range(3):
                    sums[c] += pixels[i + c]
                n += 1
        return [round(v / n) for v in sums]
    third = int(r[2] / 3)
    return mean(int(r[0]) + 5, int(r[0]) + third), mean(int(r[0] + r[2]) - third, int(r[0] + r[2]) - 5)


def region(browser, preview):
    """A drag over the left half renders only it: a change shows there alone, until
    "whole image"."""
    browser.wait_for(5, "done")  # frame 2's render (POST /set above), finished before the drag
    browser.script("""const c = document.getElementById('image'), r = c.getBoundingClientRect();
        const at = (type, fx, fy, target) => target.dispatchEvent(new MouseEvent(type,
            {clientX: r.left + r.width * fx, clientY: r.top + r.height * fy, bubbles: true}));
        at('mousedown', 0.001, 0.001, c); at('mousemove', 0.3, 0.5, window);
        at('mouseup', 0.5, 0.999, window);""")
    browser.wait_for(6, "done")  # the region's render, still frame 2 (clock 0.5)
    move_slider(browser, "red", 0)  # the region turns from magenta to blue
    browser.wait_for(7, "done")
    time.sleep(0.2)
    left, right = half_means(browser, browser.screenshot("region"))
    shown = browser.script("return [document.getElementById('region').hidden, "
                           "document.getElementById('whole').hidden]")
    # clock 0.5: linear blue 0.5 is sRGB byte 188
    if left != [0, 0, 188] or right != [255, 0, 188] or shown != [False, False]:
        fail(f"after a change with the left half as the region: left {left}, right {right}, "
             f"region and button hidden: {shown}")
    browser.script("document.getElementById('whole').click()")
    browser.wait_for(8, "done")
    time.sleep(0.2)
    left, right = half_means(browser, browser.screenshot("whole"))
    if left != [0, 0, 188] or right != [0, 0, 188]:
        fail(f"the whole image again: left {left}, right {right}")
    if post_status(f"{preview.base}/region?token={preview.token}&region=5,5,2,9") != 400:
        fail("/region takes an empty rectangle")
    print("region: a change shows in the dragged region only, then in the whole image again")


def wait_comparison(browser, generation, timeout=60):
    end = time.time() + timeout
    while time.time() < end:
        if browser.script("return document.getElementById('comparison').dataset.generation") == str(generation):
            time.sleep(0.3)  # the images decoded
            return
        time.sleep(0.1)
    fail(f"no comparison of render {generation} after {timeout} s")


def image_mean(browser, shot, element):
    r = browser.script(f"const r = document.getElementById('{element}').getBoundingClientRect();"
                       "return [r.left, r.top, r.width, r.height];")
    width, _, pixels = shot
    sums, n = [0, 0, 0], 0
    for y in range(int(r[1]) + 3, int(r[1] + r[3]) - 3, 2):
        for x in range(int(r[0]) + 3, int(r[0] + r[2]) - 3, 2):
            i = 3 * (y * width + x)
            for c in range(3):
                sums[c] += pixels[i + c]
            n += 1
    if n == 0:
        fail(f"#{element} is not shown: {r}")
    return [round(v / n) for v in sums]


def compare_beside(browser, scene):
    """--compare: POV-Ray's render of each save and the difference, beside Lucent's."""
    save(scene, scene_text("0 1 0"))
    preview = Preview(scene, "-w", "120", "-h", "80", "--compare")
    try:
        browser.open(preview.url)
        browser.wait_for(1, "done")
        wait_comparison(browser, 1)
        report = browser.script("return document.getElementById('report').textContent")
        if "psnr:       inf (identical)" not in report:
            fail(f"the comparison's report: {report}")
        shot = browser.screenshot("compare-green")
        if image_mean(browser, shot, "povray") != [0, 255, 0] or image_mean(browser, shot, "diff") != [0, 0, 0]:
            fail(f"POV-Ray's render {image_mean(browser, shot, 'povray')}, the difference "
                 f"{image_mean(browser, shot, 'diff')}")
        save(scene, scene_text("0 0 1"))
        browser.wait_for(2, "done")
        wait_comparison(browser, 2)
        povray = image_mean(browser, browser.screenshot("compare-blue"), "povray")
        if povray != [0, 0, 255]:
            fail(f"POV-Ray's render of the second save: {povray}")
        print("compare: POV-Ray's render and the difference beside each save's render")
    finally:
        preview.stop()


def side_by_side(browser, first, scene2):
    """A second preview of another scene on another port: each page shows its own scene."""
    save(scene2, scene_text("1 1 0"))
    second = Preview(scene2)
    if second.base == first.base:
        fail("two previews on one address")
    browser.open(second.url)
    browser.wait_for(1, "done")
    mean = canvas_mean(browser, browser.screenshot("second"))
    if mean[0] < 200 or mean[1] < 200 or mean[2] > 40:
        fail(f"the second preview does not show its yellow scene: {mean}")
    save(scene2, scene_text("1 0 0"))
    browser.wait_for(2, "done")
    expect_colour("second preview after its save (red)", canvas_mean(browser, browser.screenshot("second-red")), 0)
    browser.open(first.url)
    browser.wait_for(4, "done")  # still the first's fourth render: untouched by the other's save
    expect_colour("first preview beside it (blue)", canvas_mean(browser, browser.screenshot("first-again")), 2)
    return second


def many_saves(browser, preview, scene):
    """Memory after many saves, the page open and receiving every render."""
    generation = 4
    def saves(n):
        nonlocal generation
        for i in range(n):
            save(scene, scene_text(f"0 0 {0.5 + (i % 2) * 0.5}"))
            generation += 1
            browser.wait_for(generation, "done")
    saves(20)
    before = preview.rss_kb()
    start = time.time()
    saves(SAVES)
    after = preview.rss_kb()
    seconds = time.time() - start
    print(f"memory: {before} kB after 20 saves, {after} kB after {SAVES} more "
          f"({seconds / SAVES * 1000:.0f} ms a save)")
    # At most 8 kB a save (2.4 MB over 300): a leak of one image a save (240 x 160 pixels,
    # 12 bytes each: 450 kB) would be 130 MB, one of a tile's PNG (about 10 kB) 3 MB.
    bound_kb = 8 * SAVES
    if after > before + bound_kb and not os.environ.get("LUCENT_PREVIEW_NO_RSS_BOUND"):
        fail(f"the preview grew by {after - before} kB over {SAVES} saves")


def main():
    os.makedirs(WORK, exist_ok=True)
    scene, scene2 = f"{WORK}/scene.xml", f"{WORK}/other.xml"
    save(scene, scene_text("1 0 0"))
    first = Preview(scene)
    check_token(first)
    browser = Browser()
    second = None
    try:
        three_saves(browser, first, scene)
        save_button_and_pixel(browser, first, scene)
        sliders(browser, f"{WORK}/sliders.xml")
        compare_beside(browser, f"{WORK}/compare.xml")
        second = side_by_side(browser, first, scene2)
        browser.open(first.url)
        browser.wait_for(4, "done")
        many_saves(browser, first, scene)
    finally:
        browser.quit()
    first.stop()
    if second:
        second.stop()
    print("preview_in_browser: all checks passed")


if __name__ == "__main__":
    main()
