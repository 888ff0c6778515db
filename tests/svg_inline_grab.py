#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Screenshots of the elements of a page, as headless Chromium shows them.

Usage: svg_inline_grab.py CHROMIUM PAGE.html OUT_DIR WIDTH HEIGHT ID...

The page is shown in a viewport of WIDTH x HEIGHT CSS pixels at one device pixel to the CSS
pixel; each element ID (its bounding box) becomes OUT_DIR/ID.png.
"""
import base64
import json
import os
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_grab import Browser  # noqa: E402


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    exe, page, out_dir, width, height = sys.argv[1:6]
    ids = sys.argv[6:]
    signal.alarm(240)
    browser = Browser(exe)
    try:
        target = browser.call("Target.createTarget", url="about:blank")["targetId"]
        browser.session = browser.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        browser.call("Emulation.setDeviceMetricsOverride", width=int(width), height=int(height),
                     deviceScaleFactor=1, mobile=False)
        browser.call("Page.navigate", url="file://" + os.path.abspath(page))
        browser.evaluate("new Promise(done => document.readyState === 'complete' ? done() : "
                         "addEventListener('load', () => done()))")
        browser.evaluate("Promise.all([...document.images].map(i => i.decode()))")
        for element in ids:
            box = browser.evaluate("(() => { const r = document.getElementById(%s).getBoundingClientRect();"
                                   " return [r.x, r.y, r.width, r.height]; })()" % json.dumps(element))
            shot = browser.call("Page.captureScreenshot", format="png",
                                clip={"x": box[0], "y": box[1], "width": box[2], "height": box[3], "scale": 1})
            with open(os.path.join(out_dir, element + ".png"), "wb") as f:
                f.write(base64.b64decode(shot["data"]))
    finally:
        browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
