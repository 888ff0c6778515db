#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws pictures with headless Chromium and writes them as PNG files.

Usage: browser_grab.py CHROMIUM PAGE.html OUT_DIR

PAGE.html defines grab_all(), a promise of {name: "data:image/png;base64,..." or
"error: ..."}. Chromium is driven over its DevTools pipe (--remote-debugging-pipe: JSON
messages ending in a NUL byte on file descriptors 3 and 4), in real time, so that videos
load and seek as they do in a browser a reader uses; each picture becomes OUT_DIR/NAME.png.
Exit status 1 names the pictures that failed.
"""
import base64
import json
import os
import signal
import subprocess
import sys


class Browser:
    def __init__(self, exe):
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()

        def pipes():
            # Through copies: a pipe may already be 3 or 4, and dup2 onto itself would
            # leave it closed on exec.
            reads, writes = os.dup(to_child_r), os.dup(from_child_w)
            os.dup2(reads, 3)
            os.dup2(writes, 4)

        self.proc = subprocess.Popen(
            [exe, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
             "--allow-file-access-from-files", "--autoplay-policy=no-user-gesture-required",
             "--hide-scrollbars", "about:blank"],
            preexec_fn=pipes, close_fds=False, stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_child_r)
        os.close(from_child_w)
        self.buffer = b""
        self.next_id = 0
        self.session = None

    def call(self, method, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if self.session:
            message["sessionId"] = self.session
        os.write(self.to_child, json.dumps(message).encode() + b"\0")
        while True:
            while b"\0" not in self.buffer:
                chunk = os.read(self.from_child, 1 << 20)
                if not chunk:
                    raise RuntimeError("chromium closed its pipe during " + method)
                self.buffer += chunk
            raw, self.buffer = self.buffer.split(b"\0", 1)
            reply = json.loads(raw)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(method + ": " + json.dumps(reply["error"]))
                return reply["result"]

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(json.dumps(result["exceptionDetails"])[:500])
        return result["result"].get("value")

    def close(self):
        try:
            self.session = None
            self.call("Browser.close")
        except (RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    exe, page, out_dir = sys.argv[1:]
    signal.alarm(240)
    browser = Browser(exe)
    try:
        target = browser.call("Target.createTarget", url="about:blank")["targetId"]
        browser.session = browser.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        browser.call("Page.navigate", url="file://" + os.path.abspath(page))
        browser.evaluate("new Promise(done => document.readyState === 'complete' ? done() : "
                         "addEventListener('load', () => done()))")
        pictures = browser.evaluate("grab_all()")
    finally:
        browser.close()
    failed = []
    for name, url in sorted(pictures.items()):
        prefix = "data:image/png;base64,"
        if not url.startswith(prefix):
            failed.append(name + ": " + url)
            continue
        with open(os.path.join(out_dir, name + ".png"), "wb") as f:
            f.write(base64.b64decode(url[len(prefix):]))
    for line in failed:
        print("FAIL: " + line)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
