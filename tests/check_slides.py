#!/usr/bin/env python3
"""Checks the built slide decks in a real browser (headless Chromium, driven over the DevTools protocol on a
pipe, with nothing but the standard library): each deck opens, every image has loaded with a size, every slide's
content fits its page, the page logs no error and throws no exception, and a screenshot of its first slide is
not one flat colour; and that its PDF has a page a slide. Also checks that every link and image path in the
Markdown sources resolves. Usage:
    check_slides.py SLIDES_SOURCE_DIR BUILT_SLIDES_DIR
Exit status 0 when every check passes; each failure is one line naming the deck."""
import base64
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib


class Browser:
    """Chromium with --remote-debugging-pipe: commands in on fd 3, replies and events out on fd 4, each a JSON
    message ended by a NUL byte."""

    def __init__(self, executable):
        self.profile = tempfile.mkdtemp(prefix="gsv-slides-")
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()

        # The child closes every other descriptor after preexec_fn runs, so keep 3 and 4 by number.
        def wire():
            os.dup2(to_browser_r, 3)
            os.dup2(from_browser_w, 4)

        self.process = subprocess.Popen(
            [executable, "--headless=new", "--remote-debugging-pipe", "--no-sandbox", "--disable-gpu",
             "--no-first-run", "--no-default-browser-check", "--allow-file-access-from-files",
             "--window-size=1280,800", "--user-data-dir=" + self.profile, "about:blank"],
            pass_fds=(3, 4), preexec_fn=wire,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            if time.time() > deadline:
                raise TimeoutError("the browser did not answer in time")
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=30):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(method + ": " + reply["error"].get("message", "error"))
                return reply.get("result", {})
            self.events.append(reply)

    def wait_for(self, method, session, timeout=30):
        deadline = time.time() + timeout
        for i, event in enumerate(self.events):
            if event.get("method") == method and event.get("sessionId") == session:
                return self.events.pop(i)
        while True:
            event = self._read_message(deadline)
            if event.get("method") == method and event.get("sessionId") == session:
                return event
            self.events.append(event)

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def png_is_flat(data):
    """True when every pixel of an 8-bit RGB or RGBA, non-interlaced PNG has the same colour."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("unexpected PNG format")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    previous = bytearray(stride)
    first = None
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
        if first is None:
            first = bytes(line[:channels])
        if line != first * width:
            return False
        previous = line
    return True


def markdown_paths(text):
    """The targets of Markdown links and images, without titles or attributes; web links and anchors left out."""
    for block in re.findall(r"```\{\.include\}\n(.*?)\n```", text, flags=re.S):
        yield block.strip()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    for target in re.findall(r"\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", text):
        if not re.match(r"^[a-z]+:", target) and not target.startswith("#"):
            yield target.split("#")[0]


def check_sources(source_dir, built_dir):
    failures = []
    for name in sorted(os.listdir(source_dir)):
        if not name.endswith(".md"):
            continue
        with open(os.path.join(source_dir, name), encoding="utf-8") as f:
            text = f.read()
        for target in markdown_paths(text):
            places = [os.path.join(source_dir, target), os.path.join(built_dir, target)]
            if not any(os.path.exists(p) for p in places):
                failures.append(f"{name}: '{target}' resolves to no file (looked in {source_dir} and {built_dir})")
    return failures


def check_index(built_dir, decks):
    """The decks' index names every deck, and each of its links is a file beside it."""
    index = os.path.join(built_dir, "index.html")
    if not os.path.exists(index):
        return [f"no {index} was built"]
    with open(index, encoding="utf-8") as f:
        links = re.findall(r'href="([^"]+)"', f.read())
    failures = [f"index.html: '{link}' resolves to no file in {built_dir}" for link in links
                if not link.startswith("data:") and not os.path.exists(os.path.join(built_dir, link))]
    failures += [f"index.html: no link to {deck}.html" for deck in decks if deck + ".html" not in links]
    return failures


