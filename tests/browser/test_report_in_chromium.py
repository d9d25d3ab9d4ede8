# SPDX-License-Identifier: MIT
"""report.html in a real browser: headless Chromium loads it from a file URL with the
network off, nothing fails to load, and its screenshot shows the run's pictures."""
import os
import re
import shutil
import subprocess
import tempfile

import numpy as np
import pytest
from PIL import Image  # python3-pil (matplotlib's own image library)

WIDTH, HEIGHT = 1000, 4400  # tall enough for the header and all five pictures


def chromium_binary():
    return os.environ.get("FORMFLOW_CHROMIUM") or shutil.which("chromium")


def chromium(*arguments, profile):
    """Runs headless Chromium with the network off; returns (stdout, stderr)."""
    command = [chromium_binary(), "--headless", "--disable-gpu", "--no-first-run",
               "--no-default-browser-check", "--disable-extensions", "--hide-scrollbars",
               f"--user-data-dir={profile}",
               # No network: every host resolves nowhere and any proxy use fails.
               "--host-resolver-rules=MAP * ~NOTFOUND", "--proxy-server=127.0.0.1:9",
               "--enable-logging=stderr", "--v=0", "--force-device-scale-factor=1",
               f"--window-size={WIDTH},{HEIGHT}", *arguments]
    if os.geteuid() == 0:
        command.insert(1, "--no-sandbox")  # Chromium refuses to run as root otherwise (CI)
    completed = subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)
    assert completed.returncode == 0, completed.stderr
    return completed.stdout, completed.stderr


# What the page's console said. The report has no script, so a console message can
# only be the browser's about the page: above all a resource its Content Security
# Policy (nothing but data: images) refused to load, which is how a reference to a
# file or to the network shows. (Chromium's own background services log network
# errors too, on other lines: those say nothing about the page.)
LOAD_FAILURES = re.compile(r":CONSOLE[^\n]*")


@pytest.fixture(scope="module")
def report():
    scratch = tempfile.mkdtemp(prefix="formflow-browser-")
    output = os.path.join(scratch, "out")
    completed = subprocess.run([os.environ["FORMFLOW_BINARY"], "run", "--set",
                                "mesh.size=2.5", "-q", "-o", output],
                               capture_output=True, text=True, timeout=600, check=False)
    assert completed.returncode == 0, completed.stderr
    yield scratch, os.path.join(output, "report.html")
    shutil.rmtree(scratch, ignore_errors=True)


def saturated_fraction(path):
    """Share of pixels with a strong colour: the page itself is black, grey and pale
    tints (max − min of RGB below 60), the pictures' colour maps are not."""
    image = Image.open(path).convert("RGB")
    pixels = np.asarray(image, dtype=np.int16)
    spread = pixels.max(axis=2) - pixels.min(axis=2)
    return image.size, float(np.mean(spread > 100))


def test_the_dom_is_the_whole_report(report):
    scratch, page = report
    dom, log = chromium("--dump-dom", f"file://{page}", profile=os.path.join(scratch, "dom"))
    assert not LOAD_FAILURES.search(log), log
    images = re.findall(r'<img src="([^"]*)"', dom)
    # strain rate, velocity, pressure, contact, convergence, load error, exit velocity
    assert len(images) == 7
    assert all(src.startswith("data:image/svg+xml;base64,") for src in images)
    assert "<script" not in dom and "ram reaction" in dom and dom.rstrip().endswith("</html>")
    # The policy that makes any other load a logged refusal.
    assert "default-src 'none'; img-src data:" in dom


def test_the_screenshot_shows_the_pictures_and_nothing_failed(report):
    scratch, page = report
    shot = os.path.join(scratch, "report.png")
    _, log = chromium(f"--screenshot={shot}", f"file://{page}",
                      profile=os.path.join(scratch, "shot"))
    assert not LOAD_FAILURES.search(log), log
    size, fraction = saturated_fraction(shot)
    assert size == (WIDTH, HEIGHT)
    assert fraction > 0.05, fraction


def test_the_checks_see_a_page_whose_pictures_fail(report):
    # Control: the same page with its pictures' data emptied, one picture from a file
    # that is not there and one from the network. The log must show the failures and
    # the screenshot (almost) no colour, or the checks above prove nothing.
    scratch, page = report
    broken = os.path.join(scratch, "broken.html")
    with open(page, encoding="utf-8") as source:
        text = re.sub(r'src="data:image/svg\+xml;base64,[^"]*"',
                      'src="data:image/svg+xml;base64,"', source.read())
    text = text.replace("</body>", '<img src="missing.png"><img src="http://example.invalid/x.png">'
                        "</body>")
    with open(broken, "w", encoding="utf-8") as target:
        target.write(text)
    shot = os.path.join(scratch, "broken.png")
    _, log = chromium(f"--screenshot={shot}", f"file://{broken}",
                      profile=os.path.join(scratch, "broken"))
    assert LOAD_FAILURES.search(log), log
    _, fraction = saturated_fraction(shot)
    assert fraction < 0.01, fraction
