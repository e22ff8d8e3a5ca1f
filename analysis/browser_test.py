#!/usr/bin/python3
"""Opens a report (analysis/report.py) in headless Chromium and checks that it works: no console message,
every plot rendered with its data, the bounds and keys tables filled, and (--drawn) a key's decomposition
drawn, the one the address names with --key; then keeps a screenshot of the page's top (headless Chromium
draws a page scrolled to a key blank).

Chromium runs twice, each time with a fresh profile in a temporary folder: once to dump the DOM after the
page's scripts ran (--dump-dom, under a virtual time budget), once to take the screenshot. Its log on
stderr carries the page's console as lines containing "CONSOLE"; they do not say the level (console.log,
console.error and uncaught exceptions look alike), and the report logs nothing, so any console line fails.
A failure exits 1 with one line saying what failed.

usage: browser_test.py --report FILE --screenshot PNG [--drawn] [--key KEY] [--chromium /usr/bin/chromium]
                       [--timeout SECONDS]
"""

import argparse
import html.parser
import os
import signal
import subprocess
import sys
import tempfile
import time
import urllib.parse

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0",
         "--virtual-time-budget=10000", "--hide-scrollbars"]
SCREEN = "--window-size=1400,4000"


class Failure(Exception):
    pass


class ReportDom(html.parser.HTMLParser):
    """What the dumped DOM holds: per plot div (class pd-plot), the plotly SVGs (main-svg) and the marks of
    its data (path.point, or a js-line path with a d), and the rows of the tables by id. Only div and table
    elements are counted for nesting: the DOM's serialisation always closes them (not so <img>, <input>)."""

    def __init__(self):
        super().__init__()
        self.plots = {}  # id -> {"svg": n, "points": n, "lines": n}
        self.rows = {}  # table id -> rows in its tbody
        self.drawing = {"svg": 0, "pieces": 0, "title": ""}  # what div#pd-drawing shows
        self._divs, self._plot_depth, self._plot = 0, None, None
        self._drawing_depth, self._in_title = None, False
        self._tables, self._table = [], None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        classes = (attrs.get("class") or "").split()
        if tag == "div":
            self._divs += 1
            if attrs.get("id") == "pd-drawing":
                self._drawing_depth = self._divs
            if "pd-plot" in classes and self._plot is None:
                self._plot, self._plot_depth = attrs.get("id", "?"), self._divs
                self.plots[self._plot] = {"svg": 0, "points": 0, "lines": 0}
        elif tag == "table":
            self._tables.append(attrs.get("id"))
        elif tag == "tr" and self._tables and self._tables[-1]:
            self.rows[self._tables[-1]] = self.rows.get(self._tables[-1], 0) + 1
        if self._drawing_depth is not None:
            self.drawing["svg"] += tag == "svg"
            self.drawing["pieces"] += tag == "polygon" and "piece" in classes
            self._in_title = tag == "h3"
        if self._plot is not None:
            marks = self.plots[self._plot]
            if tag == "svg" and "main-svg" in classes:
                marks["svg"] += 1
            elif tag == "path" and "point" in classes:
                marks["points"] += 1
            elif tag == "path" and "js-line" in classes and (attrs.get("d") or "").strip():
                marks["lines"] += 1

    def handle_data(self, data):
        if self._in_title:
            self.drawing["title"] += data

    def handle_endtag(self, tag):
        self._in_title = self._in_title and tag != "h3"
        if tag == "div":
            if self._plot is not None and self._divs == self._plot_depth:
                self._plot = None
            if self._divs == self._drawing_depth:
                self._drawing_depth = None
            self._divs -= 1
        elif tag == "table" and self._tables:
            self._tables.pop()


