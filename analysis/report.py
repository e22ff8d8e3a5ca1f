#!/usr/bin/python3
"""Writes a sweep's HTML report, one self-contained page (DIR/index.html by default) to explore offline.

What the page holds: polydecomp_analysis/report.py. A sweep (analysis/sweep.py, `make bench`, `make paper`)
writes its report itself; this command writes it again, or from other files.

usage: report.py (--results DIR --sweep NAME | RESULTS.json) [--out FILE]
                 [--polydecomp build/polydecomp] [--registry LIST.json] [--no-drawings] [--plugins DIR]...

The keys of up to drawings.DRAW_MAX_N vertices are drawn by running --polydecomp again on each (a few
minutes for the reference run's 15,000); --no-drawings leaves them out, and so does a page written with
--registry and no --polydecomp.
"""

import argparse
import os
import sys

from polydecomp_analysis import bounds, plugins, report


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results_file", nargs="?", metavar="RESULTS.json", help="an assembled results file")
    parser.add_argument("--results", metavar="DIR", help="with --sweep: the results folder of DIR/NAME.json")
    parser.add_argument("--sweep", metavar="NAME", help="with --results: the sweep, e.g. quick or paper")
    parser.add_argument("--out", help="the page (default: index.html beside the results file)")
    parser.add_argument("--polydecomp", help="the command line, for the claims and the drawings "
                        "(default: build/polydecomp)")
    parser.add_argument("--registry", help="a saved `polydecomp list --json` output, instead of running it")
    parser.add_argument("--no-drawings", action="store_true", help="draw no key's decomposition")
    plugins.add_plugins_argument(parser)
    args = parser.parse_args(argv)
    if bool(args.results) != bool(args.sweep) or bool(args.results_file) == bool(args.results):
        parser.error("give either RESULTS.json or both --results DIR and --sweep NAME")
    results_file = args.results_file or os.path.join(args.results, args.sweep + ".json")
    out = args.out or os.path.join(os.path.dirname(results_file), "index.html")
    plugins.use_plugins(args.plugins)
    try:
        registry = bounds.load_registry(args.polydecomp or "build/polydecomp", args.registry)
        draw_with = None if args.no_drawings or (args.registry and not args.polydecomp) else (
            args.polydecomp or "build/polydecomp")
        size = report.write_report(results_file, registry, out, polydecomp=draw_with)
    except (OSError, ValueError) as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    print("wrote {} ({:.1f} MB)".format(out, size / 1e6))
    return 0


if __name__ == "__main__":
    sys.exit(main())
