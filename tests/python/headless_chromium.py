"""A page in headless Chromium (Debian's /usr/bin/chromium), driven through the DevTools protocol
over a pipe (--remote-debugging-pipe: JSON messages ending in NUL, Chromium reads fd 3 and
writes fd 4), with no network: the proxy is an address where nothing listens.

    with Page("file:///tmp/site/index.html") as page:
        page.evaluate("document.title")          # a promise is awaited

A test asks the page what it did and decides what is right; this module judges nothing."""

import fcntl
import json
import os
import shutil
import subprocess
import tempfile

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"


def available():
    return os.access(CHROMIUM, os.X_OK)


class Page:
    def __init__(self, url):
        self._url = url
        self._profile = tempfile.TemporaryDirectory(prefix="tumble_chromium_")
        to_chromium_read, self._to_chromium = os.pipe()
        self._from_chromium, from_chromium_write = os.pipe()

        def pipe_fds():  # moved clear of 3 and 4 first, so that neither dup2 closes the other
            read_end = fcntl.fcntl(to_chromium_read, fcntl.F_DUPFD, 10)
            write_end = fcntl.fcntl(from_chromium_write, fcntl.F_DUPFD, 10)
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        self._process = subprocess.Popen(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--mute-audio", "--autoplay-policy=no-user-gesture-required",
             "--allow-file-access-from-files", "--proxy-server=http://127.0.0.1:9",
             "--user-data-dir=" + self._profile.name, "--remote-debugging-pipe", "about:blank"],
            pass_fds=(3, 4), preexec_fn=pipe_fds, stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chromium_read)
        os.close(from_chromium_write)
        self._buffer = b""
        self._next_id = 0
        self._events = []
        self._session = None

    def __enter__(self):
        try:
            target = next(t for t in self._send("Target.getTargets")["targetInfos"]
                          if t["type"] == "page")
            self._session = self._send("Target.attachToTarget",
                                       {"targetId": target["targetId"], "flatten": True})["sessionId"]
            self._send("Page.enable")
            self._send("Page.navigate", {"url": self._url})
            while not any(e.get("method") == "Page.loadEventFired" for e in self._events):
                self._events.append(self._read())
        except BaseException:
            self.close()
            raise
        return self

    def __exit__(self, *exc):
        self.close()

    def evaluate(self, expression):
        """The value of a JavaScript expression in the page (a promise's, once it settles)."""
        reply = self._send("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                                "returnByValue": True})
        if "exceptionDetails" in reply:
            details = reply["exceptionDetails"]
            raise RuntimeError(details.get("exception", {}).get("description", str(details)))
        return reply["result"].get("value")

    def _send(self, method, params=None):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if self._session and not method.startswith("Target."):
            message["sessionId"] = self._session
        os.write(self._to_chromium, json.dumps(message).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]
            self._events.append(reply)

    def _read(self):
        while b"\0" not in self._buffer:
            chunk = os.read(self._from_chromium, 1 << 20)
            if not chunk:
                raise RuntimeError("chromium closed the DevTools pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def close(self):
        if self._process.poll() is None:
            try:
                os.write(self._to_chromium, json.dumps(
                    {"id": 0, "method": "Browser.close", "params": {}}).encode() + b"\0")
            except OSError:
                pass
            try:
                self._process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
        for fd in (self._to_chromium, self._from_chromium):
            try:
                os.close(fd)
            except OSError:
                pass
        self._profile.cleanup()
