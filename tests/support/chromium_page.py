#!/usr/bin/env python3
"""Drives a page in headless Chromium through the DevTools protocol, for tests of html pages.

    chromium_page.py URL STEPS_JSON

opens URL in a fresh headless Chromium with no network (its proxy is an address where nothing
listens), runs the steps in order and prints one JSON object: {"results": [one per step],
"requests": [every URL the page asked for], "errors": [exceptions and console errors]}.

A step is one of
    {"viewport": [W, H]}            the page's size in CSS px (device scale 1); W or H may be a
                                    JS expression (of the page loaded by then), its value used
    {"wait": "JS expression"}       until it is truthy (its value is the result), or fails after
                                    "timeout" seconds (default 20): a page that never gets there
    {"eval": "JS expression"}       its value (a promise is awaited)
        Either may name "frame": N, to run in the page's Nth frame (an iframe, in document
        order) instead, in a world of its own there: it sees that frame's DOM, not its script.
    {"screenshot": "out.png", "clip": "CSS selector"}   that element's box, as a PNG file
    {"data_url": "JS expression", "to": "out.png"}      its value, a data: URL, decoded to a file

Exit status 0 when every step ran, 1 with the reason on stderr otherwise. The result says what
the page did; the test decides what is right.
"""
import base64
import fcntl
import json
import os
import subprocess
import sys
import tempfile
import time


class Browser:
    def __init__(self):
        self.profile = tempfile.TemporaryDirectory(prefix="chromium_page_")
        to_chromium_r, self.to_chromium = os.pipe()
        self.from_chromium, from_chromium_w = os.pipe()

        def child_fds():  # the pipe protocol: Chromium reads fd 3 and writes fd 4
            read_end = fcntl.fcntl(to_chromium_r, fcntl.F_DUPFD, 10)  # clear of 3 and 4 first
            write_end = fcntl.fcntl(from_chromium_w, fcntl.F_DUPFD, 10)
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        self.process = subprocess.Popen(
            ["chromium", "--headless", "--no-sandbox", "--disable-gpu",
             "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--hide-scrollbars", "--mute-audio",
             "--proxy-server=http://127.0.0.1:9", "--proxy-bypass-list=<-loopback>",
             "--user-data-dir=" + self.profile.name, "--remote-debugging-pipe", "about:blank"],
            pass_fds=(3, 4), preexec_fn=child_fds,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chromium_r)
        os.close(from_chromium_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def send(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_chromium, json.dumps(message).encode() + b"\0")
        while True:
            reply = self.read()
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]
            self.events.append(reply)

    def wait_for_event(self, method):
        while not any(event.get("method") == method for event in self.events):
            self.events.append(self.read())

    def read(self):
        while b"\0" not in self.buffer:
            chunk = os.read(self.from_chromium, 1 << 20)
            if not chunk:
                raise RuntimeError("chromium closed the DevTools pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def close(self):
        try:
            self.send("Browser.close")
        except RuntimeError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.profile.cleanup()


def evaluate(browser, session, expression, context=None):
    params = {"expression": expression, "awaitPromise": True, "returnByValue": True}
    if context is not None:
        params["contextId"] = context
    reply = browser.send("Runtime.evaluate", params, session)
    if "exceptionDetails" in reply:
        details = reply["exceptionDetails"]
        raise RuntimeError(f"{expression}: {details.get('exception', {}).get('description', details)}")
    return reply["result"].get("value")


def run(url, steps):
    browser = Browser()
    try:
        page = next(t for t in browser.send("Target.getTargets")["targetInfos"]
                    if t["type"] == "page")
        session = browser.send("Target.attachToTarget",
                               {"targetId": page["targetId"], "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Network", "Log"):
            browser.send(domain + ".enable", session=session)
        results = []
        navigated = False
        for step in steps:
            if "viewport" in step:
                width, height = (evaluate(browser, session, side) if isinstance(side, str)
                                 else side for side in step["viewport"])
                browser.send("Emulation.setDeviceMetricsOverride",
                             {"width": width, "height": height, "deviceScaleFactor": 1,
                              "mobile": False}, session)
                results.append(None)
                continue
            if not navigated:
                browser.send("Page.navigate", {"url": url}, session)
                browser.wait_for_event("Page.loadEventFired")
                navigated = True
            context = None
            if "frame" in step:
                frames = browser.send("Page.getFrameTree", session=session)["frameTree"]
                frame = frames.get("childFrames", [])[step["frame"]]["frame"]["id"]
                context = browser.send("Page.createIsolatedWorld",
                                       {"frameId": frame, "worldName": "chromium_page"},
                                       session)["executionContextId"]
            if "wait" in step:
                deadline = time.monotonic() + step.get("timeout", 20)
                while True:
                    value = evaluate(browser, session, step["wait"], context)
                    if value:
                        break
                    if time.monotonic() > deadline:
                        raise RuntimeError(f"waited {step.get('timeout', 20)} s for {step['wait']}")
                    time.sleep(0.05)
                results.append(value)
            elif "eval" in step:
                results.append(evaluate(browser, session, step["eval"], context))
            elif "data_url" in step:
                url = evaluate(browser, session, step["data_url"])
                with open(step["to"], "wb") as out:
                    out.write(base64.b64decode(url.split(",", 1)[1]))
                results.append(len(url))
            elif "screenshot" in step:
                box = evaluate(browser, session,
                               "(() => { const r = document.querySelector(" +
                               json.dumps(step["clip"]) + ").getBoundingClientRect();"
                               " return [r.x, r.y, r.width, r.height]; })()")
                shot = browser.send("Page.captureScreenshot", {
                    "format": "png", "clip": {"x": box[0], "y": box[1], "width": box[2],
                                              "height": box[3], "scale": 1}}, session)
                with open(step["screenshot"], "wb") as out:
                    out.write(base64.b64decode(shot["data"]))
                results.append(box)
        requests, errors = [], []
        for event in browser.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Network.requestWillBeSent":
                requests.append(params["request"]["url"])
            elif method == "Runtime.exceptionThrown":
                errors.append(params["exceptionDetails"].get("exception", {}).get(
                    "description", params["exceptionDetails"].get("text")))
            elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
                errors.append(params["entry"]["text"])
            elif method == "Runtime.consoleAPICalled" and params["type"] == "error":
                errors.append(" ".join(str(a.get("value", a.get("description")))
                                       for a in params["args"]))
        return {"results": results, "requests": requests, "errors": errors}
    finally:
        browser.close()


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    try:
        print(json.dumps(run(sys.argv[1], json.loads(sys.argv[2])), separators=(",", ":")))
    except (RuntimeError, OSError, StopIteration, ValueError, IndexError, KeyError) as error:
        print(f"chromium_page.py: {error}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
