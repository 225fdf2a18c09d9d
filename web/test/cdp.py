"""A headless Chromium driven over its DevTools protocol through a pipe (--remote-debugging-pipe:
commands on fd 3, replies on fd 4, each a JSON text ended by a NUL byte), and a static file server
on the loopback address. Python's standard library only: no WebSocket client, no ChromeDriver."""

import functools
import http.server
import json
import os
import subprocess
import tempfile
import threading
import time


class StaticServer:
    """Serves `root` on 127.0.0.1 (a free port) from a thread; .wasm as application/wasm."""

    def __init__(self, root):
        handler = functools.partial(_QuietHandler, directory=root)
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.url = "http://127.0.0.1:%d/" % self.httpd.server_address[1]
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()

    def close(self):
        self.httpd.shutdown()
        self.httpd.server_close()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = dict(http.server.SimpleHTTPRequestHandler.extensions_map, **{".wasm": "application/wasm"})

    def log_message(self, *args):
        pass


class Chromium:
    """One headless Chromium with one page; evaluate() runs JavaScript in it."""

    def __init__(self, binary, width=1200, height=700):
        self.profile = tempfile.TemporaryDirectory(prefix="sss-web-chromium-")
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        # The child reads commands on fd 3 and writes replies on fd 4: a shell puts the pipes there
        # and execs Chromium (subprocess would close fds 3 and 4 if a preexec_fn made them). No
        # sandbox: CI runs as root, where Chromium's refuses to start; no /dev/shm: containers keep it small.
        args = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                "--remote-debugging-pipe", "--no-first-run", "--no-default-browser-check",
                "--no-sandbox", "--disable-dev-shm-usage", "--disable-extensions",
                "--user-data-dir=" + self.profile.name,
                "--window-size=%d,%d" % (width, height), "about:blank"]
        shell = 'exec "$0" "$@" 3<&%d 4>&%d' % (to_browser_r, from_browser_w)
        self.log = open(os.path.join(self.profile.name, "chromium.log"), "w")
        self.process = subprocess.Popen(["/bin/sh", "-c", shell, binary] + args, stdin=subprocess.DEVNULL,
                                        stdout=self.log, stderr=self.log, pass_fds=(to_browser_r, from_browser_w))
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._buffer = b""
        self._next_id = 0
        self.session = None

    def send(self, method, params=None, session=True, timeout=120):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if session and self.session:
            message["sessionId"] = self.session
        os.write(self._to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read(deadline)
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError("%s: %s" % (method, reply["error"]))
                return reply.get("result", {})

    def _read(self, deadline):
        while b"\0" not in self._buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("no reply from Chromium in time")
            chunk = os.read(self._from_browser, 1 << 20)
            if not chunk:
                raise RuntimeError("Chromium closed its DevTools pipe (exit %s)" % self.process.poll())
            self._buffer += chunk
        text, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(text)

    def open(self, url):
        target = self.send("Target.createTarget", {"url": url}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                                 session=False)["sessionId"]

    def evaluate(self, expression, timeout=300):
        result = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True}, timeout=timeout)
        if "exceptionDetails" in result:
            raise RuntimeError("page script failed: %s" % json.dumps(result["exceptionDetails"])[:2000])
        return result["result"].get("value")

    def wait_for(self, expression, timeout=300):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(0.25)
        raise TimeoutError("the page never satisfied: " + expression)

    def screenshot_png(self, width, height):
        import base64
        self.send("Emulation.setDeviceMetricsOverride", {"width": width, "height": height, "deviceScaleFactor": 1,
                                                         "mobile": False})
        return base64.b64decode(self.send("Page.captureScreenshot", {"format": "png"})["data"])

    def close(self):
        try:
            self.send("Browser.close", session=False, timeout=10)
        except Exception:  # already gone: the wait below reaps it
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self._to_browser)
        os.close(self._from_browser)
        self.log.close()
        self.profile.cleanup()
