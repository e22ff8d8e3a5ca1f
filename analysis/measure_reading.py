#!/usr/bin/python3
"""Measures what reading a polygon costs: the peak memory and time of `polydecomp check` (read, then
the checked constructor, as `run` does before any algorithm) on convex polygons of growing n, in plain
text and GeoJSON. Prints a Markdown table (results/README.md keeps the last one).

usage: measure_reading.py [--build DIR] [--n N ...]
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time


def peak_of(command):
    """(peak resident memory in bytes, wall seconds) of one run of command, which must succeed."""
    start = time.monotonic()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.monotonic() - start
    if status != 0:
        raise RuntimeError("{} failed (status {})".format(" ".join(command), status))
    return usage.ru_maxrss * 1024, seconds


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--n", type=int, nargs="+", default=[250000, 500000, 1000000, 2000000])
    args = parser.parse_args(argv)
    cli = os.path.join(args.build, "polydecomp")
    print("| format | n | file (MB) | peak memory (MB) | bytes per vertex | seconds |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="pd-reading-") as folder:
        for fmt in ("txt", "geojson"):
            for n in args.n:
                path = os.path.join(folder, "convex-{}.{}".format(n, fmt))
                subprocess.run([cli, "generate", "--family", "convex", "--n", str(n), "--format", fmt, "-o", path],
                               check=True)
                peak, seconds = peak_of([cli, "check", "--input", path])
                print("| {} | {} | {:.1f} | {:.1f} | {:.0f} | {:.2f} |".format(
                    fmt, n, os.path.getsize(path) / 1e6, peak / 1e6, peak / n, seconds))
                os.remove(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
