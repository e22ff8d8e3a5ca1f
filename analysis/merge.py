#!/usr/bin/python3
"""Joins the shards of a sweep into one results file.

Every shard's journal (RESULTS/S.shard-I-of-K.journal.jsonl) must be in RESULTS; the merge is
polydecomp_analysis/merge.py's. With --analyse, bounds.md and the plots follow, as after a whole sweep.

usage: merge.py --sweep S [--results DIR] [--analyse [--build DIR]]
"""

import argparse
import os
import sys

from polydecomp_analysis import merge, sweep


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sweep", required=True)
    parser.add_argument("--results", default="results")
    parser.add_argument("--analyse", action="store_true", help="then write bounds.md and the plots")
    parser.add_argument("--build", default="build")
    parser.add_argument("--gallery", default="random:40:12:1")
    args = parser.parse_args(argv)
    try:
        count, shards = merge.merge_shards(args.results, args.sweep)
    except ValueError as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    out = os.path.join(args.results, args.sweep)
    print("merge: {} keys from {} shards in {}.json and {}.csv".format(count, shards, out, out), file=sys.stderr)
    if args.analyse:
        sweep.analyse(out + ".json", args.results, args.build, args.gallery)
    return 0


if __name__ == "__main__":
    sys.exit(main())