def check_deck(browser, path):
    failures = []
    deck = os.path.basename(path)
    target = browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    for domain in ("Page.enable", "Runtime.enable", "Log.enable"):
        browser.call(domain, session=session)
    browser.call("Page.navigate", {"url": "file://" + os.path.abspath(path)}, session=session)
    browser.wait_for("Page.loadEventFired", session)
    images = browser.call("Runtime.evaluate", {
        "expression": "Array.from(document.images).map(i => [i.getAttribute('alt') || i.src.slice(0, 60), "
                      "i.complete && i.naturalWidth > 0 && i.naturalHeight > 0])",
        "returnByValue": True}, session=session)["result"]["value"]
    for alt, loaded in images:
        if not loaded:
            failures.append(f"{deck}: the image '{alt}' did not load")
    slides = browser.call("Runtime.evaluate", {"expression": "document.querySelectorAll('section').length",
                                               "returnByValue": True}, session=session)["result"]["value"]
    if slides < 2:
        failures.append(f"{deck}: {slides} slides")
    # A slide is a fixed 800 x 600 page that hides what does not fit: text or a table past its edge is lost
    # in the lecture hall.
    overflowing = browser.call("Runtime.evaluate", {
        "expression": "Array.from(document.querySelectorAll('section')).map((s, i) => [i + 1, "
                      "(s.querySelector('h1, h2') || {}).textContent || '', s.scrollWidth - s.clientWidth, "
                      "s.scrollHeight - s.clientHeight]).filter(a => a[2] > 2 || a[3] > 2)",
        "returnByValue": True}, session=session)["result"]["value"]
    for number, title, wide, tall in overflowing:
        failures.append(f"{deck}: slide {number} '{title}' does not fit its page ({wide} px too wide, {tall} px too tall)")
    shot = base64.b64decode(browser.call("Page.captureScreenshot", {"format": "png"}, session=session)["data"])
    if png_is_flat(shot):
        failures.append(f"{deck}: the screenshot of its first slide is one flat colour")
    for event in list(browser.events):
        if event.get("sessionId") != session:
            continue
        method, params = event.get("method"), event.get("params", {})
        if method == "Runtime.exceptionThrown":
            failures.append(f"{deck}: exception: {params['exceptionDetails'].get('text', '')}")
        elif method == "Runtime.consoleAPICalled" and params.get("type") == "error":
            failures.append(f"{deck}: console error: {params.get('args', [{}])[0].get('value', '')}")
        elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
            failures.append(f"{deck}: logged error: {params['entry'].get('text', '')}")
    browser.events = [e for e in browser.events if e.get("sessionId") != session]
    browser.call("Target.closeTarget", {"targetId": target})
    return failures, len(images), slides


def main():
    if len(sys.argv) != 3:
        print("usage: check_slides.py SLIDES_SOURCE_DIR BUILT_SLIDES_DIR", file=sys.stderr)
        return 2
    source_dir, built_dir = sys.argv[1], sys.argv[2]
    failures = check_sources(source_dir, built_dir)
    decks = sorted(n[:-3] for n in os.listdir(source_dir) if n.endswith(".md"))
    failures += check_index(built_dir, decks)
    chromium = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if not chromium:
        print("check_slides: no chromium to open the decks with", file=sys.stderr)
        return 2
    browser = Browser(chromium)
    try:
        for deck in decks:
            html = os.path.join(built_dir, deck + ".html")
            if not os.path.exists(html):
                failures.append(f"{deck}.md: no {html} was built")
                continue
            found, images, slides = check_deck(browser, html)
            failures += found
            # The printed copy: one page a slide.
            pdf = os.path.join(built_dir, deck + ".pdf")
            if not os.path.exists(pdf):
                failures.append(f"{deck}.md: no {pdf} was printed")
            else:
                with open(pdf, "rb") as f:
                    pages = len(re.findall(rb"/Type\s*/Page[^s]", f.read()))
                if pages != slides:
                    failures.append(f"{deck}.pdf: {pages} pages for {slides} slides")
            print(f"check_slides: {deck}.html: {slides} slides, {images} images" + ("" if found else ", fine"))
    finally:
        browser.close()
    for failure in failures:
        print("check_slides: " + failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
