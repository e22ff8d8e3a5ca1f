#!/usr/bin/python3
"""Compares two results files key by key, in the layout of Google Benchmark's compare.py.

Per key timed in both (status ok or invalid): the old and new CPU time of one call, their ratio (new / old,
below 1 is faster) and the relative change; then per algorithm the geometric mean of the ratios, and over
all keys (OVERALL_GEOMEAN). With --html the same goes into a self-contained page with a search box.
The functions: polydecomp_analysis/report.py (compare_runs, compare_text, compare_page).

usage: compare.py OLD.json NEW.json [--summary] [--html OUT]
"""

import argparse
import sys

from polydecomp_analysis import report, results


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("old", help="the baseline results file, e.g. results/paper.json")
    parser.add_argument("new", help="the results file to compare with it")
    parser.add_argument("--summary", action="store_true", help="print only the per-algorithm summary")
    parser.add_argument("--html", metavar="OUT", help="write the comparison as a page too")
    args = parser.parse_args(argv)
    try:
        old_context, old_runs = results.load(args.old)
        new_context, new_runs = results.load(args.new)
    except (OSError, ValueError) as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    comparison = report.compare_runs(old_runs, new_runs)
    sys.stdout.write(report.compare_text(args.old, args.new, comparison, summary_only=args.summary))
    if args.html:
        results.write_atomic(args.html, report.compare_page(args.old, args.new, old_context, new_context, comparison))
        print("wrote " + args.html, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
