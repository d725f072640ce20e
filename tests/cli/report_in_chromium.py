"""Opens a report.html in headless Chromium, as a reader's browser would.

Usage: report_in_chromium.py REPORT.html SCRATCH_DIR KEY...

Prints, one per line:
  model_picture N      <svg id="model-picture"> elements in the rendered page
  raw_keys K,K,...     the given report.json keys found in the page's prose
  screenshot W H       the screenshot's size in pixels
  model_pixels N       screenshot pixels in the picture's colours (not grey/white)
Exits 1 when Chromium is missing or fails.
"""
import html.parser
import os
import shutil
import subprocess
import sys

import matplotlib.image


class VisibleText(html.parser.HTMLParser):
    """The page's prose as a reader sees it: no tags, no attributes (tooltips),
    no <code> (names a reader types, e.g. ParaView's array names)."""

    def __init__(self):
        super().__init__()
        self.parts = []
        self.code = 0

    def handle_starttag(self, tag, attrs):
        self.code += tag == "code"

    def handle_endtag(self, tag):
        self.code -= tag == "code"

    def handle_data(self, data):
        if not self.code:
            self.parts.append(data)


def chromium(args):
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        sys.exit("chromium is not installed (scripts/setup.sh installs it)")
    base = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
            "--user-data-dir=" + os.path.join(SCRATCH, "profile")]
    r = subprocess.run(base + args, capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        sys.exit("chromium failed: " + r.stderr[-2000:])
    return r.stdout


page, SCRATCH, keys = sys.argv[1], sys.argv[2], sys.argv[3:]
os.makedirs(SCRATCH, exist_ok=True)
url = "file://" + os.path.abspath(page)
dom = chromium(["--dump-dom", url])
parser = VisibleText()
parser.feed(dom)
text = " ".join(parser.parts)
print("model_picture", dom.count('<svg id="model-picture"'))
words = set(text.replace(",", " ").replace(":", " ").split())
print("raw_keys", ",".join(k for k in keys if k in words))

png = os.path.join(SCRATCH, "report.png")
chromium(["--window-size=1280,2400", "--screenshot=" + png, url])
image = matplotlib.image.imread(png)[:, :, :3]
print("screenshot", image.shape[1], image.shape[0])
spread = image.max(axis=2) - image.min(axis=2)  # 0 for grey, white and black
print("model_pixels", int((spread > 0.25).sum()))
