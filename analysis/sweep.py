#!/usr/bin/python3
"""Runs a sweep end to end: polydecomp-bench until the sweep (or shard) is complete, then the results
files, then (for a whole sweep) the bounds table and the plots.

polydecomp_analysis/sweep.py says how it keeps polydecomp-bench going when a key ends the process. An
interrupt (Ctrl-C, SIGTERM) stops it; run the same command again to resume.

usage: sweep.py --sweep NAME [--sweep-file FILE] [--shard I/K] [--build DIR] [--results DIR] [--no-analysis]
                [--plugins DIR]...
                [-- extra polydecomp-bench arguments]
"""

import argparse
import os
import sys
import time

from polydecomp_analysis import plugins, results, sweep


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sweep", required=True, help="a sweep of harness/sweeps.json, e.g. quick or paper")
    parser.add_argument("--sweep-file", "--sweeps", dest="sweeps", help="another sweeps file (a user's own)")
    parser.add_argument("--shard", help="I/K: run shard I of K (merge the shards with analysis/merge.py)")
    parser.add_argument("--build", default="build")
    parser.add_argument("--results", default="results")
    parser.add_argument("--gallery", default="random:40:12:1", help="FAMILY:N:R:SEED of the gallery polygon")
    plugins.add_plugins_argument(parser)
    parser.add_argument("--no-analysis", action="store_true", help="only run the sweep and write JSON and CSV")
    parser.add_argument("bench_args", nargs="*", help="after --: more polydecomp-bench arguments")
    args = parser.parse_args(argv)
    plugins.use_plugins(args.plugins)

    start = time.monotonic()
    try:
        status = sweep.run_until_complete(args)
    except KeyboardInterrupt:
        status = 130
    if status == sweep.USAGE_EXIT:
        print("sweep: not run: polydecomp-bench refused the sweep (its error is above)", file=sys.stderr)
        return status
    stem = sweep.stem(args)
    journal = stem + ".journal.jsonl"
    if os.path.exists(journal):
        count = results.assemble([journal], stem)
        print("sweep: {} keys in {}.json and {}.csv".format(count, stem, stem), file=sys.stderr)
    if status != 0:
        print("sweep: stopped; run the same command again to resume", file=sys.stderr)
        return status
    if not args.shard and not args.no_analysis:
        sweep.analyse(stem + ".json", args.results, args.build, args.gallery)
    print("sweep: {} done in {:.0f} s".format(args.sweep, time.monotonic() - start), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