def check_dom(dom, key=None, drawn=False):
    """A summary line of a rendered report's DOM, or Failure saying what is missing. The header row of a
    table is counted among its rows, so a filled table has two at least. With drawn (the page has drawings),
    the key shown (`key`, which the address named, or the first drawn) must be drawn with its pieces."""
    parser = ReportDom()
    parser.feed(dom)
    drawing = parser.drawing
    if key is not None and drawing["title"] != key:
        raise Failure("the page shows key {!r}, not {!r} that its address names".format(drawing["title"], key))
    if drawn and not (drawing["svg"] and drawing["pieces"]):
        raise Failure("the key shown ({}) is not drawn: no svg with polygon.piece in #pd-drawing".format(
            drawing["title"] or "none"))
    if not parser.plots:
        raise Failure("no plot (div.pd-plot) in the page")
    for plot_id, marks in parser.plots.items():
        if not marks["svg"]:
            raise Failure("plot {} was not rendered (no svg.main-svg)".format(plot_id))
        if not marks["points"] and not marks["lines"]:
            raise Failure("plot {} shows no data (no path.point nor a drawn js-line)".format(plot_id))
    if parser.rows.get("pd-bounds", 0) < 2:
        raise Failure("the bounds table (#pd-bounds) has no rows")
    if parser.rows.get("pd-keys", 0) < 2:
        raise Failure("the keys table (#pd-keys) has no rows: its script did not run")
    points = sum(m["points"] for m in parser.plots.values())
    return "{} plots rendered ({} points), {} bounds rows, {} key rows shown{}".format(
        len(parser.plots), points, parser.rows["pd-bounds"] - 1, parser.rows["pd-keys"] - 1,
        ", {} drawn in {} pieces".format(drawing["title"], drawing["pieces"]) if drawn else "")


def console_lines(stderr):
    return [line.strip() for line in stderr.splitlines() if "CONSOLE" in line]


def run_chromium(chromium, args, timeout):
    """(exit status, stdout, stderr) of one Chromium run in a fresh profile. On a timeout its whole process
    group (it starts a dozen helpers) is killed, and Failure raised."""
    with tempfile.TemporaryDirectory(prefix="pd-browser-") as profile:
        command = [chromium] + FLAGS + ["--user-data-dir=" + profile] + args
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                   errors="replace", start_new_session=True)
        try:
            out, err = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            raise Failure("chromium did not finish within {} s".format(timeout))
    return process.returncode, out, err


def check_report(report, screenshot, chromium, timeout, drawn=False, key=None):
    """The summary line of a passing report; Failure otherwise. drawn: the page must draw a key; key: the
    page is opened at #key=KEY and must show (and, with drawn, draw) that key."""
    if not os.path.isfile(report):
        raise Failure("no report at {}".format(report))
    if not os.access(chromium, os.X_OK):
        raise Failure("no chromium at {}".format(chromium))
    url = "file://" + os.path.abspath(report)
    keyed = url + ("#key=" + urllib.parse.quote(key, safe="") if key else "")
    status, dom, err = run_chromium(chromium, [SCREEN, "--dump-dom", keyed], timeout)
    messages = console_lines(err)
    if messages:
        raise Failure("console: {}{}".format(messages[0], " (and {} more)".format(len(messages) - 1)
                                             if len(messages) > 1 else ""))
    if status != 0 or not dom.strip():
        raise Failure("chromium --dump-dom exited {} with {} bytes of DOM".format(status, len(dom)))
    summary = check_dom(dom, key, drawn)
    os.makedirs(os.path.dirname(os.path.abspath(screenshot)), exist_ok=True)
    if os.path.exists(screenshot):
        os.remove(screenshot)  # an older one must not pass for this run's
    status, _, err = run_chromium(chromium, [SCREEN, "--screenshot=" + os.path.abspath(screenshot), url], timeout)
    messages = console_lines(err)
    if messages:
        raise Failure("console (screenshot run): {}".format(messages[0]))
    if status != 0 or not os.path.isfile(screenshot) or os.path.getsize(screenshot) == 0:
        raise Failure("chromium --screenshot exited {} and wrote no {}".format(status, screenshot))
    return summary


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--report", required=True, help="the report's HTML file")
    parser.add_argument("--screenshot", required=True, help="the PNG to write")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--timeout", type=float, default=120, help="seconds each chromium run may take")
    parser.add_argument("--drawn", action="store_true", help="the page must draw a key's decomposition")
    parser.add_argument("--key", help="open the page at #key=KEY: it must show that key")
    args = parser.parse_args(argv)
    start = time.monotonic()
    try:
        summary = check_report(args.report, args.screenshot, args.chromium, args.timeout, args.drawn, args.key)
    except Failure as e:
        print("browser_test: FAILED: {}: {}".format(args.report, e), file=sys.stderr)
        return 1
    print("browser_test: ok: {}: {}; screenshot {} ({:.1f} s)".format(
        args.report, summary, args.screenshot, time.monotonic() - start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
