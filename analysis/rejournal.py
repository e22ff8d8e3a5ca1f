#!/usr/bin/python3
"""Writes a sweep's journal back from its assembled results, leaving out the keys to measure again.

On a fresh clone, this lets the sweep measure some keys of the committed reference run again and keep
the rest (polydecomp_analysis/rejournal.py says how the contexts are kept).

usage: rejournal.py --sweep NAME [--results DIR] [--remeasure REGEX]
"""

import argparse
import re
import sys

from polydecomp_analysis import rejournal


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sweep", required=True)
    parser.add_argument("--results", default="results")
    parser.add_argument("--remeasure", help="a regular expression searched in key names: those keys are left out")
    args = parser.parse_args(argv)
    try:
        kept, left_out = rejournal.rejournal(args.results, args.sweep, args.remeasure)
    except (ValueError, re.error) as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    print("rejournal: {} runs kept, {} left out to measure again".format(kept, left_out), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
